// Gzip inflation for svgz images (gzip_decode.h), through zlib's inflate with gzip framing (windowBits
// 16 + 15: the header and the CRC-32 trailer are checked by zlib).
#include "gzip_decode.h"

#include <zlib.h>

#include <algorithm>

namespace curvescan::svg::detail {

bool is_gzip(const std::vector<std::uint8_t>& bytes) noexcept {
  return bytes.size() >= 2 && bytes[0] == 0x1f && bytes[1] == 0x8b;
}

Gunzipped gunzip(const std::vector<std::uint8_t>& bytes, std::size_t max_bytes) {
  Gunzipped out;
  z_stream stream{};
  if (inflateInit2(&stream, 16 + MAX_WBITS) != Z_OK) {
    out.error = "the decompressor could not start";
    return out;
  }
  // zlib counts bytes in uInt (32 bits): input goes in slices of at most 1 GiB, output in 64 KiB steps.
  constexpr std::size_t kChunk = std::size_t{1} << 16;
  std::size_t consumed = 0;
  int status = Z_OK;
  while (status != Z_STREAM_END) {
    if (stream.avail_in == 0 && consumed < bytes.size()) {
      const std::size_t take = std::min<std::size_t>(bytes.size() - consumed, std::size_t{1} << 30);
      stream.next_in = const_cast<Bytef*>(bytes.data() + consumed);  // zlib does not write its input
      stream.avail_in = static_cast<uInt>(take);
      consumed += take;
    }
    const std::size_t before = out.bytes.size();
    if (before >= max_bytes) {
      out.error = "it inflates to more than " + std::to_string(max_bytes) + " bytes";
      break;
    }
    const std::size_t room = std::min(kChunk, max_bytes - before);
    out.bytes.resize(before + room);
    stream.next_out = out.bytes.data() + before;
    stream.avail_out = static_cast<uInt>(room);
    status = inflate(&stream, Z_NO_FLUSH);
    out.bytes.resize(before + (room - stream.avail_out));
    if (status == Z_STREAM_END) break;
    // Z_BUF_ERROR with input left is "no progress possible": with no input left, the data is truncated.
    if (status != Z_OK && !(status == Z_BUF_ERROR && stream.avail_in == 0 && consumed < bytes.size())) {
      out.error =
          status == Z_BUF_ERROR ? "the compressed data is truncated" : "the compressed data is corrupt";
      break;
    }
  }
  inflateEnd(&stream);
  if (!out.error.empty()) out.bytes.clear();
  return out;
}

}  // namespace curvescan::svg::detail
