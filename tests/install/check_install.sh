#!/usr/bin/env bash
# What a user of the installed library does, with the program README.md shows: installs the build into a
# temporary prefix, takes the first ```cpp block of README.md (main.cpp) and its first ```cmake block
# (CMakeLists.txt), builds the program through find_package(curvescan) and through the README's pkg-config
# line, runs both (each must write a PNG, example.png, into its working directory; the two must be the
# same bytes) and checks what each links (ldd): the README program uses the raster core alone, so it must
# load none of fontconfig, HarfBuzz, FreeType and pugixml. Every installed pkg-config file must resolve,
# and a program including the umbrella header <curvescan/curvescan.h> must build and run through
# `pkg-config curvescan` and through the CMake target curvescan::curvescan. The installed command-line
# program must run through its install RPATH.
set -euo pipefail
build_dir=${1:?usage: check_install.sh BUILD_DIR SOURCE_DIR}
source_dir=${2:?usage: check_install.sh BUILD_DIR SOURCE_DIR}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
unset LD_LIBRARY_PATH  # the programs must find their libraries without it, except where said below

prefix=$work/prefix
cmake --install "$build_dir" --prefix "$prefix" >/dev/null
pc_file=$(find "$prefix" -name curvescan-raster.pc)
[[ -n $pc_file ]] || { echo "install: no curvescan-raster.pc under $prefix"; exit 1; }
pc_dir=$(dirname "$pc_file")
lib_dir=$(realpath "$(PKG_CONFIG_PATH=$pc_dir pkg-config --variable=libdir curvescan-raster)")
# Every library's pkg-config file, and curvescan for all of them, resolves without --static.
for module in curvescan curvescan-curves curvescan-raster curvescan-text curvescan-svg curvescan-diff; do
  PKG_CONFIG_PATH=$pc_dir pkg-config --exists --print-errors "$module" ||
    { echo "install: pkg-config cannot resolve $module"; exit 1; }
done

# The README's code blocks, verbatim: the first ```cpp and the first ```cmake.
readme_block() {  # language
  awk -v open="\`\`\`$1" '$0 == open { inside = 1; next } inside && $0 == "```" { exit } inside' "$source_dir/README.md"
}
mkdir -p "$work/src" "$work/run-cmake" "$work/run-pkg"
readme_block cpp > "$work/src/main.cpp"
readme_block cmake > "$work/src/CMakeLists.txt"
for f in main.cpp CMakeLists.txt; do
  [[ -s $work/src/$f ]] || { echo "install: README.md has no code block for $f"; exit 1; }
done

is_png() {  # file: the 8-byte PNG signature
  [[ $(head -c 8 "$1" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]]
}

# 1. CMake: find_package(curvescan) and target_link_libraries, nothing else set by the consumer.
cmake -S "$work/src" -B "$work/cmake-build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/cmake-build" >/dev/null
(cd "$work/run-cmake" && "$work/cmake-build/example")
is_png "$work/run-cmake/example.png" || { echo "install: the find_package build wrote no PNG"; exit 1; }

# 2. pkg-config, the README's line as it stands. The prefix is not on the loader's path: running needs
# LD_LIBRARY_PATH (a shared build; the README says so), harmless for a static one.
(cd "$work/src" && PKG_CONFIG_PATH=$pc_dir g++ -std=c++20 main.cpp -o "$work/pkg-example" \
  $(PKG_CONFIG_PATH=$pc_dir pkg-config --cflags --libs curvescan-raster))
(cd "$work/run-pkg" && LD_LIBRARY_PATH=$lib_dir "$work/pkg-example")
is_png "$work/run-pkg/example.png" || { echo "install: the pkg-config build wrote no PNG"; exit 1; }
cmp "$work/run-cmake/example.png" "$work/run-pkg/example.png"

echo "== ldd, find_package build"
ldd "$work/cmake-build/example"
echo "== ldd, pkg-config build (LD_LIBRARY_PATH=$lib_dir)"
LD_LIBRARY_PATH=$lib_dir ldd "$work/pkg-example"

# The README program uses the raster core alone (paths, canvas, PNG): it links libpng and the curves
# library and nothing of SVG or text, through either build.
unwanted_libraries() {  # ldd output on stdin
  grep -oE 'lib(fontconfig|harfbuzz|freetype|pugixml)[^ ]*' | sort -u | tr '\n' ' ' || true
}
unwanted=$(ldd "$work/cmake-build/example" | unwanted_libraries)
[[ -z $unwanted ]] || { echo "install: the raster-only program (find_package) loads ${unwanted% }"; exit 1; }
unwanted=$(LD_LIBRARY_PATH=$lib_dir ldd "$work/pkg-example" | unwanted_libraries)
[[ -z $unwanted ]] || { echo "install: the raster-only program (pkg-config) loads ${unwanted% }"; exit 1; }

# Every library under one name: the umbrella header through `pkg-config curvescan`.
cat > "$work/src/umbrella.cpp" <<'CPP'
#include <curvescan/curvescan.h>

int main() {
  const auto path = curvescan::PathBuilder().move_to({0, 0}).line_to({1, 0}).line_to({0, 1}).close().build();
  return path && !path->empty() ? 0 : 1;
}
CPP
(cd "$work/src" && g++ -std=c++20 umbrella.cpp -o "$work/umbrella" \
  $(PKG_CONFIG_PATH=$pc_dir pkg-config --cflags --libs curvescan))
LD_LIBRARY_PATH=$lib_dir "$work/umbrella" ||
  { echo "install: the umbrella-header program failed (pkg-config)"; exit 1; }
# ... and through find_package and the CMake target curvescan::curvescan.
mkdir -p "$work/umbrella-src"
cp "$work/src/umbrella.cpp" "$work/umbrella-src/"
cat > "$work/umbrella-src/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.25)
project(umbrella CXX)
find_package(curvescan REQUIRED)
add_executable(umbrella umbrella.cpp)
target_link_libraries(umbrella PRIVATE curvescan::curvescan)
CMAKE
cmake -S "$work/umbrella-src" -B "$work/umbrella-build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/umbrella-build" >/dev/null
"$work/umbrella-build/umbrella" ||
  { echo "install: the umbrella-header program failed (find_package)"; exit 1; }

# 3. The installed command-line program finds its libraries through its install RPATH.
if [[ -x $prefix/bin/curvescan ]]; then
  "$prefix/bin/curvescan" --help >/dev/null
  echo "== the installed curvescan runs; $(readelf -d "$prefix/bin/curvescan" | grep -oE 'Library r(un)?path: .*' || echo 'no RPATH')"
fi
echo "install: the README program built through find_package and pkg-config, both wrote the same example.png"
echo "install: neither loads an SVG or text dependency; the umbrella header builds through pkg-config and CMake"
