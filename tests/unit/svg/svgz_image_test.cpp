// svgz: gzip-compressed SVG in <image> (SVG 2 1.2.2; curvescan/svg/gzip.h). The gzip streams are built here
// by hand, independently of zlib's compressor: a stored (uncompressed) deflate block (RFC 1951 3.2.4) in gzip
// framing (RFC 1952 2.3) with a bitwise CRC-32, so the decoder is checked against the format itself.
#include <catch2/catch.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/svg/gzip.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

// CRC-32 of RFC 1952 8 (reflected polynomial 0xEDB88320), bit by bit.
std::uint32_t crc32_of(const std::string& data) {
  std::uint32_t crc = 0xffffffffu;
  for (const char c : data) {
    crc ^= static_cast<std::uint8_t>(c);
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xffffffffu;
}

void put32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

// `data` (under 64 KiB) as one gzip member holding one final stored deflate block.
std::vector<std::uint8_t> gzip_stored(const std::string& data) {
  std::vector<std::uint8_t> out{0x1f, 0x8b, 8, 0, 0, 0, 0, 0, 0, 0xff};  // deflate, no flags, unknown OS
  out.push_back(1);                                                      // BFINAL = 1, BTYPE = 00
  const auto length = static_cast<std::uint16_t>(data.size());
  out.push_back(static_cast<std::uint8_t>(length & 0xff));
  out.push_back(static_cast<std::uint8_t>(length >> 8));
  out.push_back(static_cast<std::uint8_t>(~length & 0xff));
  out.push_back(static_cast<std::uint8_t>((~length >> 8) & 0xff));
  out.insert(out.end(), data.begin(), data.end());
  put32(out, crc32_of(data));
  put32(out, static_cast<std::uint32_t>(data.size()));
  return out;
}

const std::string kGreenSquare =
    "<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'>"
    "<rect width='10' height='10' fill='#00ff00'/></svg>";

}  // namespace

TEST_CASE("gunzip: a stored block comes back byte for byte, the output bound and corruption are errors",
          "[svg][image][svgz]") {
  const std::vector<std::uint8_t> bytes = gzip_stored(kGreenSquare);
  const std::string stream(bytes.begin(), bytes.end());
  REQUIRE(is_gzip(stream));
  const Result<std::string> whole = gunzip(stream, 1 << 20);
  REQUIRE(whole.is_ok());
  CHECK(*whole == kGreenSquare);
  // Exactly the content's size is enough; one byte less is refused (a bomb stops at the bound).
  CHECK(gunzip(stream, kGreenSquare.size()).is_ok());
  const Result<std::string> bounded = gunzip(stream, kGreenSquare.size() - 1);
  REQUIRE_FALSE(bounded.is_ok());
  CHECK(bounded.error().kind == ErrorKind::kLimitExceeded);
  // Two members inflate to both contents, as gzip -d concatenates them; zero padding after is allowed.
  const Result<std::string> twice = gunzip(stream + stream + std::string(3, '\0'), 1 << 20);
  REQUIRE(twice.is_ok());
  CHECK(*twice == kGreenSquare + kGreenSquare);
  // Something after the stream that is not another member is corruption.
  CHECK(gunzip(stream + "x", 1 << 20).error().kind == ErrorKind::kCorruptInput);
  // Truncated: the trailer is missing.
  const Result<std::string> truncated = gunzip(stream.substr(0, stream.size() - 8), 1 << 20);
  REQUIRE_FALSE(truncated.is_ok());
  CHECK(truncated.error().message.find("truncated") != std::string::npos);
  // A wrong CRC-32 is corruption (zlib checks the trailer).
  std::string bad_crc = stream;
  bad_crc[bad_crc.size() - 8] = static_cast<char>(bad_crc[bad_crc.size() - 8] ^ 1);
  CHECK(gunzip(bad_crc, 1 << 20).error().kind == ErrorKind::kCorruptInput);
  CHECK_FALSE(is_gzip("\x1f"));
}

TEST_CASE("image: a gzip-compressed SVG (svgz) data URI is drawn as its SVG", "[svg][image][svgz]") {
  const std::string uri = "data:image/svg+xml;base64," + base64(gzip_stored(kGreenSquare));
  const RenderedDocument out = render(
      svg_document("width=\"20\" height=\"20\"", "<image width=\"20\" height=\"20\" href=\"" + uri + "\"/>"));
  // The 10 x 10 square scaled to 20 x 20 covers every pixel: opaque green everywhere.
  const Rgba8 corner = out.image.at(0, 0), centre = out.image.at(10, 10), far = out.image.at(19, 19);
  for (const Rgba8& pixel : {corner, centre, far}) {
    CHECK(pixel.r == 0);
    CHECK(pixel.g == 255);
    CHECK(pixel.b == 0);
    CHECK(pixel.a == 255);
  }
  CHECK(out.warnings.empty());
}

TEST_CASE("image: a truncated svgz is a warning and draws nothing", "[svg][image][svgz]") {
  std::vector<std::uint8_t> stream = gzip_stored(kGreenSquare);
  stream.resize(stream.size() / 2);
  const RenderedDocument out = render(svg_document(
      "width=\"20\" height=\"20\"",
      "<image width=\"20\" height=\"20\" href=\"data:image/svg+xml;base64," + base64(stream) + "\"/>"));
  CHECK(inked_pixels(out.image) == 0);
  CHECK(contains(out.warnings, "the gzip data is truncated"));
}

TEST_CASE("feImage: a gzip-compressed SVG (svgz) is drawn as its SVG, as <image> draws it",
          "[svg][filter][svgz]") {
  // The 10 x 10 green square fills a 20 x 20 primitive subregion (preserveAspectRatio meet, same ratio).
  const std::string uri = "data:image/svg+xml;base64," + base64(gzip_stored(kGreenSquare));
  const RenderedDocument out = render(svg_document(
      "width=\"20\" height=\"20\"",
      "<filter id=\"f\" filterUnits=\"userSpaceOnUse\" x=\"0\" y=\"0\" width=\"20\" height=\"20\">"
      "<feImage href=\"" +
          uri + "\"/></filter><rect width=\"20\" height=\"20\" filter=\"url(#f)\"/>"));
  CHECK(out.image.at(10, 10) == Rgba8{0, 255, 0, 255});
  CHECK(out.warnings.empty());
}

TEST_CASE("Document::parse_glyph_document: plain and gzip-compressed glyph documents, and its two failures",
          "[svg][svgz][text]") {
  // An SVG-in-OpenType document: the glyph is the element glyph3, in font units with y down.
  const std::string glyphs =
      "<svg xmlns='http://www.w3.org/2000/svg'><rect id='glyph3' width='10' height='10' "
      "fill='#00ff00'/></svg>";
  const std::vector<std::uint8_t> packed = gzip_stored(glyphs);
  for (const std::string& stored : {glyphs, std::string(packed.begin(), packed.end())}) {
    const Result<Document> document = Document::parse_glyph_document(stored);
    REQUIRE(document.is_ok());
    Result<Canvas> canvas = Canvas::create(4, 4);
    REQUIRE(canvas.is_ok());
    // An em of 10 units on 2 pixels: the glyph covers the top-left 2 x 2 pixels exactly.
    REQUIRE(document->draw_glyph(*canvas, 3, Affine::scale(0.2, 0.2), 10.0, RenderOptions{}).is_ok());
    CHECK(canvas->image().at(1, 1) == Rgba8{0, 255, 0, 255});
    CHECK(canvas->image().at(2, 2) == Rgba8{0, 0, 0, 0});
  }
  // The caller's warning reads "an SVG glyph document " + the message, whichever step failed.
  const std::string broken(packed.begin(), packed.end() - 8);  // the trailer cut off
  const Result<Document> uninflated = Document::parse_glyph_document(broken);
  REQUIRE_FALSE(uninflated.is_ok());
  CHECK(uninflated.error().kind == ErrorKind::kCorruptInput);
  CHECK(uninflated.error().message.rfind("cannot be inflated (", 0) == 0);
  const Result<Document> not_svg = Document::parse_glyph_document("<html/>");
  REQUIRE_FALSE(not_svg.is_ok());
  CHECK(not_svg.error().kind == ErrorKind::kCorruptInput);
  CHECK(not_svg.error().message.rfind("is not a well-formed SVG document (", 0) == 0);
  // The inflated text counts against the memory bound.
  CHECK(Document::parse_glyph_document(std::string(packed.begin(), packed.end()), 16).error().kind ==
        ErrorKind::kLimitExceeded);
}
