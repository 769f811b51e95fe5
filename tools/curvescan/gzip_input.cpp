// Inflating gzip input within a size limit (gzip_input.h).
#include "gzip_input.h"

#include <zlib.h>

#include <algorithm>
#include <climits>

#include "limit_options.h"

namespace curvescan::cli {

bool is_gzip(std::string_view data) noexcept {
  return data.size() >= 2 && static_cast<unsigned char>(data[0]) == 0x1f &&
         static_cast<unsigned char>(data[1]) == 0x8b;
}

Result<std::string> gunzip(std::string_view data, std::size_t max_bytes, const std::string& name) {
  z_stream stream{};
  // 16 + MAX_WBITS: a gzip header and trailer around the deflate data (zlib.h, inflateInit2).
  if (inflateInit2(&stream, 16 + MAX_WBITS) != Z_OK) {
    return Error{ErrorKind::kIoError, "cannot start the gzip decoder for '" + name + "'"};
  }
  std::string out;
  char buffer[1 << 16];
  std::size_t offset = 0;
  int code = Z_OK;
  while (true) {
    const std::size_t chunk = std::min<std::size_t>(data.size() - offset, UINT_MAX);
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data() + offset));
    stream.avail_in = static_cast<uInt>(chunk);
    stream.next_out = reinterpret_cast<Bytef*>(buffer);
    stream.avail_out = sizeof buffer;
    code = inflate(&stream, Z_NO_FLUSH);
    offset += chunk - stream.avail_in;
    out.append(buffer, sizeof buffer - stream.avail_out);
    if (out.size() > max_bytes) {
      inflateEnd(&stream);
      return input_too_large(name + " (uncompressed)", max_bytes);
    }
    if (code == Z_STREAM_END) {
      // Another member may follow (gzip -d concatenates members); trailing zeros are padding.
      const std::string_view rest = data.substr(offset);
      if (rest.find_first_not_of('\0') == std::string_view::npos) break;
      if (!is_gzip(rest)) {
        inflateEnd(&stream);
        return Error{ErrorKind::kCorruptInput, "'" + name + "': data after the end of the gzip stream"};
      }
      inflateReset(&stream);
      continue;
    }
    if (code == Z_BUF_ERROR && stream.avail_in == 0 && offset == data.size()) {
      inflateEnd(&stream);
      return Error{ErrorKind::kCorruptInput, "'" + name + "': the gzip data is truncated"};
    }
    if (code != Z_OK && code != Z_BUF_ERROR) {
      const std::string reason = stream.msg ? stream.msg : "corrupt data";
      inflateEnd(&stream);
      return Error{ErrorKind::kCorruptInput, "'" + name + "': not valid gzip data (" + reason + ")"};
    }
  }
  inflateEnd(&stream);
  return out;
}

}  // namespace curvescan::cli
