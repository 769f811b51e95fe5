// encode_png writes the PNG file itself (raster/io/png_encode.cpp): each row unpremultiplied, with the
// opaque and transparent pixels taken four at a time, filtered None or Up, compressed by libdeflate, in
// IDAT chunks of at most 1 MiB. Each case builds an image that reaches one of those paths and checks
// the file with code independent of the writer: libpng decodes it (verifying every chunk's CRC and the
// zlib checksum), and zlib inflates the IDAT data to read each row's filter byte.
#include <zlib.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "curvescan/raster/image.h"
#include "curvescan/raster/pixel_format.h"
#include "curvescan/raster/png_io.h"

using namespace curvescan;

namespace {

std::uint32_t read_u32(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  return std::uint32_t{bytes[at]} << 24 | std::uint32_t{bytes[at + 1]} << 16 |
         std::uint32_t{bytes[at + 2]} << 8 | std::uint32_t{bytes[at + 3]};
}

struct Chunk {
  std::string type;
  std::size_t size = 0;
};

// The chunks of a PNG file in order, and the concatenated IDAT data.
std::vector<Chunk> chunks_of(const std::vector<std::uint8_t>& png, std::vector<std::uint8_t>& idat) {
  std::vector<Chunk> chunks;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::size_t size = read_u32(png, at);
    chunks.push_back({std::string(png.begin() + static_cast<std::ptrdiff_t>(at + 4),
                                  png.begin() + static_cast<std::ptrdiff_t>(at + 8)),
                      size});
    if (chunks.back().type == "IDAT")
      idat.insert(idat.end(), png.begin() + static_cast<std::ptrdiff_t>(at + 8),
                  png.begin() + static_cast<std::ptrdiff_t>(at + 8 + size));
    at += 12 + size;
  }
  return chunks;
}

// The filter byte of each row, from the inflated image data (zlib, not the writer's libdeflate).
std::vector<int> row_filters(const std::vector<std::uint8_t>& png, int width, int height) {
  std::vector<std::uint8_t> idat;
  (void)chunks_of(png, idat);
  const std::size_t row_bytes = 1 + 4 * static_cast<std::size_t>(width);
  std::vector<std::uint8_t> raw(row_bytes * static_cast<std::size_t>(height));
  uLongf raw_size = raw.size();
  REQUIRE(uncompress(raw.data(), &raw_size, idat.data(), idat.size()) == Z_OK);
  REQUIRE(raw_size == raw.size());
  std::vector<int> filters;
  for (int y = 0; y < height; ++y) filters.push_back(raw[static_cast<std::size_t>(y) * row_bytes]);
  return filters;
}

Image decoded(const std::vector<std::uint8_t>& png) {
  Result<Image> image = decode_png(png);
  REQUIRE(image.is_ok());
  return std::move(*image);
}

}  // namespace

TEST_CASE("encode_png: runs of opaque and transparent pixels at every offset and width round-trip exactly",
          "[png]") {
  // Widths 1..37 put the runs of four alike pixels at every alignment and leave 0..3 pixels after the
  // last group of four; each row mixes opaque runs, transparent runs and translucent pixels.
  std::mt19937 rng(7);
  for (int width = 1; width <= 37; ++width) {
    CAPTURE(width);
    Image image(width, 6);
    for (int y = 0; y < 6; ++y) {
      for (int x = 0; x < width; ++x) {
        const int kind = static_cast<int>((x / (1 + y) + y) % 3);
        const auto c = static_cast<std::uint8_t>(rng() % 256);
        const auto a = static_cast<std::uint8_t>(1 + rng() % 254);
        image.at(x, y) = kind == 0   ? Rgba8{c, static_cast<std::uint8_t>(255 - c), 9, 255}
                         : kind == 1 ? Rgba8{0, 0, 0, 0}
                                     : Rgba8{static_cast<std::uint8_t>(c % (a + 1)), 0, a, a};
      }
    }
    const Result<std::vector<std::uint8_t>> png = encode_png(image);
    REQUIRE(png.is_ok());
    CHECK(decoded(*png) == image);  // exact: premultiply(unpremultiply(p)) == p for valid pixels
  }
}

TEST_CASE("encode_png: a transparent pixel is stored as zero whatever colour it holds", "[png]") {
  // Invalid premultiplied pixels (colour above a zero alpha), four in a row and alone: a PNG pixel of
  // alpha 0 carries no colour here, as unpremultiply gives for one pixel.
  Image image(5, 1);
  for (int x = 0; x < 5; ++x) image.at(x, 0) = {200, 100, 50, 0};
  const Image back = decoded(*encode_png(image));
  for (int x = 0; x < 5; ++x) CHECK(back.at(x, 0) == Rgba8{0, 0, 0, 0});
}

TEST_CASE("encode_png: rows like the row above are stored with the Up filter, the first with None", "[png]") {
  // A vertical gradient: each row differs from the one above by one level, so Up's differences (all 1)
  // cost far less than None's bytes; a row of noise under it costs less with None than with Up.
  const int width = 40, height = 12;
  Image image(width, height);
  std::mt19937 rng(3);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const auto v = static_cast<std::uint8_t>(y < height - 1 ? 100 + y : rng() % 50);
      image.at(x, y) = {v, v, v, 255};
    }
  }
  const std::vector<std::uint8_t> png = *encode_png(image);
  const std::vector<int> filters = row_filters(png, width, height);
  CHECK(filters.front() == 0);
  for (int y = 1; y < height - 1; ++y) CHECK(filters[static_cast<std::size_t>(y)] == 2);
  CHECK(filters.back() == 0);
  CHECK(decoded(png) == image);
}

TEST_CASE("encode_png: the chunks are IHDR, IDATs of at most 1 MiB, IEND", "[png]") {
  // Noise does not compress: 640 x 640 opaque random pixels are 1.6 MB of image data, two IDAT chunks.
  const int side = 640;
  Image image(side, side);
  std::mt19937 rng(11);
  for (Rgba8& p : image.pixels()) {
    const auto bits = static_cast<std::uint32_t>(rng());
    p = {static_cast<std::uint8_t>(bits), static_cast<std::uint8_t>(bits >> 8),
         static_cast<std::uint8_t>(bits >> 16), 255};
  }
  const std::vector<std::uint8_t> png = *encode_png(image);
  std::vector<std::uint8_t> idat;
  const std::vector<Chunk> chunks = chunks_of(png, idat);
  REQUIRE(chunks.size() >= 4);
  CHECK(chunks.front().type == "IHDR");
  CHECK(chunks.front().size == 13);
  CHECK(chunks.back().type == "IEND");
  CHECK(chunks.back().size == 0);
  for (std::size_t i = 1; i + 1 < chunks.size(); ++i) {
    CHECK(chunks[i].type == "IDAT");
    CHECK(chunks[i].size <= (std::size_t{1} << 20));
  }
  CHECK(decoded(png) == image);
}
