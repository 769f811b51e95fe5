// GIF and WebP in <image> (gif_decode.h, webp_decode.h). The GIFs are built here byte by byte from the
// GIF89a specification, with LZW data that clears its table every two pixels so that every code stays 3
// bits wide (appendix F): the expected pixels are the test's own palette entries. The WebPs come from
// libwebp's lossless encoder (animations: libwebpmux's animation encoder, lossless too), so decoding must
// give back exactly the pixels encoded.
#include <webp/encode.h>
#include <webp/mux.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "svg/gif_decode.h"
#include "svg/image_source.h"
#include "svg/webp_decode.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

// Palette: 0 red, 1 green, 2 blue, 3 white.
constexpr std::uint8_t kPalette[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};

void put16(std::vector<std::uint8_t>& out, int value) {
  out.push_back(static_cast<std::uint8_t>(value & 0xff));
  out.push_back(static_cast<std::uint8_t>(value >> 8));
}

// LZW data (minimum code size 2: clear = 4, end = 5, 3-bit codes) for `indices`: a clear code before
// every pair of pixels, so the table never grows past entry 6 and the code size stays 3 bits.
std::vector<std::uint8_t> lzw_3bit(const std::vector<int>& indices) {
  std::vector<int> codes;
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (i % 2 == 0) codes.push_back(4);
    codes.push_back(indices[i]);
  }
  codes.push_back(5);
  std::vector<std::uint8_t> bytes;
  unsigned accumulator = 0;
  int bits = 0;
  for (const int code : codes) {  // codes are packed least significant bit first
    accumulator |= static_cast<unsigned>(code) << bits;
    bits += 3;
    while (bits >= 8) {
      bytes.push_back(static_cast<std::uint8_t>(accumulator & 0xff));
      accumulator >>= 8;
      bits -= 8;
    }
  }
  if (bits > 0) bytes.push_back(static_cast<std::uint8_t>(accumulator & 0xff));
  return bytes;
}

struct Frame {
  int left, top, width, height;
  bool interlaced;
  std::vector<int> indices;  ///< in the order they are stored (interlaced: pass by pass)
};

// A GIF89a of a `width` x `height` screen with the global palette, a Graphic Control Extension with
// `transparent` (or none when negative) and one frame.
std::vector<std::uint8_t> gif(int width, int height, int transparent, const Frame& frame) {
  std::vector<std::uint8_t> out{'G', 'I', 'F', '8', '9', 'a'};
  put16(out, width);
  put16(out, height);
  out.push_back(0x81);  // a global colour table of 2^(1+1) = 4 entries
  out.push_back(0);     // background colour index
  out.push_back(0);     // no aspect ratio
  out.insert(out.end(), std::begin(kPalette), std::end(kPalette));
  if (transparent >= 0) {
    out.insert(out.end(), {0x21, 0xf9, 4, 0x01, 0, 0, static_cast<std::uint8_t>(transparent), 0});
  }
  out.push_back(0x2c);  // image descriptor
  put16(out, frame.left);
  put16(out, frame.top);
  put16(out, frame.width);
  put16(out, frame.height);
  out.push_back(frame.interlaced ? 0x40 : 0);
  out.push_back(2);  // LZW minimum code size
  const std::vector<std::uint8_t> data = lzw_3bit(frame.indices);
  for (std::size_t i = 0; i < data.size(); i += 255) {  // data sub-blocks of at most 255 bytes
    const std::size_t n = std::min<std::size_t>(255, data.size() - i);
    out.push_back(static_cast<std::uint8_t>(n));
    out.insert(out.end(), data.begin() + static_cast<std::ptrdiff_t>(i),
               data.begin() + static_cast<std::ptrdiff_t>(i + n));
  }
  out.push_back(0);     // block terminator
  out.push_back(0x3b);  // trailer
  return out;
}

bool is(const Rgba8& p, int r, int g, int b, int a) {
  return p.r == r && p.g == g && p.b == b && p.a == a;
}

// A lossless WebP of straight RGBA pixels, row by row.
std::vector<std::uint8_t> webp(int width, int height, const std::vector<std::uint8_t>& rgba) {
  std::uint8_t* output = nullptr;
  const std::size_t size = WebPEncodeLosslessRGBA(rgba.data(), width, height, width * 4, &output);
  REQUIRE(size > 0);
  std::vector<std::uint8_t> bytes(output, output + size);
  WebPFree(output);
  return bytes;
}

// A lossless animated WebP of `frames` (straight RGBA, each the whole canvas), 100 ms each.
std::vector<std::uint8_t> animated_webp(int width, int height,
                                        const std::vector<std::vector<std::uint8_t>>& frames) {
  WebPAnimEncoderOptions options;
  REQUIRE(WebPAnimEncoderOptionsInit(&options));
  WebPAnimEncoder* encoder = WebPAnimEncoderNew(width, height, &options);
  REQUIRE(encoder != nullptr);
  int timestamp = 0;
  for (const std::vector<std::uint8_t>& rgba : frames) {
    WebPConfig config;
    REQUIRE(WebPConfigInit(&config));
    config.lossless = 1;
    WebPPicture picture;
    REQUIRE(WebPPictureInit(&picture));
    picture.use_argb = 1;
    picture.width = width;
    picture.height = height;
    REQUIRE(WebPPictureImportRGBA(&picture, rgba.data(), width * 4));
    const int added = WebPAnimEncoderAdd(encoder, &picture, timestamp, &config);
    WebPPictureFree(&picture);
    REQUIRE(added);
    timestamp += 100;
  }
  REQUIRE(WebPAnimEncoderAdd(encoder, nullptr, timestamp, nullptr));
  WebPData data;
  WebPDataInit(&data);
  const int assembled = WebPAnimEncoderAssemble(encoder, &data);
  WebPAnimEncoderDelete(encoder);
  REQUIRE(assembled);
  std::vector<std::uint8_t> bytes(data.bytes, data.bytes + data.size);
  WebPDataClear(&data);
  return bytes;
}

// An animated WebP on a 4 x 4 canvas whose first frame is `first` (2 x 2, straight RGBA) at offset (2, 2),
// blended (the rest of the canvas stays transparent), and whose second frame paints the whole canvas red.
// Assembled frame by frame with libwebpmux, as the animation encoder would crop nothing here.
std::vector<std::uint8_t> offset_frame_webp(const std::vector<std::uint8_t>& first) {
  const std::vector<std::uint8_t> first_bytes = webp(2, 2, first);
  std::vector<std::uint8_t> red;
  for (int i = 0; i < 16; ++i) red.insert(red.end(), {255, 0, 0, 255});
  const std::vector<std::uint8_t> second_bytes = webp(4, 4, red);
  WebPMux* mux = WebPMuxNew();
  REQUIRE(mux != nullptr);
  REQUIRE(WebPMuxSetCanvasSize(mux, 4, 4) == WEBP_MUX_OK);
  const WebPMuxAnimParams params{0xffffffffu, 0};  // an opaque white background colour: a hint, ignored
  REQUIRE(WebPMuxSetAnimationParams(mux, &params) == WEBP_MUX_OK);
  WebPMuxFrameInfo frame{};
  frame.bitstream = {first_bytes.data(), first_bytes.size()};
  frame.x_offset = 2;
  frame.y_offset = 2;
  frame.duration = 100;
  frame.id = WEBP_CHUNK_ANMF;
  frame.dispose_method = WEBP_MUX_DISPOSE_NONE;
  frame.blend_method = WEBP_MUX_BLEND;
  REQUIRE(WebPMuxPushFrame(mux, &frame, 1) == WEBP_MUX_OK);
  frame.bitstream = {second_bytes.data(), second_bytes.size()};
  frame.x_offset = 0;
  frame.y_offset = 0;
  REQUIRE(WebPMuxPushFrame(mux, &frame, 1) == WEBP_MUX_OK);
  WebPData data;
  WebPDataInit(&data);
  const WebPMuxError assembled = WebPMuxAssemble(mux, &data);
  WebPMuxDelete(mux);
  REQUIRE(assembled == WEBP_MUX_OK);
  std::vector<std::uint8_t> bytes(data.bytes, data.bytes + data.size);
  WebPDataClear(&data);
  return bytes;
}

// A GIF of two frames on a `width` x 1 screen: `first`, then `second`, each the whole screen. The second
// file's header and palette (13 + 12 bytes) are dropped, and its image follows the first's.
std::vector<std::uint8_t> animated_gif(int width, const std::vector<int>& first,
                                       const std::vector<int>& second) {
  std::vector<std::uint8_t> bytes = gif(width, 1, -1, {0, 0, width, 1, false, first});
  bytes.pop_back();  // the trailer
  const std::vector<std::uint8_t> next = gif(width, 1, -1, {0, 0, width, 1, false, second});
  bytes.insert(bytes.end(), next.begin() + 25, next.end());
  return bytes;
}

}  // namespace

TEST_CASE("GIF: the first frame on its logical screen, with its transparent index", "[svg][image][gif]") {
  // A 3 x 3 screen, a 2 x 2 frame at (1, 1): red green / blue white, white transparent.
  const std::vector<std::uint8_t> bytes = gif(3, 3, 3, {1, 1, 2, 2, false, {0, 1, 2, 3}});
  CHECK(detail::sniff_image_format(bytes) == detail::ImageFormat::kGif);
  const auto size = detail::gif_dimensions(bytes);
  REQUIRE(size);
  CHECK(size->first == 3);
  CHECK(size->second == 3);
  const Result<Image> image = detail::decode_gif(bytes, 1 << 20);
  REQUIRE(image.is_ok());
  CHECK(image->width() == 3);
  CHECK(image->height() == 3);
  CHECK(is(image->at(0, 0), 0, 0, 0, 0));  // outside the frame: the screen starts transparent
  CHECK(is(image->at(1, 1), 255, 0, 0, 255));
  CHECK(is(image->at(2, 1), 0, 255, 0, 255));
  CHECK(is(image->at(1, 2), 0, 0, 255, 255));
  CHECK(is(image->at(2, 2), 0, 0, 0, 0));  // the transparent index
}

TEST_CASE("GIF: interlaced rows come in four passes", "[svg][image][gif]") {
  // A 1 x 5 image whose row r is palette entry r % 3; stored in the order of the passes: 0, 4, 2, 1, 3.
  const std::vector<std::uint8_t> bytes =
      gif(1, 5, -1, {0, 0, 1, 5, true, {0 % 3, 4 % 3, 2 % 3, 1 % 3, 3 % 3}});
  const Result<Image> image = detail::decode_gif(bytes, 1 << 20);
  REQUIRE(image.is_ok());
  const Rgba8 colours[] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}};
  for (int row = 0; row < 5; ++row) {
    INFO("row " << row);
    CHECK(image->at(0, row) == colours[row % 3]);
  }
}

TEST_CASE("GIF: broken, truncated and oversized files are errors, never a crash", "[svg][image][gif]") {
  const std::vector<std::uint8_t> good = gif(3, 3, 3, {1, 1, 2, 2, false, {0, 1, 2, 3}});
  for (std::size_t cut : {std::size_t{6}, std::size_t{13}, std::size_t{30}, good.size() - 4}) {
    INFO("cut at " << cut);
    const std::vector<std::uint8_t> truncated(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(cut));
    CHECK_FALSE(detail::decode_gif(truncated, 1 << 20).is_ok());
  }
  // The pixel limit applies to the logical screen, before anything is allocated.
  const Result<Image> big = detail::decode_gif(gif(60000, 60000, -1, {0, 0, 1, 1, false, {0}}), 1 << 20);
  REQUIRE_FALSE(big.is_ok());
  CHECK(big.error().kind == ErrorKind::kLimitExceeded);
  // The frame's own area is bounded too: every row of it would be decoded even off the screen. A 1 x 1
  // screen with a 2000 x 2000 frame (4·10⁶ pixels, over a limit of 2^20) is refused before any decoding.
  const Result<Image> big_frame = detail::decode_gif(gif(1, 1, -1, {0, 0, 2000, 2000, false, {0}}), 1 << 20);
  REQUIRE_FALSE(big_frame.is_ok());
  CHECK(big_frame.error().kind == ErrorKind::kLimitExceeded);
  // A file that ends before any image.
  std::vector<std::uint8_t> no_image(good.begin(), good.begin() + 13 + 12);
  no_image.push_back(0x3b);
  CHECK_FALSE(detail::decode_gif(no_image, 1 << 20).is_ok());
}

TEST_CASE("GIF: rows of a frame below the screen are not decoded", "[svg][image][gif]") {
  // A 1 x 2 screen and a 1 x 5 frame whose data holds only its first two rows: what the screen shows
  // is complete, so the image decodes (reading on would meet the end of the data and fail).
  const Result<Image> image = detail::decode_gif(gif(1, 2, -1, {0, 0, 1, 5, false, {1, 2}}), 1 << 20);
  INFO((image.is_ok() ? std::string() : image.error().message));
  REQUIRE(image.is_ok());
  CHECK(is(image->at(0, 0), 0, 255, 0, 255));
  CHECK(is(image->at(0, 1), 0, 0, 255, 255));
}

TEST_CASE("WebP: a lossless image decodes to its pixels, premultiplied", "[svg][image][webp]") {
  // Opaque red, green at alpha 128 (premultiplied 128·255/255 -> (0, 128, 0, 128)), transparent.
  const std::vector<std::uint8_t> rgba{255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 0, 0};
  const std::vector<std::uint8_t> bytes = webp(3, 1, rgba);
  CHECK(detail::sniff_image_format(bytes) == detail::ImageFormat::kWebp);
  const Result<Image> image = detail::decode_webp(bytes, 1 << 20);
  REQUIRE(image.is_ok());
  CHECK(image->width() == 3);
  CHECK(image->height() == 1);
  CHECK(is(image->at(0, 0), 255, 0, 0, 255));
  CHECK(is(image->at(1, 0), 0, 128, 0, 128));
  CHECK(is(image->at(2, 0), 0, 0, 0, 0));
  CHECK_FALSE(detail::decode_webp(bytes, 2).is_ok());  // 3 pixels, beyond a limit of 2
  const std::vector<std::uint8_t> truncated(bytes.begin(), bytes.begin() + 20);
  CHECK_FALSE(detail::decode_webp(truncated, 1 << 20).is_ok());
}

namespace {

// `uri`, a 2 x 1 image of green then blue, drawn 20 x 10 with nearest sampling (each texel a 10 x 10
// square); its two texels are checked here, the warnings by the caller.
RenderedDocument render_green_blue(const std::string& uri) {
  RenderedDocument out = render(svg_document("width=\"20\" height=\"10\"",
                                             "<image width=\"20\" height=\"10\" "
                                             "image-rendering=\"optimizeSpeed\" href=\"" +
                                                 uri + "\"/>"));
  CHECK(is(out.image.at(5, 5), 0, 255, 0, 255));
  CHECK(is(out.image.at(15, 5), 0, 0, 255, 255));
  return out;
}

}  // namespace

TEST_CASE("image: GIF and WebP data URIs are drawn", "[svg][image][gif][webp]") {
  // Each image is 2 x 1, drawn 20 x 10 with nearest sampling: each texel covers a 10 x 10 square.
  const std::string gif_uri = "data:image/gif;base64," + base64(gif(2, 1, -1, {0, 0, 2, 1, false, {1, 2}}));
  const std::string webp_uri =
      "data:image/webp;base64," + base64(webp(2, 1, {0, 255, 0, 255, 0, 0, 255, 255}));
  for (const std::string& uri : {gif_uri, webp_uri}) {
    const RenderedDocument out = render_green_blue(uri);
    CHECK(out.warnings.empty());
  }
}

// Regression: an animated WebP was refused ("an animated WebP image is not supported") while an animated GIF
// showed its first frame without a word. Both now draw their first frame, with the same warning.
TEST_CASE("image: an animated GIF or WebP draws its first frame, with a warning", "[svg][image][gif][webp]") {
  // Frame 1: green, blue; frame 2: red, red (palette entries 1, 2 and 0 for the GIF).
  const std::vector<std::uint8_t> webp_bytes =
      animated_webp(2, 1, {{0, 255, 0, 255, 0, 0, 255, 255}, {255, 0, 0, 255, 255, 0, 0, 255}});
  const std::vector<std::uint8_t> gif_bytes = animated_gif(2, {1, 2}, {0, 0});
  bool animated = false;
  const Result<Image> webp_image = detail::decode_webp(webp_bytes, 1 << 20, &animated);
  REQUIRE(webp_image.is_ok());
  CHECK(animated);
  CHECK(is(webp_image->at(0, 0), 0, 255, 0, 255));
  CHECK(is(webp_image->at(1, 0), 0, 0, 255, 255));
  animated = false;
  const Result<Image> gif_image = detail::decode_gif(gif_bytes, 1 << 20, &animated);
  REQUIRE(gif_image.is_ok());
  CHECK(animated);
  CHECK(is(gif_image->at(0, 0), 0, 255, 0, 255));
  CHECK(is(gif_image->at(1, 0), 0, 0, 255, 255));
  // A still image is not an animation.
  CHECK(detail::decode_gif(gif(2, 1, -1, {0, 0, 2, 1, false, {1, 2}}), 1 << 20, &animated).is_ok());
  CHECK_FALSE(animated);
  animated = true;
  CHECK(detail::decode_webp(webp(1, 1, {0, 0, 0, 255}), 1 << 20, &animated).is_ok());
  CHECK_FALSE(animated);

  for (const std::string& uri :
       {"data:image/gif;base64," + base64(gif_bytes), "data:image/webp;base64," + base64(webp_bytes)}) {
    INFO(uri.substr(0, 16));
    const RenderedDocument out = render_green_blue(uri);
    CHECK(contains(out.warnings, "animation is not supported, first frame drawn"));
  }
}

// The first frame of an animation is decoded into the returned image itself, at its offset on the canvas
// (RFC 9649 2.7): libwebpdemux's animation decoder, used before, held two canvases of its own that the
// render's memory budget did not count. The canvas outside the frame is transparent (the background colour
// is a hint a decoder may ignore, and libwebp's own animation decoder ignores it too), and the frame over
// transparency is its own pixels whether blended or not. Exact: the encoding is lossless.
TEST_CASE("WebP: an animation's first frame lands at its offset on a transparent canvas",
          "[svg][image][webp]") {
  // Green, blue at alpha 128 (premultiplied (0, 0, 128, 128)), white, green at alpha 64 ((0, 64, 0, 64)).
  const std::vector<std::uint8_t> first{0, 255, 0, 255, 0, 0, 255, 128, 255, 255, 255, 255, 0, 255, 0, 64};
  bool animated = false;
  const Result<Image> image = detail::decode_webp(offset_frame_webp(first), 1 << 20, &animated);
  INFO((image.is_ok() ? std::string() : image.error().message));
  REQUIRE(image.is_ok());
  CHECK(animated);
  REQUIRE(image->width() == 4);
  REQUIRE(image->height() == 4);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      if (x >= 2 && y >= 2) continue;
      INFO("x " << x << " y " << y);
      CHECK(is(image->at(x, y), 0, 0, 0, 0));
    }
  }
  CHECK(is(image->at(2, 2), 0, 255, 0, 255));
  CHECK(is(image->at(3, 2), 0, 0, 128, 128));
  CHECK(is(image->at(2, 3), 255, 255, 255, 255));
  CHECK(is(image->at(3, 3), 0, 64, 0, 64));
}

// Regression: image-rendering was read from the <image>'s own attribute only, and <feImage> ignored it. It is
// an inherited property (SVG 1.1 15.3) set by attributes and CSS alike, and applies to <feImage> as to
// <image>. The 2 x 1 image (green, blue) is drawn 20 x 10: pixel 9's centre lies at texel 0.95, all green
// under nearest sampling and a green-blue mix under bilinear.
TEST_CASE("image: image-rendering is inherited, read from CSS, and applies to feImage", "[svg][image]") {
  const std::string uri = "data:image/gif;base64," + base64(gif(2, 1, -1, {0, 0, 2, 1, false, {1, 2}}));
  const std::string image =
      "<image width=\"20\" height=\"10\" preserveAspectRatio=\"none\" href=\"" + uri + "\"/>";
  const std::string fe_image_filter =
      "<filter id=\"f\" filterUnits=\"userSpaceOnUse\" x=\"0\" y=\"0\" width=\"20\" height=\"10\">"
      "<feImage image-rendering=\"optimizeSpeed\" preserveAspectRatio=\"none\" href=\"" +
      uri + "\"/></filter>";
  const std::string bodies[] = {
      "<g image-rendering=\"optimizeSpeed\">" + image + "</g>",
      "<style>g { image-rendering: pixelated }</style><g>" + image + "</g>",
      fe_image_filter + "<rect width=\"20\" height=\"10\" filter=\"url(#f)\"/>",
  };
  for (const std::string& body : bodies) {
    const RenderedDocument out = render(svg_document("width=\"20\" height=\"10\"", body));
    CHECK(is(out.image.at(9, 5), 0, 255, 0, 255));
    CHECK(is(out.image.at(10, 5), 0, 0, 255, 255));
  }
  // Without it, bilinear sampling mixes the two texels at pixel 9.
  const RenderedDocument smooth = render(svg_document("width=\"20\" height=\"10\"", image));
  CHECK(smooth.image.at(9, 5).b > 0);
}
