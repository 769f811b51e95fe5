// <image> (SVG 1.1 5.7, SVG 2 "The image element"): data: URIs with PNG, JPEG and SVG content, sizing and
// preserveAspectRatio, and the file policy (no network, files only beside the document when allowed).
// PNGs are made here with encode_png, so the expected pixels are the test's own; placements keep every
// checked pixel inside one scaled texel, away from edges: nearest and padded bilinear sampling both
// return that texel exactly.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "curvescan/raster/png_io.h"
#include "scratch_directory.h"
#include "svg/image_dimensions.h"
#include "svg/image_source.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

const Rgba8 kRed{255, 0, 0, 255}, kGreen{0, 255, 0, 255}, kBlue{0, 0, 255, 255}, kWhite{255, 255, 255, 255};

// A 2 x 2 PNG: red, green / blue, white.
std::vector<std::uint8_t> quadrants_png() {
  Image image(2, 2);
  image.at(0, 0) = kRed;
  image.at(1, 0) = kGreen;
  image.at(0, 1) = kBlue;
  image.at(1, 1) = kWhite;
  return *encode_png(image);
}

std::string png_uri() {
  return "data:image/png;base64," + base64(quadrants_png());
}

}  // namespace

TEST_CASE("image: a PNG data URI fills its rectangle, nearest or bilinear", "[svg][image]") {
  for (const std::string rendering : {"", " image-rendering=\"optimizeSpeed\""}) {
    INFO(rendering);
    const RenderedDocument doc =
        render_square(20, "<image width=\"20\" height=\"20\"" + rendering + " href=\"" + png_uri() + "\"/>");
    CHECK(doc.image.at(2, 2) == kRed);
    CHECK(doc.image.at(17, 2) == kGreen);
    CHECK(doc.image.at(2, 17) == kBlue);
    CHECK(doc.image.at(17, 17) == kWhite);
    CHECK(doc.warnings.empty());
  }
  // Nearest keeps the texel up to its edge; bilinear blends across it.
  const RenderedDocument sharp = render_square(
      20, "<image width=\"20\" height=\"20\" image-rendering=\"optimizeSpeed\" href=\"" + png_uri() + "\"/>");
  CHECK(sharp.image.at(9, 2) == kRed);
  const RenderedDocument smooth =
      render_square(20, "<image width=\"20\" height=\"20\" href=\"" + png_uri() + "\"/>");
  CHECK(smooth.image.at(9, 2).g > 0);
}

TEST_CASE("image: sizes and preserveAspectRatio", "[svg][image]") {
  // No width and height: the image's own 2 x 2 pixels.
  const RenderedDocument own = render_square(
      20, "<image x=\"4\" y=\"4\" image-rendering=\"optimizeSpeed\" href=\"" + png_uri() + "\"/>");
  CHECK(own.image.at(4, 4) == kRed);
  CHECK(own.image.at(5, 5) == kWhite);
  CHECK(own.image.at(6, 6) == Rgba8{});
  // Width alone: the height follows the aspect ratio.
  const RenderedDocument wide =
      render_square(20, "<image width=\"10\" image-rendering=\"optimizeSpeed\" href=\"" + png_uri() + "\"/>");
  CHECK(wide.image.at(7, 7) == kWhite);
  CHECK(wide.image.at(7, 12) == Rgba8{});
  // A square image in a 20 x 10 box: meet centres it (x 5..15), none stretches it, slice covers and clips.
  const std::string box =
      "width=\"20\" height=\"10\" image-rendering=\"optimizeSpeed\" href=\"" + png_uri() + "\"";
  const RenderedDocument meet = render_square(20, "<image " + box + "/>");
  CHECK(meet.image.at(2, 2) == Rgba8{});
  CHECK(meet.image.at(6, 2) == kRed);
  const RenderedDocument none = render_square(20, "<image preserveAspectRatio=\"none\" " + box + "/>");
  CHECK(none.image.at(2, 2) == kRed);
  CHECK(none.image.at(2, 7) == kBlue);
  const RenderedDocument slice =
      render_square(20, "<image preserveAspectRatio=\"xMidYMid slice\" " + box + "/>");
  CHECK(slice.image.at(2, 2) == kRed);  // 20 x 20 at y -5..15, the top half shows red at y 0..5
  CHECK(slice.image.at(2, 7) == kBlue);
  CHECK(slice.image.at(2, 12) == Rgba8{});  // clipped below the box
  CHECK(render_square(20, "<image width=\"0\" height=\"10\" href=\"" + png_uri() + "\"/>").image.at(2, 2) ==
        Rgba8{});
}

TEST_CASE("image: SVG content is drawn as a sub-document — nesting is bounded", "[svg][image]") {
  const std::string inner =
      "<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'>"
      "<rect width='5' height='10' fill='%23008000'/></svg>";
  const RenderedDocument doc =
      render_square(20, "<image width=\"20\" height=\"20\" href=\"data:image/svg+xml," + inner + "\"/>");
  CHECK(doc.image.at(5, 10) == Rgba8{0, 128, 0, 255});
  CHECK(doc.image.at(15, 10) == Rgba8{});
  // SVG images nested in SVG images, six deep: the innermost beyond the bound are not drawn, with a warning.
  std::string level =
      "<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'><rect width='10' height='10'/></svg>";
  for (int i = 0; i < 6; ++i) {
    const std::vector<std::uint8_t> bytes(level.begin(), level.end());
    level =
        "<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'><image width='10' height='10' "
        "href='data:image/svg+xml;base64," +
        base64(bytes) + "'/></svg>";
  }
  const std::vector<std::uint8_t> bytes(level.begin(), level.end());
  const RenderedDocument deep = render_square(
      20, "<image width=\"20\" height=\"20\" href=\"data:image/svg+xml;base64," + base64(bytes) + "\"/>");
  CHECK(contains(deep.warnings, "nested more than"));
}

// An 8 x 8 JPEG of (200, 100, 50) at quality 100, made with libjpeg, as a data URI.
const std::string kJpegDataUri =
    "data:image/jpeg;base64,/9j/4AAQSkZJRgABAQAAAQABAAD/"
    "2wBDAAEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQH/"
    "2wBDAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQH/"
    "wAARCAAIAAgDASIAAhEBAxEB/8QAHwAAAQUBAQEBAQEAAAAAAAAAAAECAwQFBgcICQoL/"
    "8QAtRAAAgEDAwIEAwUFBAQAAAF9AQIDAAQRBRIhMUEGE1FhByJxFDKBkaEII0KxwRVS0fAkM2JyggkKFhcYGRolJicoKSo0NTY3ODk"
    "6Q0RFRkdISUpTVFVWV1hZWmNkZWZnaGlqc3R1dnd4eXqDhIWGh4iJipKTlJWWl5iZmqKjpKWmp6ipqrKztLW2t7i5usLDxMXGx8jJy"
    "tLT1NXW19jZ2uHi4+Tl5ufo6erx8vP09fb3+Pn6/8QAHwEAAwEBAQEBAQEBAQAAAAAAAAECAwQFBgcICQoL/"
    "8QAtREAAgECBAQDBAcFBAQAAQJ3AAECAxEEBSExBhJBUQdhcRMiMoEIFEKRobHBCSMzUvAVYnLRChYkNOEl8RcYGRomJygpKjU2Nzg"
    "5OkNERUZHSElKU1RVVldYWVpjZGVmZ2hpanN0dXZ3eHl6goOEhYaHiImKkpOUlZaXmJmaoqOkpaanqKmqsrO0tba3uLm6wsPExcbHy"
    "MnK0tPU1dbX2Nna4uPk5ebn6Onq8vP09fb3+Pn6/9oADAMBAAIRAxEAPwDn6KKK/wArz/bA/9k=";

TEST_CASE("image: a JPEG data URI", "[svg][image]") {
  // The YCbCr round trip of the JPEG rounds each channel by at most 1 level either way, so each is
  // checked within 2.
  const RenderedDocument doc = render_square(20,
                                             "<image width=\"20\" height=\"20\" "
                                             "href=\"" +
                                                 kJpegDataUri + "\"/>");
  const Rgba8 p = doc.image.at(10, 10);
  CHECK(p.a == 255);
  CHECK(std::abs(p.r - 200) <= 2);
  CHECK(std::abs(p.g - 100) <= 2);
  CHECK(std::abs(p.b - 50) <= 2);
  const RenderedDocument broken =
      render_square(20, "<image width=\"20\" height=\"20\" href=\"data:image/jpeg;base64,/9j/AAAA\"/>");
  CHECK(contains(broken.warnings, "JPEG"));
}

TEST_CASE("image: files only beside the document and only when allowed — never the network", "[svg][image]") {
  const auto directory = test::scratch_directory("image-test");
  std::filesystem::create_directories(directory / "sub");
  const std::vector<std::uint8_t> png = quadrants_png();
  std::ofstream(directory / "sub" / "q.png", std::ios::binary)
      .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  const std::string file = "<image width=\"20\" height=\"20\" href=\"sub/q.png\"/>";
  const RenderedDocument refused = render_square(20, file);
  CHECK(refused.image.at(2, 2) == Rgba8{});
  CHECK(contains(refused.warnings, "--allow-files"));
  RenderOptions allowed;
  allowed.resource_directory = directory;
  CHECK(render_square(20, file, allowed).image.at(2, 2) == kRed);
  CHECK(contains(render_square(20, "<image width=\"20\" height=\"20\" href=\"../q.png\"/>", allowed).warnings,
                 "leaving"));
  CHECK(contains(
      render_square(20, "<image width=\"20\" height=\"20\" href=\"/etc/passwd\"/>", allowed).warnings,
      "relative"));
  CHECK(contains(
      render_square(20, "<image width=\"20\" height=\"20\" href=\"https://example.org/q.png\"/>", allowed)
          .warnings,
      "never fetched"));
}

TEST_CASE("image: a file's bytes count against the memory the render has left", "[svg][image]") {
  const auto directory = test::scratch_directory("image-memory-test");
  // 2 MiB: a valid PNG followed by padding (libpng stops at IEND), so that only the byte count matters.
  std::vector<std::uint8_t> bytes = quadrants_png();
  bytes.resize(std::size_t{2} << 20, 0);
  std::ofstream(directory / "big.png", std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  const std::string file = "<image width=\"20\" height=\"20\" href=\"big.png\"/>";
  RenderOptions options;
  options.resource_directory = directory;
  CHECK(render_square(20, file, options).image.at(2, 2) ==
        kRed);  // the default budget (limits.h) holds 2 MiB
  options.limits.render.max_memory_bytes = std::int64_t{1} << 20;  // less than the file
  const RenderedDocument refused = render_square(20, file, options);
  CHECK(refused.image.at(2, 2) == Rgba8{});
  CHECK(contains(refused.warnings, "--max-memory"));
}

namespace {

// CRC-32 of PNG chunks (ISO/IEC 15948 annex D: polynomial 0xEDB88320, reflected), bit by bit.
std::uint32_t png_crc(const std::vector<std::uint8_t>& bytes, std::size_t begin) {
  std::uint32_t crc = 0xffffffffu;
  for (std::size_t i = begin; i < bytes.size(); ++i) {
    crc ^= bytes[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xffffffffu;
}

void append_chunk(std::vector<std::uint8_t>& png, const char* type, const std::vector<std::uint8_t>& data) {
  const auto be32 = [&png](std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) png.push_back(static_cast<std::uint8_t>(v >> shift));
  };
  be32(static_cast<std::uint32_t>(data.size()));
  const std::size_t typed = png.size();
  png.insert(png.end(), type, type + 4);
  png.insert(png.end(), data.begin(), data.end());
  be32(png_crc(png, typed));
}

// A 57-byte PNG whose header declares width x height 8-bit RGBA pixels: signature, IHDR, an IDAT holding
// an empty zlib stream, IEND. Its pixel data is missing, so only a reader that trusts the header before
// decoding allocates anything.
std::vector<std::uint8_t> declared_png(std::uint32_t width, std::uint32_t height) {
  std::vector<std::uint8_t> png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<std::uint8_t> header;
  for (const std::uint32_t v : {width, height})
    for (int shift = 24; shift >= 0; shift -= 8) header.push_back(static_cast<std::uint8_t>(v >> shift));
  header.insert(header.end(), {8, 6, 0, 0, 0});  // 8 bits, RGBA, deflate, adaptive filters, no interlace
  append_chunk(png, "IHDR", header);
  append_chunk(png, "IDAT", {0x78, 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01});  // zlib of nothing
  append_chunk(png, "IEND", {});
  return png;
}

}  // namespace

TEST_CASE("image: a PNG declaring 30000 x 30000 pixels is refused by the memory limit, the rest drawn",
          "[svg][image][limits]") {
  const std::vector<std::uint8_t> bomb = declared_png(30000, 30000);
  REQUIRE(bomb.size() < 100);
  const std::string body =
      "<rect width=\"10\" height=\"20\" fill=\"#00ff00\"/>"
      "<image x=\"10\" width=\"10\" height=\"20\" href=\"data:image/png;base64," +
      base64(bomb) + "\"/>";
  // 30000 · 30000 · 4 bytes = 3.4 GiB, beyond the default budget of 1 GiB (limits.h).
  const RenderedDocument doc = render_square(20, body);
  CHECK(doc.image.at(5, 10) == kGreen);
  CHECK(doc.image.at(15, 10) == Rgba8{});
  CHECK(contains(doc.warnings, "30000 x 30000"));
  CHECK(contains(doc.warnings, "--max-memory"));
  // In <feImage> too.
  const RenderedDocument filtered = render_square(
      20, "<filter id=\"f\"><feImage href=\"data:image/png;base64," + base64(bomb) + "\"/></filter>" +
              "<rect width=\"20\" height=\"20\" fill=\"#00ff00\" filter=\"url(#f)\"/>");
  CHECK(contains(filtered.warnings, "--max-memory"));
}

TEST_CASE("image: decoded pixels count against the memory the render has left", "[svg][image][limits]") {
  // A 1000 x 1000 green PNG: a few KiB of file, 4,000,000 bytes decoded. Under a 2 MiB budget its file
  // fits and its pixels do not; under the default budget (1 GiB) both do.
  Image green(1000, 1000);
  std::fill(green.pixels().begin(), green.pixels().end(), kGreen);
  const std::vector<std::uint8_t> png = *encode_png(green);
  REQUIRE(png.size() < (std::size_t{64} << 10));
  const std::string body =
      "<image width=\"20\" height=\"20\" href=\"data:image/png;base64," + base64(png) + "\"/>";
  CHECK(render_square(20, body).image.at(10, 10) == kGreen);
  RenderOptions options;
  options.limits.render.max_memory_bytes = std::int64_t{2} << 20;
  const RenderedDocument refused = render_square(20, body, options);
  CHECK(refused.image.at(10, 10) == Rgba8{});
  CHECK(contains(refused.warnings, "1000 x 1000 pixels would take 4 MiB"));
  CHECK(contains(refused.warnings, "--max-memory"));
}

TEST_CASE("image: the size a PNG or JPEG declares is read from its header alone", "[svg][image][limits]") {
  const auto png_size = detail::declared_dimensions(declared_png(30000, 7), detail::ImageFormat::kPng);
  REQUIRE(png_size);
  CHECK(png_size->width == 30000);
  CHECK(png_size->height == 7);
  const std::optional<std::vector<std::uint8_t>> jpeg = detail::decode_data_uri(kJpegDataUri);
  REQUIRE(jpeg);
  const auto jpeg_size = detail::declared_dimensions(*jpeg, detail::ImageFormat::kJpeg);
  REQUIRE(jpeg_size);
  CHECK(jpeg_size->width == 8);
  CHECK(jpeg_size->height == 8);
  // Too short, or not the format it claims: no size (the decoder reports the error).
  CHECK_FALSE(detail::declared_dimensions(std::vector<std::uint8_t>(10, 0), detail::ImageFormat::kPng));
  CHECK_FALSE(
      detail::declared_dimensions(std::vector<std::uint8_t>{0xff, 0xd8, 0, 0}, detail::ImageFormat::kJpeg));
}

TEST_CASE("data: URIs decode base64 with white space and percent escapes", "[svg][image]") {
  using svg::detail::decode_data_uri;
  CHECK(decode_data_uri("data:;base64,SGk=") == std::vector<std::uint8_t>{'H', 'i'});
  CHECK(decode_data_uri("data:text/plain;base64,S G\nk") == std::vector<std::uint8_t>{'H', 'i'});
  CHECK(decode_data_uri("data:,a%20b") == std::vector<std::uint8_t>{'a', ' ', 'b'});
  CHECK_FALSE(decode_data_uri("data:;base64,S*k=").has_value());
  CHECK_FALSE(decode_data_uri("http://x").has_value());
}
