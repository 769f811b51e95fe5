// Inflating gzip data within a size limit (curvescan/svg/gzip.h), through zlib's inflate with gzip framing
// (windowBits 16 + 15: zlib checks the header and the CRC-32 trailer).
#include "curvescan/svg/gzip.h"

#include <zlib.h>

#include <algorithm>
#include <climits>

namespace curvescan::svg {

bool is_gzip(std::string_view data) noexcept {
  return data.size() >= 2 && static_cast<unsigned char>(data[0]) == 0x1f &&
         static_cast<unsigned char>(data[1]) == 0x8b;
}

Result<std::string> gunzip(std::string_view data, std::size_t max_bytes) {
  z_stream stream{};
  if (inflateInit2(&stream, 16 + MAX_WBITS) != Z_OK) {
    return Error{ErrorKind::kIoError, "the gzip decoder could not start"};
  }
  const auto fail = [&](ErrorKind kind, std::string message) {
    inflateEnd(&stream);
    return Error{kind, std::move(message)};
  };
  std::string out;
  char buffer[1 << 16];
  std::size_t offset = 0;
  while (true) {
    // zlib counts bytes in uInt (32 bits): the input goes in slices of at most UINT_MAX.
    const std::size_t chunk = std::min<std::size_t>(data.size() - offset, UINT_MAX);
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data() + offset));  // zlib only reads
    stream.avail_in = static_cast<uInt>(chunk);
    stream.next_out = reinterpret_cast<Bytef*>(buffer);
    stream.avail_out = sizeof buffer;
    const int code = inflate(&stream, Z_NO_FLUSH);
    offset += chunk - stream.avail_in;
    const std::size_t produced = sizeof buffer - stream.avail_out;
    if (produced > max_bytes - std::min(out.size(), max_bytes)) {
      return fail(ErrorKind::kLimitExceeded,
                  "it inflates to more than " + std::to_string(max_bytes) + " bytes");
    }
    out.append(buffer, produced);
    if (code == Z_STREAM_END) {
      const std::string_view rest = data.substr(offset);
      if (rest.find_first_not_of('\0') == std::string_view::npos) break;
      if (!is_gzip(rest)) return fail(ErrorKind::kCorruptInput, "data after the end of the gzip stream");
      inflateReset(&stream);
      continue;
    }
    // Z_BUF_ERROR with all input used: no progress is possible, the data ends too early.
    if (code == Z_BUF_ERROR && stream.avail_in == 0 && offset == data.size()) {
      return fail(ErrorKind::kCorruptInput, "the gzip data is truncated");
    }
    if (code != Z_OK && code != Z_BUF_ERROR) {
      return fail(ErrorKind::kCorruptInput,
                  std::string("not valid gzip data (") + (stream.msg ? stream.msg : "corrupt data") + ")");
    }
  }
  inflateEnd(&stream);
  return out;
}

}  // namespace curvescan::svg
