// encode_png and write_png (contract in png_io.h): the bytes of a PNG file (PNG specification, third
// edition: the signature, IHDR, IDAT chunks, IEND) written here, the image data compressed by libdeflate.
//
// Why not libpng, which reads PNGs (png_io.cpp): libpng hands rows one by one to zlib's streaming
// deflate, and that was most of the CPU time of `curvescan render`: 3.62 G of 4.05 G instructions
// (89 %) for 105 documents of resvg's test suite at 300 px, 454 M for the 1024 px tiger. libdeflate
// compresses a whole buffer in one call: at the same level (6) the tiger took 252 M instructions, and the
// files are smaller (the tiger 340 KB instead of 388 KB: libpng's default strategy with row filters is
// zlib's Z_FILTERED, which finds shorter matches). The price is memory: the filtered rows are held whole,
// the image's size again plus one byte a row, besides the compressed bytes. The chunks around the data
// are 12 bytes each plus IHDR's 13, not worth a library.
//
// Rows. Each row is unpremultiplied (pixel_format.h: rounding to nearest) and stored with filter None or
// Up (PNG 7.3, 9.2): Up, whichever of the two has the smaller sum of its bytes read as signed magnitudes
// (the heuristic of the specification's 12.8, as libpng applies it). None suits the flat colours and
// transparent areas of rendered vector art, Up the vertical coherence of gradients; trying Sub, Average
// and Paeth too cost a quarter more time for files 2–6 % smaller. Filters are lossless: the pixels a
// decoder returns are the unpremultiplied pixels, whatever filter each row takes.
#include <libdeflate.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "curvescan/raster/file_io.h"
#include "curvescan/raster/limits.h"
#include "curvescan/raster/pixel_format.h"
#include "curvescan/raster/png_io.h"
#include "quoted_path.h"

namespace curvescan {
namespace {

constexpr std::array<std::uint8_t, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
// libdeflate's level 7 of 1..12: the smallest level whose files are no larger than libpng's with zlib's
// default level on any of three sets measured (300 documents of resvg's suite: 3 % smaller; 105 of its
// gradient documents: the same; the tiger at 1024 px: 12 % smaller); level 6 made the gradients' files
// 11 % larger for 6 % fewer instructions.
constexpr int kCompressionLevel = 7;
// IDAT chunks of at most this many bytes: any size up to 2^31 − 1 is valid (PNG 5.3); decoders that
// stream read one chunk at a time, so a bounded chunk keeps their buffers small.
constexpr std::size_t kMaxIdatBytes = std::size_t{1} << 20;

void append_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  const std::uint8_t bytes[4] = {static_cast<std::uint8_t>(value >> 24),
                                 static_cast<std::uint8_t>(value >> 16),
                                 static_cast<std::uint8_t>(value >> 8), static_cast<std::uint8_t>(value)};
  out.insert(out.end(), bytes, bytes + 4);
}

// A chunk (PNG 5.3): length, type, data, and the CRC-32 of type and data.
void append_chunk(std::vector<std::uint8_t>& out, const char (&type)[5], const std::uint8_t* data,
                  std::size_t size) {
  append_u32(out, static_cast<std::uint32_t>(size));
  const std::size_t type_at = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data, data + size);
  append_u32(out, libdeflate_crc32(0, out.data() + type_at, size + 4));
}

// One pixel's bytes unpremultiplied; opaque and transparent pixels, most of rendered art, without the
// division.
inline void unpremultiply_pixel(Rgba8 p, std::uint8_t* out) {
  if (p.a == 255) {
    std::memcpy(out, &p, 4);
  } else if (p.a == 0) {
    std::memset(out, 0, 4);
  } else {
    const StraightRgba8 straight = unpremultiply(p);
    out[0] = straight.r;
    out[1] = straight.g;
    out[2] = straight.b;
    out[3] = straight.a;
  }
}

// The row's bytes unpremultiplied, four pixels at a time where all four are opaque or all transparent.
void unpremultiply_row(const Rgba8* source, int width, std::uint8_t* out) {
  static_assert(sizeof(Rgba8) == 4, "a pixel is four bytes, r g b a");
  int x = 0;
  for (; x + 4 <= width; x += 4, out += 16) {
    std::uint8_t alpha_and = 255, alpha_or = 0;
    for (int i = 0; i < 4; ++i) {
      alpha_and &= source[x + i].a;
      alpha_or |= source[x + i].a;
    }
    if (alpha_and == 255) {
      std::memcpy(out, source + x, 16);
    } else if (alpha_or == 0) {  // zero, whatever colour an invalid pixel holds
      std::memset(out, 0, 16);
    } else {
      for (int i = 0; i < 4; ++i) unpremultiply_pixel(source[x + i], out + 4 * i);
    }
  }
  for (; x < width; ++x, out += 4) unpremultiply_pixel(source[x], out);
}

// The byte read as a signed number, its magnitude: the cost of a filtered byte in the 12.8 heuristic.
inline unsigned signed_magnitude(std::uint8_t byte) {
  return byte < 128 ? byte : 256u - byte;
}

// The costs of storing `row` with None and with Up (the sums of signed_magnitude over its bytes and over
// its differences from `above`), sixteen bytes at a time with SSE2: min(b, 256 − b) is the magnitude, and
// psadbw sums sixteen of them.
void filter_costs(const std::uint8_t* row, const std::uint8_t* above, std::size_t n, std::uint64_t& none_cost,
                  std::uint64_t& up_cost) {
  none_cost = 0;
  up_cost = 0;
  std::size_t i = 0;
#if defined(__SSE2__)
  const __m128i zero = _mm_setzero_si128();
  __m128i none_sum = zero, up_sum = zero;
  const auto magnitude = [&](__m128i v) { return _mm_min_epu8(v, _mm_sub_epi8(zero, v)); };
  for (; i + 16 <= n; i += 16) {
    const __m128i r = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + i));
    const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(above + i));
    none_sum = _mm_add_epi64(none_sum, _mm_sad_epu8(magnitude(r), zero));
    up_sum = _mm_add_epi64(up_sum, _mm_sad_epu8(magnitude(_mm_sub_epi8(r, a)), zero));
  }
  none_cost = static_cast<std::uint64_t>(_mm_cvtsi128_si64(none_sum)) +
              static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_unpackhi_epi64(none_sum, none_sum)));
  up_cost = static_cast<std::uint64_t>(_mm_cvtsi128_si64(up_sum)) +
            static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_unpackhi_epi64(up_sum, up_sum)));
#endif
  for (; i < n; ++i) {
    none_cost += signed_magnitude(row[i]);
    up_cost += signed_magnitude(static_cast<std::uint8_t>(row[i] - above[i]));
  }
}

// Stores `row` (n bytes, unfiltered) into `out` (1 + n bytes) with None or Up against `above` (null for
// the first row), whichever costs less.
void filter_row(const std::uint8_t* row, const std::uint8_t* above, std::size_t n, std::uint8_t* out) {
  if (above != nullptr) {
    std::uint64_t none_cost = 0, up_cost = 0;
    filter_costs(row, above, n, none_cost, up_cost);
    if (up_cost < none_cost) {
      out[0] = 2;  // Up
      for (std::size_t i = 0; i < n; ++i) out[1 + i] = static_cast<std::uint8_t>(row[i] - above[i]);
      return;
    }
  }
  out[0] = 0;  // None
  std::memcpy(out + 1, row, n);
}

struct CompressorDeleter {
  void operator()(libdeflate_compressor* compressor) const { libdeflate_free_compressor(compressor); }
};

Result<std::vector<std::uint8_t>> encode(const Image& image) {
  const auto width = static_cast<std::size_t>(image.width());
  const auto height = static_cast<std::size_t>(image.height());
  const std::size_t row_bytes = 4 * width;
  const std::size_t filtered_bytes = (1 + row_bytes) * height;
  // Default-initialised: pages of these buffers are touched only as they are written.
  const std::unique_ptr<std::uint8_t[]> filtered(new std::uint8_t[filtered_bytes]);
  const std::unique_ptr<std::uint8_t[]> rows(new std::uint8_t[2 * row_bytes]);
  for (std::size_t y = 0; y < height; ++y) {
    std::uint8_t* row = rows.get() + (y % 2) * row_bytes;
    const std::uint8_t* above = y == 0 ? nullptr : rows.get() + ((y + 1) % 2) * row_bytes;
    unpremultiply_row(image.row(static_cast<int>(y)), image.width(), row);
    filter_row(row, above, row_bytes, filtered.get() + y * (1 + row_bytes));
  }

  const std::unique_ptr<libdeflate_compressor, CompressorDeleter> compressor(
      libdeflate_alloc_compressor(kCompressionLevel));
  if (!compressor) throw std::bad_alloc();
  const std::size_t bound = libdeflate_zlib_compress_bound(compressor.get(), filtered_bytes);
  const std::unique_ptr<std::uint8_t[]> compressed(new std::uint8_t[bound]);
  const std::size_t compressed_bytes =
      libdeflate_zlib_compress(compressor.get(), filtered.get(), filtered_bytes, compressed.get(), bound);
  if (compressed_bytes == 0) {  // cannot happen with the bound libdeflate gives
    return Error{ErrorKind::kIoError, "cannot encode a PNG: the compressed data did not fit its bound"};
  }

  std::vector<std::uint8_t> bytes;
  const std::size_t idat_chunks = (compressed_bytes + kMaxIdatBytes - 1) / kMaxIdatBytes;
  bytes.reserve(kSignature.size() + 25 + compressed_bytes + 12 * idat_chunks + 12);
  bytes.insert(bytes.end(), kSignature.begin(), kSignature.end());
  // IHDR (PNG 11.2.2): width, height, bit depth 8, colour type 6 (RGBA), compression 0, filter method 0,
  // no interlace.
  std::vector<std::uint8_t> header;
  append_u32(header, static_cast<std::uint32_t>(width));
  append_u32(header, static_cast<std::uint32_t>(height));
  header.insert(header.end(), {8, 6, 0, 0, 0});
  append_chunk(bytes, "IHDR", header.data(), header.size());
  for (std::size_t at = 0; at < compressed_bytes; at += kMaxIdatBytes) {
    append_chunk(bytes, "IDAT", compressed.get() + at, std::min(kMaxIdatBytes, compressed_bytes - at));
  }
  append_chunk(bytes, "IEND", nullptr, 0);
  return bytes;
}

}  // namespace

Result<std::vector<std::uint8_t>> encode_png(const Image& image) {
  if (image.empty())
    return Error{ErrorKind::kInvalidArgument, "cannot encode a PNG: the image has no pixels"};
  if (!image_size_within_limits(image.width(), image.height())) {
    return Error{ErrorKind::kLimitExceeded, "cannot encode a PNG: the image exceeds the size limit"};
  }
  try {
    return encode(image);
  } catch (const std::bad_alloc&) {
    return Error{ErrorKind::kIoError, "cannot encode a PNG: out of memory"};
  }
}

Status write_png(const Image& image, const std::filesystem::path& path) {
  const Result<std::vector<std::uint8_t>> bytes = encode_png(image);
  if (!bytes) {
    std::string reason = bytes.error().message;
    if (reason.rfind("cannot encode a PNG: ", 0) == 0) reason.erase(0, sizeof "cannot encode a PNG: " - 1);
    return Error{bytes.error().kind, "cannot write " + detail::quoted(path) + ": " + reason};
  }
  return write_output_file(path, std::span<const std::uint8_t>(*bytes));
}

}  // namespace curvescan
