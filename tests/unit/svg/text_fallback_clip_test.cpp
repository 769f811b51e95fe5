// SVG <text> with per-character font fallback, and <text> as a <clipPath> child, against the library:
// the same glyph outlines (text_layout.h with a FontFallback: text_path) filled, or pushed as a clip,
// through Canvas with the same paint.
//
// Tolerance: max |Δ| <= 1/255 per channel, as in text_document_test.cpp: both sides rasterize the same
// curves; only the summation order of glyph origins differs (~1e-13 px), which can flip the rounding of
// 255·coverage by one level. A wrong face, size or position moves whole edges (differences ~100/255).
#include <algorithm>
#include <catch2/catch.hpp>
#include <string>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/svg/document.h"
#include "curvescan/text/font_fallback.h"
#include "curvescan/text/font_lookup.h"
#include "curvescan/text/text_layout.h"

using namespace curvescan;

namespace {

constexpr int kWidth = 240;
constexpr int kHeight = 80;

svg::RenderedDocument render(const std::string& body) {
  const std::string xml = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(kWidth) +
                          "\" height=\"" + std::to_string(kHeight) + "\">" + body + "</svg>";
  Result<svg::RenderedDocument> rendered = svg::render_svg_document(xml, svg::RenderOptions{});
  REQUIRE(rendered.is_ok());
  return std::move(rendered).value();
}

Font font(const std::string& family) {
  Result<Font> loaded = load_font(FontQuery{family, 400, false}, false);
  REQUIRE(loaded.is_ok());
  return std::move(loaded).value();
}

Path fallback_text(const std::string& family, const std::string& utf8, Point origin, double size) {
  const Font primary = font(family);
  FontFallback fonts(primary, FontQuery{family, 400, false});
  TextStyle style;
  style.size = size;
  Result<Path> path = text_path(fonts, utf8, origin, style);
  REQUIRE(path.is_ok());
  return std::move(path).value();
}

int max_delta(const Image& a, const Image& b) {
  REQUIRE(a.pixels().size() == b.pixels().size());
  int worst = 0;
  for (std::size_t i = 0; i < a.pixels().size(); ++i) {
    const Rgba8 p = a.pixels()[i], q = b.pixels()[i];
    worst = std::max({worst, std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b), std::abs(p.a - q.a)});
  }
  return worst;
}

int inked_pixels(const Image& image) {
  return static_cast<int>(
      std::count_if(image.pixels().begin(), image.pixels().end(), [](const Rgba8& p) { return p.a > 0; }));
}

bool any_warning_mentions(const svg::RenderedDocument& rendered, const std::string& text) {
  return std::any_of(rendered.warnings.begin(), rendered.warnings.end(),
                     [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

// The axis-aligned rectangle from `top_left` to `bottom_right` as one closed contour, clockwise on screen
// like the SVG <rect> it stands for.
void append_rect(PathBuilder& builder, Point top_left, Point bottom_right) {
  builder.move_to(top_left);
  builder.line_to({bottom_right.x, top_left.y});
  builder.line_to(bottom_right);
  builder.line_to({top_left.x, bottom_right.y});
  builder.close();
}

}  // namespace

TEST_CASE("svg text: characters the face lacks come from the fallback face, as the library draws them",
          "[svg][text][fallback]") {
  // A ♠ ─ ■ in Cantarell: the last three from DejaVu Sans (tests/unit/font/font_fallback_test.cpp).
  const svg::RenderedDocument rendered =
      render("<text x='10' y='50' font-family='Cantarell' font-size='36'>A\xE2\x99\xA0\xE2\x94\x80\xE2\x96\xA0</text>");
  CHECK_FALSE(any_warning_mentions(rendered, ".notdef"));
  Result<Canvas> canvas = Canvas::create(kWidth, kHeight);
  REQUIRE(canvas.is_ok());
  const Path path = fallback_text("Cantarell", "A\xE2\x99\xA0\xE2\x94\x80\xE2\x96\xA0", {10.0, 50.0}, 36.0);
  REQUIRE(canvas->fill(path, Paint::solid({0, 0, 0, 1}), FillRule::kNonZero).is_ok());
  const Image expected = std::move(*canvas).take_image();
  CHECK(inked_pixels(expected) > 300);
  CHECK(max_delta(expected, rendered.image) <= 1);

  // And not what Cantarell alone draws (three .notdef boxes): the comparison can fail.
  Result<Canvas> boxes = Canvas::create(kWidth, kHeight);
  REQUIRE(boxes.is_ok());
  TextStyle style;
  style.size = 36.0;
  const Font cantarell = font("Cantarell");
  const Result<Path> notdefs = text_path(cantarell, "A\xE2\x99\xA0\xE2\x94\x80\xE2\x96\xA0", {10.0, 50.0}, style);
  REQUIRE(notdefs.is_ok());
  REQUIRE(boxes->fill(*notdefs, Paint::solid({0, 0, 0, 1}), FillRule::kNonZero).is_ok());
  CHECK(max_delta(std::move(*boxes).take_image(), rendered.image) > 100);
}

TEST_CASE("svg text: a character no installed face has is .notdef with one warning", "[svg][text][fallback]") {
  const svg::RenderedDocument rendered = render(
      "<text x='10' y='50' font-family='Cantarell' font-size='36'>a\xF4\x8F\xBF\xBD\xE2\x99\xA0\xF4\x8F\xBF\xBD</text>");
  const auto count = std::count_if(rendered.warnings.begin(), rendered.warnings.end(),
                                   [](const std::string& w) { return w.find("U+10FFFD") != std::string::npos; });
  CHECK(count == 1);
  CHECK_FALSE(any_warning_mentions(rendered, "U+2660"));
}

TEST_CASE("svg clipPath: a <text> child clips to its glyph outlines", "[svg][text][clip]") {
  const svg::RenderedDocument rendered = render(
      "<clipPath id='c'><text x='8' y='62' font-family='DejaVu Sans' font-size='56'>Clip\xCE\xA9</text></clipPath>"
      "<rect width='240' height='80' fill='#0000ff' clip-path='url(#c)'/>");
  CHECK(rendered.warnings.empty());
  Result<Canvas> canvas = Canvas::create(kWidth, kHeight);
  REQUIRE(canvas.is_ok());
  const Path glyphs = fallback_text("DejaVu Sans", "Clip\xCE\xA9", {8.0, 62.0}, 56.0);
  REQUIRE(canvas->push_clip(glyphs, FillRule::kNonZero).is_ok());
  PathBuilder rect;
  append_rect(rect, {0.0, 0.0}, {240.0, 80.0});
  const Result<Path> rect_path = rect.build();
  REQUIRE(rect_path.is_ok());
  REQUIRE(canvas->fill(*rect_path, Paint::solid({0, 0, 1, 1}), FillRule::kNonZero).is_ok());
  REQUIRE(canvas->pop_clip().is_ok());
  const Image expected = std::move(*canvas).take_image();
  // The glyphs cover some of the rect, far from all of it: a clip that was skipped (the whole rect) or
  // empty (nothing) fails here or in the comparison.
  CHECK(inked_pixels(expected) > 500);
  CHECK(inked_pixels(expected) < kWidth * kHeight / 2);
  CHECK(max_delta(expected, rendered.image) <= 1);
}

TEST_CASE("svg clipPath: text with a transform and a shape together", "[svg][text][clip]") {
  const svg::RenderedDocument rendered = render(
      "<clipPath id='c'><text x='0' y='0' transform='translate(10 60) scale(1.5)' font-family='DejaVu Sans' "
      "font-size='30'>Hi</text><rect x='150' y='10' width='60' height='60'/></clipPath>"
      "<rect width='240' height='80' fill='#00ff00' clip-path='url(#c)'/>");
  Result<Canvas> canvas = Canvas::create(kWidth, kHeight);
  REQUIRE(canvas.is_ok());
  // translate(10 60) scale(1.5) of 30-unit text at (0, 0) is 45-unit text at (10, 60): layout scales
  // linearly with the size (advances and kerning are font units times size / units_per_em).
  const Font sans = font("DejaVu Sans");
  FontFallback fonts(sans, FontQuery{"DejaVu Sans", 400, false});
  TextStyle style;
  style.size = 45.0;
  const Result<TextLayout> layout = layout_text(fonts, U"Hi", {10.0, 60.0}, style);
  REQUIRE(layout.is_ok());
  PathBuilder clip;
  REQUIRE(append_text_outlines(sans, *layout, clip).is_ok());
  append_rect(clip, {150.0, 10.0}, {210.0, 70.0});
  const Result<Path> clip_path = clip.build();
  REQUIRE(clip_path.is_ok());
  REQUIRE(canvas->push_clip(*clip_path, FillRule::kNonZero).is_ok());
  PathBuilder rect;
  append_rect(rect, {0.0, 0.0}, {240.0, 80.0});
  const Result<Path> rect_path = rect.build();
  REQUIRE(rect_path.is_ok());
  REQUIRE(canvas->fill(*rect_path, Paint::solid({0, 1, 0, 1}), FillRule::kNonZero).is_ok());
  REQUIRE(canvas->pop_clip().is_ok());
  const Image expected = std::move(*canvas).take_image();
  CHECK(inked_pixels(expected) > 60 * 60);
  CHECK(max_delta(expected, rendered.image) <= 1);
}
