// Stroke outlines of simple shapes have areas known in closed form: each test renders the outline
// (nonzero) and compares the total coverage with the formula. Tolerance: the outline is within 0.05 px
// of the exact stroke (stroke.h), so the area is within 0.05 · perimeter, plus 8-bit rounding of at most
// 0.5/255 per covered pixel; the bounds below use that sum.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "stroke_render.h"

namespace curvescan {
namespace {

using testing::polyline_path;
using testing::render_stroke;

constexpr double kTolerance = 0.05;

double area_bound(double perimeter, const testing::CoverageMask& mask) {
  return kTolerance * perimeter + 0.5 / 255.0 * static_cast<double>(mask.values.size());
}

TEST_CASE("a horizontal line with each cap has the area of its rectangle plus the caps", "[stroke]") {
  const Path line = polyline_path({{20.5, 40.25}, {80.5, 40.25}});
  StrokeStyle style;
  style.width = 10.0;
  const double length = 60.0, w = 10.0;
  struct Case {
    LineCap cap;
    double area;
  };
  const Case cases[] = {{LineCap::kButt, length * w},
                        {LineCap::kSquare, (length + w) * w},
                        {LineCap::kRound, length * w + std::numbers::pi * 25.0}};
  for (const Case& c : cases) {
    style.cap = c.cap;
    const testing::CoverageMask mask = render_stroke(line, style, 120, 80, kTolerance);
    CHECK(mask.total() == Approx(c.area).margin(area_bound(2 * (length + w) + 2 * w, mask)));
  }
}

TEST_CASE("a closed square with miter joins is the outer square minus the inner one", "[stroke]") {
  const Path square = polyline_path({{20, 20}, {80, 20}, {80, 80}, {20, 80}}, true);
  StrokeStyle style;
  style.width = 8.0;
  style.join = LineJoin::kMiter;
  const testing::CoverageMask mask = render_stroke(square, style, 100, 100, kTolerance);
  // Pixel-aligned: the outline is exact here, so only 8-bit rounding remains.
  CHECK(mask.total() == Approx(68.0 * 68.0 - 52.0 * 52.0).margin(0.5 / 255.0 * 100 * 100));
  for (int i = 16; i < 84; ++i) CHECK(mask.at(i, 17) == 255);
  CHECK(mask.at(50, 50) == 0);
  CHECK(mask.at(15, 15) == 0);
  CHECK(mask.at(16, 16) == 255);  // the miter corner is filled
}

TEST_CASE("bevel and round joins of a closed square cut the outer corners", "[stroke]") {
  const Path square = polyline_path({{20, 20}, {80, 20}, {80, 80}, {20, 80}}, true);
  StrokeStyle style;
  style.width = 8.0;
  const double h = 4.0, frame = 68.0 * 68.0 - 52.0 * 52.0;
  style.join = LineJoin::kBevel;
  const testing::CoverageMask bevel = render_stroke(square, style, 100, 100, kTolerance);
  CHECK(bevel.total() == Approx(frame - 4 * 0.5 * h * h).margin(area_bound(8 * 4 * h, bevel)));
  style.join = LineJoin::kRound;
  const testing::CoverageMask round = render_stroke(square, style, 100, 100, kTolerance);
  CHECK(round.total() == Approx(frame - 4 * (1 - std::numbers::pi / 4) * h * h).margin(area_bound(8 * 4 * h, round)));
}

TEST_CASE("a full circle stroked is the annulus", "[stroke]") {
  PathBuilder builder;
  builder.arc({50, 50}, 30, 30, 0, 0, 2 * std::numbers::pi).close();
  const Path circle = *builder.build();
  StrokeStyle style;
  style.width = 12.0;
  const testing::CoverageMask mask = render_stroke(circle, style, 100, 100, kTolerance);
  const double annulus = std::numbers::pi * (36.0 * 36.0 - 24.0 * 24.0);
  CHECK(mask.total() == Approx(annulus).margin(area_bound(2 * std::numbers::pi * 60, mask)));
}

TEST_CASE("a stroke wider than the circle's diameter fills the disc without a hole", "[stroke][strong]") {
  // Half-width 40 > radius 15: the inner offset inverts; the true stroke is the disc of radius 55.
  PathBuilder builder;
  builder.arc({60, 60}, 15, 15, 0, 0, 2 * std::numbers::pi).close();
  StrokeStyle style;
  style.width = 80.0;
  const testing::CoverageMask mask = render_stroke(*builder.build(), style, 120, 120, kTolerance);
  CHECK(mask.at(60, 60) == 255);
  CHECK(mask.total() == Approx(std::numbers::pi * 55 * 55).margin(area_bound(2 * std::numbers::pi * 55, mask)));
}

TEST_CASE("a miter join within the limit reaches the tip, beyond it falls back to a bevel", "[stroke]") {
  // A right angle: miter ratio 1/sin(45°) = 1.414.
  const Path corner = polyline_path({{20, 80}, {50, 20}, {80, 80}});
  StrokeStyle style;
  style.width = 10.0;
  style.miter_limit = 10.0;  // ratio 1/sin(φ/2), φ = 2·atan(0.5) = 53.13° -> 2.236
  const testing::CoverageMask miter = render_stroke(corner, style, 100, 100, kTolerance);
  style.miter_limit = 2.0;
  const testing::CoverageMask bevel = render_stroke(corner, style, 100, 100, kTolerance);
  style.join = LineJoin::kBevel;
  const testing::CoverageMask explicit_bevel = render_stroke(corner, style, 100, 100, kTolerance);
  // The miter tip is 2.236·5 = 11.18 px above the vertex (50, 20): the pixel row 10 is covered.
  CHECK(miter.at(50, 10) > 100);
  CHECK(bevel.at(50, 10) == 0);
  CHECK(testing::max_abs_diff(bevel, explicit_bevel) == 0);
  // The kite between bevel and tip: (tip - bevel midpoint) · bevel chord / 2.
  const double h = 5.0, phi = 2 * std::atan(0.5);
  const double tip = h / std::sin(phi / 2), bevel_mid = h * std::sin(phi / 2);
  const double kite = (tip - bevel_mid) * 2 * h * std::cos(phi / 2) / 2;
  CHECK(miter.total() - bevel.total() == Approx(kite).margin(0.2));
}

TEST_CASE("miter-clip cuts an over-long miter at miter_limit · width / 2", "[stroke]") {
  const Path corner = polyline_path({{20, 80}, {50, 20}, {80, 80}});
  StrokeStyle style;
  style.width = 10.0;
  style.miter_limit = 1.5;  // below the 2.236 ratio of this corner
  style.join = LineJoin::kMiterClip;
  const testing::CoverageMask clipped = render_stroke(corner, style, 100, 100, kTolerance);
  // The clip line is horizontal, 1.5 · 5 = 7.5 px above the vertex (50, 20): y = 12.5. Row 11 is empty,
  // the pixel (50, 12) is half covered (±2 for 8-bit rounding and the 0.05 px tolerance), row 13 full.
  for (int x = 0; x < 100; ++x) CHECK(clipped.at(x, 11) == 0);
  CHECK(std::abs(clipped.at(50, 12) - 128) <= 2);
  CHECK(clipped.at(50, 13) == 255);
  style.join = LineJoin::kBevel;
  CHECK(clipped.total() > render_stroke(corner, style, 100, 100, kTolerance).total());
}

}  // namespace
}  // namespace curvescan
