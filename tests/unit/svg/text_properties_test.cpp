// The text layout properties (raster/svg/text_properties.h) and the path measure of <textPath>
// (raster/svg/text_path_measure.h).
#include "svg/text_properties.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "curvescan/raster/path_builder.h"
#include "property_test_support.h"
#include "svg/computed_style.h"
#include "svg/text_path_measure.h"

using namespace curvescan;
using namespace curvescan::svg::detail;

namespace {

// Applies one declaration through the cascade's property table; true when it was valid (no warning).
bool apply(TextProperties& style, std::string_view name, std::string_view value) {
  ComputedStyle computed;
  computed.text = style;
  const bool valid = curvescan::svg::testing::apply_declaration(computed, ComputedStyle{}, name, value);
  style = computed.text;
  return valid;
}

}  // namespace

TEST_CASE("text properties: keywords and lengths, invalid values refused") {
  TextProperties style;
  CHECK(apply(style, "direction", "rtl"));
  CHECK(style.right_to_left);
  CHECK_FALSE(apply(style, "direction", "up"));
  CHECK(apply(style, "unicode-bidi", "isolate-override"));
  CHECK(style.unicode_bidi == UnicodeBidi::kIsolateOverride);
  CHECK_FALSE(apply(style, "unicode-bidi", "sideways"));
  CHECK(apply(style, "letter-spacing", "0.5em"));
  REQUIRE(style.letter_spacing);
  CHECK(style.letter_spacing->unit == svg::LengthUnit::kEm);
  CHECK(apply(style, "letter-spacing", "normal"));
  CHECK_FALSE(style.letter_spacing);
  // A <length-percentage> (CSS Text 4), the percentage kept to resolve against the font
  // size of each element at layout.
  CHECK(apply(style, "word-spacing", "10%"));
  REQUIRE(style.word_spacing);
  CHECK(style.word_spacing->unit == svg::LengthUnit::kPercent);
  CHECK(style.word_spacing->value == 10.0);
  CHECK(apply(style, "letter-spacing", "-5%"));
  REQUIRE(style.letter_spacing);
  CHECK(style.letter_spacing->unit == svg::LengthUnit::kPercent);
  CHECK_FALSE(apply(style, "letter-spacing", "5%%"));
  CHECK(apply(style, "baseline-shift", "super"));
  CHECK(style.baseline_shift.kind == BaselineShift::Kind::kSuper);
  CHECK(apply(style, "baseline-shift", "-30%"));
  CHECK(style.baseline_shift.kind == BaselineShift::Kind::kLength);
  CHECK(style.baseline_shift.length.value == -30.0);
  CHECK_FALSE(apply(style, "baseline-shift", "high"));
  CHECK(apply(style, "dominant-baseline", "text-top"));
  CHECK(style.dominant_baseline == Baseline::kTextBeforeEdge);
  CHECK_FALSE(apply(style, "dominant-baseline", "baseline"));  // alignment-baseline only
  CHECK(apply(style, "alignment-baseline", "baseline"));
  CHECK(apply(style, "text-decoration", "underline  line-through"));
  CHECK(style.decoration.underline);
  CHECK(style.decoration.line_through);
  CHECK_FALSE(style.decoration.overline);
  CHECK_FALSE(apply(style, "text-decoration", "underline wavy"));
  CHECK(apply(style, "text-decoration", "none"));
  CHECK_FALSE(style.decoration.any());
  // SVG 1.1 and CSS vertical modes; the sideways modes set every glyph sideways, sideways-lr bottom to top.
  CHECK(apply(style, "writing-mode", "tb"));
  CHECK(style.vertical);
  CHECK(apply(style, "writing-mode", "lr-tb"));
  CHECK_FALSE(style.vertical);
  CHECK(apply(style, "writing-mode", "vertical-rl"));
  CHECK(style.vertical);
  CHECK_FALSE(style.sideways);
  CHECK(apply(style, "writing-mode", "sideways-rl"));
  CHECK((style.vertical && style.sideways && !style.bottom_to_top));
  CHECK(apply(style, "writing-mode", "sideways-lr"));
  CHECK((style.vertical && style.sideways && style.bottom_to_top));
  CHECK(apply(style, "writing-mode", "vertical-lr"));
  CHECK((style.vertical && !style.sideways && !style.bottom_to_top));
  CHECK_FALSE(apply(style, "writing-mode", "diagonal"));
}

TEST_CASE("text properties: which are inherited") {
  TextProperties parent;
  parent.right_to_left = true;
  parent.decoration.underline = true;
  parent.unicode_bidi = UnicodeBidi::kEmbed;
  parent.baseline_shift.kind = BaselineShift::Kind::kSub;
  TextProperties child = parent;
  reset_non_inherited(child);
  CHECK(child.right_to_left);           // direction is inherited
  CHECK_FALSE(child.decoration.any());  // decoration is drawn by the declaring element, not inherited
  CHECK(child.unicode_bidi == UnicodeBidi::kNormal);
  CHECK(child.baseline_shift.kind == BaselineShift::Kind::kBaseline);
}

TEST_CASE("text path measure: length, points and tangents — reversed — closed") {
  PathBuilder builder;
  builder.move_to({0, 0}).line_to({30, 0}).line_to({30, 40});
  const Result<Path> path = builder.build();
  REQUIRE(path.is_ok());
  const std::optional<PathMeasure> forward = PathMeasure::measure(*path, 0.01, false);
  REQUIRE(forward);
  CHECK(forward->length() == Approx(70.0));
  CHECK_FALSE(forward->closed());
  const PathMeasure::Sample a = forward->at(10.0);
  CHECK(a.point.x == Approx(10.0));
  CHECK(a.point.y == Approx(0.0).margin(1e-12));
  CHECK(a.tangent.x == Approx(1.0));
  const PathMeasure::Sample b = forward->at(50.0);
  CHECK(b.point.x == Approx(30.0));
  CHECK(b.point.y == Approx(20.0));
  CHECK(b.tangent.y == Approx(1.0));
  // Beyond the ends: clamped.
  CHECK(forward->at(1e9).point.y == Approx(40.0));
  CHECK(forward->at(-5.0).point.x == Approx(0.0).margin(1e-12));
  const std::optional<PathMeasure> backward = PathMeasure::measure(*path, 0.01, true);
  REQUIRE(backward);
  CHECK(backward->at(20.0).point.y == Approx(20.0));
  CHECK(backward->at(20.0).tangent.y == Approx(-1.0));

  // A circle of radius 50, four exact conic quarters (weight cos 45°), flattened within 0.001.
  PathBuilder circle;
  const double w = std::sqrt(0.5);
  circle.move_to({50, 0}).conic_to({50, 50}, {0, 50}, w).conic_to({-50, 50}, {-50, 0}, w);
  circle.conic_to({-50, -50}, {0, -50}, w).conic_to({50, -50}, {50, 0}, w).close();
  const Result<Path> round = circle.build();
  REQUIRE(round.is_ok());
  const std::optional<PathMeasure> measured = PathMeasure::measure(*round, 0.001, false);
  REQUIRE(measured);
  CHECK(measured->closed());
  // Chords within 0.001 of an arc of radius 50 are shorter than it by a relative 0.001/(3·50) ≈ 7e-6 at most
  // (sagitta h of a chord of half-angle t: h = r(1 - cos t), length ratio sin t / t ≈ 1 - t²/6 = 1 - h/(3r)).
  CHECK(measured->length() == Approx(2.0 * 3.14159265358979323846 * 50.0).epsilon(1e-5));
  // A path of zero length has no measure.
  PathBuilder dot;
  dot.move_to({5, 5}).line_to({5, 5});
  const Result<Path> point = dot.build();
  REQUIRE(point.is_ok());
  CHECK_FALSE(PathMeasure::measure(*point, 0.01, false));
}
