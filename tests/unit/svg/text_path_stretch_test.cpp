// <textPath method="stretch"> (SVG 1.1 10.13.2; raster/svg/text_element.cpp): glyph outlines bent along
// the path, each outline point at its distance along the path and its offset along the normal there.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "curvescan/svg/document.h"
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
