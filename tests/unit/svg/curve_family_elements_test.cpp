// cs:explicit, cs:implicit and cs:patch: each draws what an SVG path of the library's own polylines or
// cubics draws, and reports splits, singular points and errors as warnings.
#include <catch2/catch.hpp>
#include <cstdio>
#include <string>

#include "curvescan/curves/bezier_patch.h"
#include "curvescan/curves/explicit_curve.h"
#include "curvescan/svg/document.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;

using curvescan::svg::testing::contains;

namespace {

std::string svg_document(const std::string& body) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:cs=\"urn:curvescan:curves\" width=\"64\" "
         "height=\"40\">" +
         body + "</svg>";
}

RenderedDocument render(const std::string& text) {
  Result<RenderedDocument> rendered = render_svg_document(text, {});
  INFO(text);
  REQUIRE(rendered.is_ok());
  return std::move(rendered).value();
}

std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, " %.17g", v);
  return buffer;
}

std::size_t painted(const Image& image) {
  std::size_t count = 0;
  for (const Rgba8& pixel : image.pixels()) count += pixel.a != 0;
  return count;
}

}  // namespace

TEST_CASE("cs:explicit draws the library's certified polyline", "[svg][curves]") {
  const std::string style = " fill=\"none\" stroke=\"#123\" stroke-width=\"1.5\"";
  const Image native =
      render(svg_document("<cs:explicit f=\"20 + 12*sin(x/6)\" x=\"2 62\" tolerance=\"0.05\"" + style + "/>"))
          .image;
  constexpr ExpressionVariable kX[] = {ExpressionVariable::kX};
  const auto f = Expression::parse("20 + 12*sin(x/6)", kX);
  REQUIRE(f.is_ok());
  ExplicitCurveOptions options;
  options.tolerance = 0.05;
  const auto curve = flatten_explicit_curve(*f, 2, 62, options);
  REQUIRE(curve.is_ok());
  REQUIRE(curve->polylines.size() == 1);
  std::string data = "M";
  for (std::size_t i = 0; i < curve->polylines[0].size(); ++i) {
    if (i == 1) data += " L";
    data += number(curve->polylines[0][i].x) + number(curve->polylines[0][i].y);
  }
  const Image path = render(svg_document("<path d=\"" + data + "\"" + style + "/>")).image;
  CHECK(native.pixels() == path.pixels());
  CHECK(painted(native) > 100);
}

TEST_CASE("cs:implicit circle covers the pixels of an SVG circle", "[svg][curves]") {
  const Image native = render(svg_document("<cs:implicit f=\"(x-20)^2 + (y-20)^2 - 196\" box=\"0 0 40 40\" "
                                           "tolerance=\"0.05\"/>"))
                           .image;
  const Image circle = render(svg_document("<circle cx=\"20\" cy=\"20\" r=\"14\"/>")).image;
  // The contour's vertices lie on the circle and its chords within 0.05 of it, the <circle> is flattened
  // within 0.1 px: edge coverage may differ by 0.15 px of area, 0.15 · 255 ≈ 38 levels.
  int max_delta = 0;
  for (std::size_t i = 0; i < native.pixels().size(); ++i) {
    max_delta = std::max(max_delta, std::abs(native.pixels()[i].a - circle.pixels()[i].a));
  }
  CHECK(max_delta <= 40);
  CHECK(native.at(20, 20).a == 255);  // a closed subpath: filled inside
}

TEST_CASE("cs:patch draws its iso-curves as the cubics of the patch", "[svg][curves]") {
  // A flat patch over [4, 60] x [4, 36] with a bulge; the default view is orthographic onto (x, y).
  BezierPatch patch;
  std::string points;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      const Point3 p{4.0 + 56.0 * j / 3 + (i == 1 ? 5.0 : 0.0), 4.0 + 32.0 * i / 3 + (j == 2 ? -4.0 : 0.0),
                     0.0};
      patch.points[4 * i + j] = p;
      points += number(p.x) + number(p.y) + number(p.z);
    }
  }
  const std::string style = " fill=\"none\" stroke=\"#123\" stroke-width=\"1\"";
  const Image native =
      render(svg_document("<cs:patch points=\"" + points + "\" iso=\"3 2\"" + style + "/>")).image;
  std::string data;
  for (int k = 0; k < 5; ++k) {
    const auto ctrl = k < 3 ? patch.curve_at_u(k / 2.0) : patch.curve_at_v(k - 3.0);
    data += " M" + number(ctrl[0].x) + number(ctrl[0].y) + " C";
    for (int c = 1; c < 4; ++c) data += number(ctrl[c].x) + number(ctrl[c].y);
  }
  const Image path = render(svg_document("<path d=\"" + data + "\"" + style + "/>")).image;
  CHECK(native.pixels() == path.pixels());
  CHECK(painted(native) > 100);
}

TEST_CASE("cs:explicit, cs:implicit and cs:patch report splits, singular points and errors",
          "[svg][curves]") {
  const RenderedDocument notes =
      render(svg_document("<cs:explicit f=\"tan(x)\" x=\"-3 3\" y=\"-20 20\" fill=\"none\" stroke=\"black\"/>"
                          "<cs:implicit f=\"(x^2 + y^2)^2 - 2*(x^2 - y^2)\" box=\"-2 -1.1 2.2 1.3\" "
                          "fill=\"none\" stroke=\"black\"/>"));
  CHECK(contains(notes.warnings, "<cs:explicit>: the graph of tan(x) is split at 2 places"));
  CHECK(contains(notes.warnings, "has a singular point near ("));
  const RenderedDocument bad = render(svg_document(
      "<cs:explicit f=\"sin(x\" x=\"0 1\"/><cs:implicit f=\"x+y\" box=\"0 0 1\"/>"
      "<cs:patch points=\"1 2 3\"/><cs:patch points=\"0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 "
      "0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\" eye=\"1 1 1\" target=\"1 1 1\"/>"));
  CHECK(contains(bad.warnings, "<cs:explicit>: f: column 6: expected ')' to close the '(' at column 4"));
  CHECK(contains(bad.warnings, "<cs:implicit>: attribute 'box' needs 4 numbers"));
  CHECK(contains(bad.warnings, "<cs:patch>: attribute 'points' needs a multiple of 48 numbers"));
  CHECK(contains(bad.warnings, "<cs:patch>: the camera's eye and target must differ"));
}
