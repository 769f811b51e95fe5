// <textPath method="stretch"> (SVG 1.1 10.13.2; raster/svg/text_element.cpp): glyph outlines bent along
// the path, each outline point at its distance along the path and its offset along the normal there.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "curvescan/svg/document.h"
#include "curvescan/text/font_lookup.h"
#include "curvescan/text/text_layout.h"
#include "svg_test_support.h"

using namespace curvescan;
using curvescan::svg::testing::inked_pixels;
using curvescan::svg::testing::max_delta;

namespace {

svg::RenderedDocument render(const std::string& path, const std::string& method, const std::string& text) {
  const std::string document =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"200\"><defs><path id=\"p\" d=\"" +
      path + "\"/></defs><text font-family=\"DejaVu Sans\" font-size=\"24\"><textPath href=\"#p\" method=\"" +
      method + "\">" + text + "</textPath></text></svg>";
  // Curves flattened within 0.001 px (the default 0.25 px would dominate the comparisons below).
  svg::RenderOptions options;
  options.tolerance = 0.001;
  Result<svg::RenderedDocument> rendered = svg::render_svg_document(document, options);
  REQUIRE(rendered.is_ok());
  return std::move(rendered).value();
}

// The ink of an image: the sum of its alpha, in pixels (exact coverage: the area of the shapes drawn).
double ink(const Image& image) {
  double sum = 0.0;
  for (const Rgba8& p : image.pixels()) sum += p.a / 255.0;
  return sum;
}

}  // namespace

TEST_CASE("textPath stretch on a straight path draws what align draws") {
  // A straight path bends nothing: the stretched outline is the aligned one, flattened within size/2000 =
  // 0.012 px and cut into pieces; the aligned curves are flattened within 0.001 px. Edges 0.013 px apart
  // change a pixel's coverage by at most 0.013 of it: 4/255.
  const svg::RenderedDocument align = render("M 10 100 L 190 100", "align", "Stretch");
  const svg::RenderedDocument stretch = render("M 10 100 L 190 100", "stretch", "Stretch");
  CHECK(stretch.warnings.empty());
  CHECK(inked_pixels(align.image) > 300);
  CHECK(max_delta(align.image, stretch.image) <= 4);
}

TEST_CASE("textPath stretch widens glyphs outside a circle as the radius grows") {
  // The upper half of a circle of radius r = 60 about (100, 120), clockwise on screen: the normal points to
  // the centre, so glyphs stand outwards. Stretched, a point at height h above the baseline keeps its
  // angle x / r, so the bars of "IIII" (width w in all, height H from the baseline) cover w (r + h) / r at
  // height h: their area is w H (1 + H / (2r)), against w H aligned.
  const std::string arc = "M 40 120 A 60 60 0 0 1 160 120";
  const svg::RenderedDocument align = render(arc, "align", "IIII");
  const svg::RenderedDocument stretch = render(arc, "stretch", "IIII");
  // H from the same bars on a straight line: their area over their width, the coverage of one row across
  // them (y = 95, inside the bars' height: each bar's row adds up to its width, edges included).
  const svg::RenderedDocument straight = render("M 10 100 L 190 100", "align", "IIII");
  double width = 0.0;
  for (int x = 0; x < straight.image.width(); ++x) width += straight.image.at(x, 95).a / 255.0;
  REQUIRE(width > 4.0);
  const double height = ink(straight.image) / width;
  CHECK(height == Approx(0.729 * 24.0).epsilon(0.05));  // DejaVu Sans' cap height, 1493 / 2048 em
  REQUIRE(ink(align.image) > 100.0);
  // Tolerance 0.5 %: coverage is exact area; the bent outline is within 0.012 px of the exact warp along
  // ~150 px of edges (< 2 px^2 of ~190 px^2), and the row's 8-bit coverage rounds by < 1/510 per pixel.
  CHECK(ink(stretch.image) / ink(align.image) == Approx(1.0 + height / 120.0).epsilon(0.005));
}

namespace {

// "WWW" in DejaVu Sans at 48 px on the upper half of a circle of radius 80 about (120, 130), clockwise on
// screen, so that the glyphs stand outwards and the baseline's normal (down in the glyph) points at the
// centre. W is wide (47 px): an aligned glyph's straight cell and underline reach up to (w/2)^2 / (2r) =
// 3.5 px off the circle at its ends; bent, they follow it.
constexpr double kCx = 120.0, kCy = 130.0, kRadius = 80.0, kSize = 48.0;

std::string arc_document(const std::string& method, const std::string& text_attributes,
                         const std::string& defs) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"240\" height=\"240\"><defs><path id=\"p\" "
         "d=\"M 40 130 A 80 80 0 0 1 200 130\"/>" +
         defs + "</defs><text font-family=\"DejaVu Sans\" font-size=\"48\" " + text_attributes +
         "><textPath href=\"#p\" method=\"" + method + "\">WWW</textPath></text></svg>";
}

svg::RenderedDocument render_document(const std::string& document) {
  svg::RenderOptions options;
  options.tolerance = 0.001;
  Result<svg::RenderedDocument> rendered = svg::render_svg_document(document, options);
  REQUIRE(rendered.is_ok());
  return std::move(rendered).value();
}

const Font& dejavu_sans() {
  static const Font font = [] {
    Result<Font> loaded = load_font(FontQuery{"DejaVu Sans", 400, false}, false);
    REQUIRE(loaded.is_ok());
    return std::move(loaded).value();
  }();
  return font;
}

// The pixels the underline adds to the text (the glyphs are the same in both images) whose centres lie
// outside the underline's band about the circle widened by `margin`, and the pixels it adds in all.
struct UnderlineCheck {
  int added = 0, outside = 0;
};
UnderlineCheck underline_band(const std::string& method) {
  const svg::RenderedDocument plain = render_document(arc_document(method, "", ""));
  const svg::RenderedDocument underlined =
      render_document(arc_document(method, "text-decoration=\"underline\"", ""));
  CHECK(underlined.warnings.empty());
  // The band across the baseline, y down (towards the centre): the post table's underline, centred at
  // underline_position with underline_thickness (text_decoration.cpp).
  const FontMetrics m = dejavu_sans().metrics();
  const double s = kSize / m.units_per_em;
  const double near = -(m.underline_position + 0.5 * m.underline_thickness) * s;  // nearest the baseline
  const double far = -(m.underline_position - 0.5 * m.underline_thickness) * s;
  UnderlineCheck check;
  for (int y = 0; y < 240; ++y) {
    for (int x = 0; x < 240; ++x) {
      // An added quarter of a pixel or more: the underline covers part of this pixel.
      if (underlined.image.at(x, y).a - plain.image.at(x, y).a < 64) continue;
      ++check.added;
      const double r = std::hypot(x + 0.5 - kCx, y + 0.5 - kCy);
      // Margin: a pixel the band covers a quarter of has its centre within 0.71 px (half a diagonal) of it.
      if (r < kRadius - far - 0.71 || r > kRadius - near + 0.71) ++check.outside;
    }
  }
  return check;
}

}  // namespace

TEST_CASE("textPath stretch bends the underline with the glyphs") {
  const UnderlineCheck stretch = underline_band("stretch");
  CHECK(stretch.added > 100);  // the underline is drawn (142 px long, 2 px thick)
  CHECK(stretch.outside == 0);
  // The check has teeth: align's straight underline pieces leave the band at the ends of each W.
  const UnderlineCheck align = underline_band("align");
  CHECK(align.added > 100);
  CHECK(align.outside > 10);
}

TEST_CASE("textPath stretch: the object bounding box is that of the bent glyph cells") {
  // The cells bent are one annular sector: from radius r - descent to r + ascent, from the path's start
  // (the circle's leftmost point, angle pi) over the advance of "WWW" (angle L / r clockwise on screen).
  const FontMetrics m = dejavu_sans().metrics();
  const double s = kSize / m.units_per_em;
  TextStyle style;
  style.size = kSize;
  const Result<TextLayout> layout = layout_text(dejavu_sans(), U"WWW", {0.0, 0.0}, style);
  REQUIRE(layout.is_ok());
  const double length = layout->lines.front().advance;
  const double end = std::numbers::pi - length / kRadius;  // angle of the last cell's end, y up
  REQUIRE(end > 0.0);
  REQUIRE(end < 0.5 * std::numbers::pi);  // the sector passes the top of the circle
  const double outer = kRadius + m.ascender * s;
  // Left: the outer arc at angle pi; top: the outer arc at the top; right: the outer end corner; bottom:
  // the start, on the circle's horizontal diameter.
  const Rect box{kCx - outer, kCy - outer, kCx + outer * std::cos(end), kCy};
  // A gradient across the box with a steep ramp at its middle (4 % of the box, ~5 px), in both units: a
  // box off by a pixel moves the ramp by half a pixel, ~25/255 on the pixels in it. Tolerance 6/255: the
  // path is followed as its flattened polyline (text_path_measure.h, within 1/20000 of its box's diagonal,
  // 0.009 px here), whose first chord leans 0.015 rad off the circle's tangent, so the start edge of the
  // first cell leans too and its inner corner (a descent, 11 px, from the path) sits up to 0.17 px below
  // the diameter: the vertical ramp moves by 0.08 px, 4/255. The bent cells are sampled every size/40 =
  // 1.2 px along the outer arc, which cuts its top by 1.2^2 / (8 * 115) = 0.002 px: well under 1/255.
  const auto gradient = [](const std::string& units, double x1, double y1, double x2, double y2) {
    return "<linearGradient id=\"g\" gradientUnits=\"" + units + "\" x1=\"" + std::to_string(x1) +
           "\" y1=\"" + std::to_string(y1) + "\" x2=\"" + std::to_string(x2) + "\" y2=\"" +
           std::to_string(y2) +
           "\"><stop offset=\"0.48\" stop-color=\"red\"/><stop offset=\"0.52\" stop-color=\"blue\"/>"
           "</linearGradient>";
  };
  for (const bool across : {true, false}) {
    INFO((across ? "horizontal" : "vertical"));
    const std::string object = arc_document(
        "stretch", "fill=\"url(#g)\"", gradient("objectBoundingBox", 0, 0, across ? 1 : 0, across ? 0 : 1));
    const std::string user = arc_document(
        "stretch", "fill=\"url(#g)\"",
        gradient("userSpaceOnUse", box.x0, box.y0, across ? box.x1 : box.x0, across ? box.y0 : box.y1));
    const svg::RenderedDocument expected = render_document(user);
    const svg::RenderedDocument actual = render_document(object);
    CHECK(actual.warnings.empty());
    CHECK(inked_pixels(expected.image) > 500);
    CHECK(max_delta(expected.image, actual.image) <= 6);
    // The check has teeth: the straight cells of the glyphs align places reach ~7 px further, below the
    // diameter at the start and right of the end.
    std::string aligned = object;
    aligned.replace(aligned.find("method=\"stretch\""), 16, "method=\"align\"");
    std::string aligned_user = user;
    aligned_user.replace(aligned_user.find("method=\"stretch\""), 16, "method=\"align\"");
    CHECK(max_delta(render_document(aligned_user).image, render_document(aligned).image) > 20);
  }
}
