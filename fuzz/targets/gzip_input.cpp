// Fuzz target gzip_input: gzip data (a .svgz file, gzip on standard input, an svgz image) through
// svg::gunzip (curvescan/svg/gzip.h, zlib): truncated and corrupt members, concatenated members,
// trailing garbage, and data that expands past the size limit (a "zip bomb" must stop at the limit).
#include <string>
#include <string_view>

#include "curvescan/svg/gzip.h"
#include "fuzz_targets.h"

namespace curvescan::fuzz {

int fuzz_gzip_input(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);  // bytes as characters
  (void)svg::is_gzip(bytes);
  // 128 KiB: the limit must hold whatever the compression ratio (the default --max-input-size is tested in
  // tests/bad_input). gunzip inflates through a 64 KiB buffer, so two buffers' worth still drives output
  // appended across buffers and the refusal of the one that crosses the limit; with 1 MiB, every member
  // that expands (most mutations of the expanding seeds) inflated 16 buffers to reach the same refusal.
  constexpr std::size_t kLimit = std::size_t{1} << 17;
  const Result<std::string> inflated = svg::gunzip(bytes, kLimit);
  if (inflated && inflated->size() > kLimit) __builtin_trap();  // the limit did not hold
  return 0;
}

}  // namespace curvescan::fuzz
