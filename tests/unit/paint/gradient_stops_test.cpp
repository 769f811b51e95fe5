// Gradient stops and the degenerate cases SVG prescribes (gradient.h), and the fast colour walker held to
// the plain double reference.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "curvescan/raster/gradient.h"

using namespace curvescan;

namespace {
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
const std::vector<GradientStop> kTwo{{0.0, {1, 0, 0, 1}}, {1.0, {0, 0, 1, 1}}};
}  // namespace

TEST_CASE("stop offsets are clamped, made non-decreasing, and padded to [0, 1]", "[paint][gradient]") {
  const std::vector<GradientStop> stops{
      {0.3, {1, 0, 0, 1}}, {0.1, {0, 1, 0, 1}}, {kNan, {0, 0, 1, 1}}, {1.7, {2, -1, kNan, 0.5}}};
  const std::vector<GradientStop> out = normalize_gradient_stops(stops);
  REQUIRE(out.size() == 5);  // a copy of the first stop at 0 in front
  CHECK(out[0] == GradientStop{0.0, {1, 0, 0, 1}});
  CHECK(out[1].offset == 0.3);
  CHECK(out[2].offset == 0.3);                       // 0.1 < 0.3 is raised to 0.3 (SVG 1.1 13.2.4)
  CHECK(out[3].offset == 0.3);                       // NaN counts as the largest offset so far
  CHECK(out[4] == GradientStop{1.0, {1, 0, 0, 0.5}});  // clamped offset and channels, NaN channel -> 0
  CHECK(normalize_gradient_stops({}).empty());
  const std::vector<GradientStop> early{{0.2, {0, 0, 0, 1}}, {0.6, {1, 1, 1, 1}}};
  const std::vector<GradientStop> padded = normalize_gradient_stops(early);
  REQUIRE(padded.size() == 4);
  CHECK(padded.front().offset == 0.0);
  CHECK(padded.back() == GradientStop{1.0, {1, 1, 1, 1}});
}

TEST_CASE("degenerate gradients become the solid or none paints SVG prescribes", "[paint][gradient]") {
  const std::vector<GradientStop> one{{0.4, {0.2, 0.4, 0.6, 0.5}}};
  CHECK(linear_gradient_paint({{0, 0}, {1, 0}}, {}, SpreadMethod::kPad).color == Rgba8{0, 0, 0, 0});
  CHECK(linear_gradient_paint({{0, 0}, {1, 0}}, {}, SpreadMethod::kPad).gradient == nullptr);
  const Paint single = linear_gradient_paint({{0, 0}, {1, 0}}, one, SpreadMethod::kPad);
  CHECK(single.kind() == PaintKind::kSolid);
  CHECK(single.color == Paint::solid({0.2, 0.4, 0.6, 0.5}).color);
  // Zero-length vector and r = 0: the last stop's colour.
  const Paint zero_length = linear_gradient_paint({{3, 3}, {3, 3}}, kTwo, SpreadMethod::kRepeat);
  CHECK(zero_length.kind() == PaintKind::kSolid);
  CHECK(zero_length.color == Rgba8{0, 0, 255, 255});
  const Paint zero_radius = radial_gradient_paint({{1, 1}, 0.0, {1, 1}, 0.0}, kTwo, SpreadMethod::kPad);
  CHECK(zero_radius.color == Rgba8{0, 0, 255, 255});
  // Negative radii, non-finite input and singular transforms paint nothing.
  CHECK(radial_gradient_paint({{1, 1}, -1.0, {1, 1}, 0.0}, kTwo, SpreadMethod::kPad).color.a == 0);
  CHECK(radial_gradient_paint({{1, 1}, 1.0, {1, 1}, -0.5}, kTwo, SpreadMethod::kPad).color.a == 0);
  CHECK(linear_gradient_paint({{0, kNan}, {1, 0}}, kTwo, SpreadMethod::kPad).color.a == 0);
  CHECK(linear_gradient_paint({{0, 0}, {1, 0}}, kTwo, SpreadMethod::kPad, Affine::scale(1, 0)).color.a == 0);
  CHECK(radial_gradient_paint({{1, 1}, 1.0, {1, 1}, 1.0}, kTwo, SpreadMethod::kPad).color.a ==
        0);  // same circles
  CHECK(linear_gradient_paint({{0, 0}, {1, 0}}, kTwo, SpreadMethod::kPad).kind() ==
        PaintKind::kLinearGradient);
  CHECK(radial_gradient_paint({{0, 0}, 1, {0, 0}, 0}, kTwo, SpreadMethod::kPad).kind() ==
        PaintKind::kRadialGradient);
}

TEST_CASE("a focal point outside the circle is moved inside along its direction", "[paint][gradient]") {
  const RadialGradient outside{{10, 10}, 5, {10, 30}, 0};
  const Point f = clamped_focal_point(outside);
  CHECK(f.x == 10.0);
  CHECK(f.y == Approx(10.0 + 5.0 * kFocalClampRatio).epsilon(1e-15));
  const RadialGradient inside{{10, 10}, 5, {12, 11}, 0};
  CHECK(clamped_focal_point(inside) == inside.focal);
  // Every pixel of the plane is then painted (the focal point is strictly inside): t exists everywhere.
  const Paint paint = radial_gradient_paint(outside, kTwo, SpreadMethod::kPad);
  for (double x = -50; x <= 50; x += 7.3) {
    for (double y = -50; y <= 70; y += 6.1) CHECK_FALSE(std::isnan(paint.gradient->parameter_at({x, y})));
  }
}

TEST_CASE("the radial parameter is 0 on the focal circle and 1 on the end circle", "[paint][gradient]") {
  const Paint paint = radial_gradient_paint({{0, 0}, 10, {2, 1}, 1.5}, kTwo, SpreadMethod::kPad);
  const GradientShader& g = *paint.gradient;
  // |d| = 1e-9 relative: the quadratic solve in double loses a few ulps of the inputs' scale.
  for (double angle = 0.0; angle < 6.28; angle += 0.37) {
    CHECK(g.parameter_at({10 * std::cos(angle), 10 * std::sin(angle)}) == Approx(1.0).margin(1e-9));
    CHECK(g.parameter_at({2 + 1.5 * std::cos(angle), 1 + 1.5 * std::sin(angle)}) == Approx(0.0).margin(1e-9));
  }
  CHECK(std::isnan(g.parameter_at({kNan, 0})));
}

TEST_CASE("hard stops: the later stop governs from the shared offset on", "[paint][gradient]") {
  const std::vector<GradientStop> hard{
      {0.0, {1, 0, 0, 1}}, {0.5, {1, 0, 0, 1}}, {0.5, {0, 0, 1, 1}}, {1.0, {0, 0, 1, 1}}};
  const Paint paint = linear_gradient_paint({{0, 0}, {1, 0}}, hard, SpreadMethod::kPad);
  CHECK(paint.gradient->color_at(0.5) == Rgba8{0, 0, 255, 255});
  CHECK(paint.gradient->color_at(0.499) == Rgba8{255, 0, 0, 255});
  CHECK(paint.gradient->color_at_reference(0.5) == Rgba8{0, 0, 255, 255});
  CHECK(paint.gradient->color_at_reference(0.499) == Rgba8{255, 0, 0, 255});
}

TEST_CASE("spread methods fold t as SVG says", "[paint][gradient]") {
  const Paint pad = linear_gradient_paint({{0, 0}, {1, 0}}, kTwo, SpreadMethod::kPad);
  const Paint reflect = linear_gradient_paint({{0, 0}, {1, 0}}, kTwo, SpreadMethod::kReflect);
  const Paint repeat = linear_gradient_paint({{0, 0}, {1, 0}}, kTwo, SpreadMethod::kRepeat);
  CHECK(pad.gradient->color_at(-3.0) == Rgba8{255, 0, 0, 255});
  CHECK(pad.gradient->color_at(7.0) == Rgba8{0, 0, 255, 255});
  // Exact periodicity and symmetry hold for the reference; the walker, like pixman, evaluates its float
  // lerp at the absolute position and truncates t towards zero, so it may differ by one level.
  const auto close = [](Rgba8 p, Rgba8 q) {
    return std::abs(p.r - q.r) <= 1 && std::abs(p.g - q.g) <= 1 && std::abs(p.b - q.b) <= 1 &&
           std::abs(p.a - q.a) <= 1;
  };
  for (const double t : {0.125, 0.3125, 0.71875}) {  // dyadic: t ± an integer is exact
    const GradientShader& rp = *repeat.gradient;
    const GradientShader& rf = *reflect.gradient;
    CHECK(rp.color_at_reference(t + 3.0) == rp.color_at_reference(t));
    CHECK(rp.color_at_reference(t - 2.0) == rp.color_at_reference(t));
    CHECK(rf.color_at_reference(2.0 - t) == rf.color_at_reference(t));
    CHECK(rf.color_at_reference(-t) == rf.color_at_reference(t));
    CHECK(close(rp.color_at(t + 3.0), rp.color_at(t)));
    CHECK(close(rp.color_at(t - 2.0), rp.color_at(t)));
    CHECK(close(rf.color_at(2.0 - t), rf.color_at(t)));
    CHECK(close(rf.color_at(-t), rf.color_at(t)));
  }
  CHECK(reflect.gradient->color_at(1.0) == Rgba8{0, 0, 255, 255});
  CHECK(repeat.gradient->color_at(1.0) == Rgba8{255, 0, 0, 255});
  CHECK(pad.gradient->color_at(kNan) == Rgba8{0, 0, 0, 0});
}

TEST_CASE("colour and alpha are interpolated straight, then premultiplied (as pixman does)",
          "[paint][gradient]") {
  const std::vector<GradientStop> fade{{0.0, {1, 0, 0, 1}}, {1.0, {0, 0, 1, 0}}};
  const Paint paint = linear_gradient_paint({{0, 0}, {1, 0}}, fade, SpreadMethod::kPad);
  // Midway: alpha 0.5 and straight (0.5, 0, 0.5): premultiplied (0.25, 0, 0.25, 0.5) -> (64, 0, 64, 128).
  CHECK(paint.gradient->color_at_reference(0.5) == Rgba8{64, 0, 64, 128});
  const Rgba8 fast = paint.gradient->color_at(0.5);
  CHECK(std::abs(fast.r - 64) <= 1);
  CHECK(std::abs(fast.a - 128) <= 1);
}

TEST_CASE("the walker stays within one level of the double reference (seeded random gradients)",
          "[paint][gradient]") {
  std::mt19937 rng(424242);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int worst = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<GradientStop> stops;
    const int count = 2 + trial % 5;
    for (int i = 0; i < count; ++i)
      stops.push_back({unit(rng), {unit(rng), unit(rng), unit(rng), unit(rng)}});
    std::sort(stops.begin(), stops.end(),
              [](const GradientStop& a, const GradientStop& b) { return a.offset < b.offset; });
    const auto spread = static_cast<SpreadMethod>(trial % 3);
    const Paint paint = linear_gradient_paint({{0, 0}, {1, 0}}, stops, spread);
    const GradientShader& g = *paint.gradient;
    for (int k = 0; k < 400; ++k) {
      // t on the 16.16 grid, where the walker does not quantize and only float rounding differs.
      const double t = std::round((unit(rng) * 5.0 - 2.0) * 65536.0) / 65536.0;
      const Rgba8 fast = g.color_at(t), slow = g.color_at_reference(t);
      worst = std::max({worst, std::abs(fast.r - slow.r), std::abs(fast.g - slow.g),
                        std::abs(fast.b - slow.b), std::abs(fast.a - slow.a)});
    }
  }
  // One level: pixman's float intercept form against exact double arithmetic (gradient_walker.h); stop
  // channels are quantized to 16 bits on the fast side (< 0.004 levels).
  CHECK(worst <= 1);
}
