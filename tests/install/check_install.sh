#!/usr/bin/env bash
# Installs the build into a temporary prefix, then builds and runs a program against it twice: through
# find_package(curvescan) and through pkg-config. What a user of the installed library does.
set -euo pipefail
build_dir=${1:?usage: check_install.sh BUILD_DIR SOURCE_DIR}
source_dir=${2:?usage: check_install.sh BUILD_DIR SOURCE_DIR}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
cmake -S "$source_dir/tests/install/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/consumer" >/dev/null
"$work/consumer/consumer" "$work/cmake.png"
g++ -std=c++20 "$source_dir/tests/install/consumer/main.cpp" -o "$work/pkg_consumer" \
  $(PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig" pkg-config --cflags --libs --static curvescan)
"$work/pkg_consumer" "$work/pkg.png"
cmp "$work/cmake.png" "$work/pkg.png"
echo "install: find_package and pkg-config consumers both built and drew the same PNG"
