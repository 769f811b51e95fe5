#!/usr/bin/env bash
# The project's one entry point (see README.md):
#   ./build.sh demo    install what is missing, build, render the example scenes and figures into out/
#   ./build.sh test    install what is missing, build with warnings as errors, run the whole test suite,
#                      then again under AddressSanitizer + UndefinedBehaviorSanitizer, then runs every
#                      fuzz target for 30 s (libFuzzer, clang-14; docs/fuzzing.md)
#   ./build.sh bench   build the benchmarks (Release) and run them side by side with Cairo
set -euo pipefail
cd "$(dirname "$0")"

# Debian 12 packages the build needs; each is explained in README.md ("Dependencies").
packages=(cmake g++ ninja-build pkg-config catch2 libcairo2-dev libpng-dev libdeflate-dev zlib1g-dev nlohmann-json3-dev libcli11-dev
          libbenchmark-dev chromium libfreetype-dev libfontconfig-dev libharfbuzz-dev libglib2.0-dev libfribidi-dev fonts-dejavu-core
          fonts-dejavu-extra fonts-cantarell fonts-noto-mono fonts-ipafont-gothic fonts-inter-variable
          libpugixml-dev libjpeg62-turbo-dev libgif-dev libwebp-dev librsvg2-bin unicode-data clang-14 libclang-rt-14-dev)

install_missing_packages() {
  local missing=()
  for package in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  if [ "$(id -u)" -ne 0 ]; then
    echo "Missing Debian packages. Run as root, then run this command again:" >&2
    echo "  apt-get update && apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
  echo "Installing missing packages: ${missing[*]}"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
}

jobs=$(nproc)

# ccache, where installed, makes a rebuild after a small change (or of a second clone) take seconds; the
# build does not need it.
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi

configure_and_build() {  # build_dir, extra cmake args...
  local dir=$1; shift
  cmake -S . -B "$dir" -G Ninja "${launcher[@]}" "$@" >/dev/null
  cmake --build "$dir" -j "$jobs"
}

run_tests() {  # build_dir
  ctest --test-dir "$1" -j "$jobs" --output-on-failure
}

# The libFuzzer executables (docs/fuzzing.md): clang-14 only, the libraries instrumented, only the fuzz
# targets built. Warnings are not errors here: the -Werror builds above are the warning gate (GCC), and a
# clang-only warning must not hide the fuzz results.
build_fuzzers() {  # build_dir
  # OSS-Fuzz's compile flags: -O1 with line tables only compiles in about half the time of -O2 -g and
  # still symbolizes every frame of a report.
  CC=clang-14 CXX=clang++-14 cmake -S . -B "$1" -G Ninja "${launcher[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only" -DCURVESCAN_BUILD_FUZZERS=ON -DCURVESCAN_BUILD_TESTS=OFF -DCURVESCAN_BUILD_BENCH=OFF \
    -DCURVESCAN_BUILD_TOOLS=OFF >/dev/null
  cmake --build "$1" -j "$jobs" --target fuzz_all  # every target of fuzz/CMakeLists.txt
}

command=${1:-}
case "$command" in
  demo)
    install_missing_packages
    configure_and_build build -DCMAKE_BUILD_TYPE=Release -DCURVESCAN_BUILD_TESTS=OFF -DCURVESCAN_BUILD_BENCH=OFF
    tools/render_examples.sh build out
    ;;
  test)
    install_missing_packages
    # The benchmarks are compiled here too (not run): an API change that breaks them fails the build.
    configure_and_build build-test -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCURVESCAN_WERROR=ON \
      -DCURVESCAN_BUILD_BENCH=ON
    run_tests build-test
    echo "== again under AddressSanitizer + UndefinedBehaviorSanitizer =="
    # -O1 rather than -O0: the sanitizers see the same bugs, and the oracle corpora run several times faster.
    configure_and_build build-asan -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-g -O1" \
      -DCURVESCAN_WERROR=ON -DCURVESCAN_SANITIZE=ON -DCURVESCAN_BUILD_BENCH=OFF
    ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      run_tests build-asan
    echo "== the fuzz targets, 30 s each from their seed corpora (a crash, hang or OOM fails) =="
    build_fuzzers build-fuzz-clang
    # A fixed seed makes the CI runs repeatable: the same binary explores the same inputs in the same order.
    FUZZ_BUILD_DIR=build-fuzz-clang fuzz/run.sh all 30 -seed=1
    ;;
  bench)
    install_missing_packages
    configure_and_build build-bench -DCMAKE_BUILD_TYPE=Release -DCURVESCAN_BUILD_TESTS=OFF
    tools/run_benchmarks.sh build-bench
    ;;
  *)
    echo "usage: ./build.sh demo|test|bench" >&2
    exit 64
    ;;
esac
