# The libFuzzer build (docs/fuzzing.md), included by the top-level CMakeLists.txt before the libraries so
# that every library is compiled with the fuzzer's coverage instrumentation and the sanitizers.
#
# clang-14 only (CC=clang-14 CXX=clang++-14): -fsanitize=fuzzer-no-link instruments the code for
# libFuzzer's coverage feedback without pulling in its main(); fuzz/CMakeLists.txt links -fsanitize=fuzzer
# into the one executable per target. UBSan findings abort (-fno-sanitize-recover) so that libFuzzer sees
# them as crashes rather than as log lines.
option(CURVESCAN_BUILD_FUZZERS "Build the libFuzzer targets of fuzz/ (clang-14 only)" OFF)
if(CURVESCAN_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "CURVESCAN_BUILD_FUZZERS needs clang (configure with CC=clang-14 CXX=clang++-14)")
  endif()
  if(CURVESCAN_SANITIZE)
    message(FATAL_ERROR "CURVESCAN_BUILD_FUZZERS already enables ASan and UBSan; leave CURVESCAN_SANITIZE off")
  endif()
  # Long depth runs may drop AddressSanitizer (CURVESCAN_FUZZ_SANITIZERS=undefined): without its shadow
  # memory and allocator a rendering target runs several times faster, and the corpus such a run finds is
  # then replayed once through the default build, so every input still passes under ASan (docs/fuzzing.md).
  set(CURVESCAN_FUZZ_SANITIZERS "address,undefined" CACHE STRING
      "Sanitizers of the libFuzzer build: address,undefined (default) or undefined")
  if(NOT CURVESCAN_FUZZ_SANITIZERS MATCHES "^(address,undefined|undefined)$")
    message(FATAL_ERROR "CURVESCAN_FUZZ_SANITIZERS must be address,undefined or undefined")
  endif()
  # Comparison tracing (trace-cmp, part of fuzzer-no-link) lets libFuzzer learn the operands of integer
  # comparisons: it finds keywords and magic numbers in the parsers, but in the geometry and raster core
  # (curves, raster) the comparisons are loop bounds and pixel indices over floating-point data it cannot
  # steer, and they cost a rendering target 10 to 15 % of its time. Depth runs may switch it off there
  # (docs/fuzzing.md); the parsers (svg, text, the fuzz targets) keep it.
  option(CURVESCAN_FUZZ_CORE_TRACE_CMP "Trace comparisons in the curves and raster core libraries" ON)
  add_compile_options(-fsanitize=fuzzer-no-link,${CURVESCAN_FUZZ_SANITIZERS} -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${CURVESCAN_FUZZ_SANITIZERS})
endif()
