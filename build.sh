#!/usr/bin/env bash
# The project's one entry point (see README.md):
#   ./build.sh demo    install what is missing, build, render the example scenes and figures into out/
#   ./build.sh test    install what is missing, build with warnings as errors, run the whole test suite,
#                      then again under AddressSanitizer + UndefinedBehaviorSanitizer
#   ./build.sh bench   build the benchmarks (Release) and run them side by side with Cairo
set -euo pipefail
cd "$(dirname "$0")"

# Debian 12 packages the build needs; each is explained in README.md ("Dependencies").
packages=(cmake g++ ninja-build pkg-config catch2 libcairo2-dev libpng-dev nlohmann-json3-dev libcli11-dev
          libbenchmark-dev chromium libfreetype-dev libfontconfig-dev libharfbuzz-dev fonts-dejavu-core
          fonts-cantarell libpugixml-dev librsvg2-bin)

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

configure_and_build() {  # build_dir, extra cmake args...
  local dir=$1; shift
  cmake -S . -B "$dir" -G Ninja "$@" >/dev/null
  cmake --build "$dir" -j "$jobs"
}

run_tests() {  # build_dir
  ctest --test-dir "$1" -j "$jobs" --output-on-failure
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
    configure_and_build build-test -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCURVESCAN_WERROR=ON \
      -DCURVESCAN_BUILD_BENCH=OFF
    run_tests build-test
    echo "== again under AddressSanitizer + UndefinedBehaviorSanitizer =="
    # -O1 rather than -O0: the sanitizers see the same bugs, and the oracle corpora run several times faster.
    configure_and_build build-asan -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-g -O1" \
      -DCURVESCAN_WERROR=ON -DCURVESCAN_SANITIZE=ON -DCURVESCAN_BUILD_BENCH=OFF
    ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      run_tests build-asan
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
