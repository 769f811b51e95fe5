// libFuzzer's entry point for one fuzz target: CURVESCAN_FUZZ_TARGET names the plain function of
// targets/<name>.cpp (fuzz/CMakeLists.txt compiles this file once per target).
#include <cstddef>
#include <cstdint>

#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return curvescan::fuzz::CURVESCAN_FUZZ_TARGET(data, size);
}
