// Curves whose control points coincide, or nearly coincide, with their end points: the direction of the
// caps and of the joins with the neighbouring segments comes from the first control point that is not
// (practically) on the end point, then from the chord — SVG 2 §9.5.2 "Path directionality" for
// coincident points, and what Cairo, Skia and resvg draw. The curve's own derivative there points at the
// nearby control point, a direction the curve keeps only over a length of that order; a cap drawn along
// it would stand across the stroke.
//
// Oracle: Cairo. Its 24.8 fixed-point coordinates merge points closer than 1/512 px, so for offsets of
// 1e-9 and 1e-4 px it strokes exactly the coincident case (the direction of the next distinct control
// point). The bounds are the fill oracle's (MaskComparison::within_bounds: no far pixel differs, max |Δ|
// <= 20/255, mean <= 4/255, totals within 0.5 %), which a cap turned by 90° on a 16 px stroke breaks by
// dozens of far pixels. A control point 0.5 px away is a real one, far above the coincidence distance
// (tolerance/64, stroker.cpp): it keeps its direction (the last test). Neither Cairo nor the swept-area
// reference of stroke_scene.h is an oracle there: its uniform samples miss a quarter turn within a
// hundredth of a pixel (stroke_hard_cases_test.cpp checks such a turn against it with the curve cut at
// its ends), and Cairo differs from the exact sweep.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "stroke_scene.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

constexpr double kTolerance = 0.02;  // device px, as the other stroke oracle tests
using C = SceneCommand;

void check_cairo(const StrokeScene& scene) {
  const MaskComparison m =
      compare_masks(render_scene_curvescan(scene, kTolerance), render_scene_cairo(scene, kTolerance));
  INFO(scene.name << " vs Cairo: far " << m.far_mismatches << " max " << m.max_diff << " mean " << m.mean_diff
                  << " total " << m.total_ours << " vs " << m.total_other);
  CHECK(m.within_bounds());
}

StrokeScene scene(std::string name, std::vector<SceneCommand> commands, LineJoin join, LineCap cap) {
  StrokeScene s;
  s.name = std::move(name);
  s.commands = std::move(commands);
  s.style.width = 16;
  s.style.join = join;
  s.style.cap = cap;
  return s;
}

// Offsets of the control points from their end points, perpendicular to the curve's direction there:
// exact coincidence and two near coincidences (Cairo merges both).
constexpr double kOffsets[] = {0.0, 1e-9, 1e-4};

std::string label(const char* what, double offset) {
  return std::string(what) + " offset " + std::to_string(offset);
}

}  // namespace

TEST_CASE("a line drawn as a cubic with control points on or near its ends is capped along its chord",
          "[oracle][stroke][coincident]") {
  for (const double e : kOffsets) {
    for (const LineCap cap : {LineCap::kButt, LineCap::kSquare, LineCap::kRound}) {
      // P1 just above P0, P2 just below P3: the derivative at each end points across the line.
      check_cairo(scene(label("line as cubic", e),
                        {{C::kMove, {{24, 64}}}, {C::kCubic, {{24, 64 - e}, {104, 64 + e}, {104, 64}}}},
                        LineJoin::kMiter, cap));
    }
  }
}

TEST_CASE("a curve with a control point near its start takes the next control point's direction",
          "[oracle][stroke][coincident]") {
  for (const double e : kOffsets) {
    for (const LineCap cap : {LineCap::kButt, LineCap::kSquare, LineCap::kRound}) {
      // P2 - P0 = (40, -80); the offset of P1 is along (2, 1), perpendicular to it.
      const double u = e / std::sqrt(5.0);
      check_cairo(scene(label("curve", e),
                        {{C::kMove, {{20, 100}}}, {C::kCubic, {{20 + 2 * u, 100 + u}, {60, 20}, {108, 100}}}},
                        LineJoin::kMiter, cap));
    }
  }
}

TEST_CASE("joins on both sides of a line drawn as a cubic follow its chord", "[oracle][stroke][coincident]") {
  for (const double e : kOffsets) {
    for (const LineJoin join : {LineJoin::kMiter, LineJoin::kRound, LineJoin::kBevel}) {
      // Lines in and out at 60°-ish corners: a join turned by the vanishing derivative would bend the
      // miter tip or the bevel far from Cairo's.
      check_cairo(scene(label("joined line as cubic", e),
                        {{C::kMove, {{14, 110}}},
                         {C::kLine, {{34, 60}}},
                         {C::kCubic, {{34, 60 - e}, {94, 60 + e}, {94, 60}}},
                         {C::kLine, {{114, 110}}}},
                        join, LineCap::kButt));
    }
  }
}

TEST_CASE("a control point 0.5 px from the end is a real one: it still sets the end's direction",
          "[oracle][stroke][coincident]") {
  // The same line as a cubic, its control points 0.5 px across the line: the curve leaves its ends across
  // it, so the stroke's ends differ from those of the coincident case (which is Cairo's, above) by more
  // than the oracle bounds. Were 0.5 px taken for coincidence, they would be equal.
  const auto line = [](double e) {
    return scene("line as cubic",
                 {{C::kMove, {{24, 64}}}, {C::kCubic, {{24, 64 - e}, {104, 64 + e}, {104, 64}}}},
                 LineJoin::kMiter, LineCap::kButt);
  };
  const MaskComparison m = compare_masks(render_scene_curvescan(line(0.5), kTolerance),
                                         render_scene_curvescan(line(0.0), kTolerance));
  INFO("0.5 px vs coincident: far " << m.far_mismatches << " max " << m.max_diff);
  CHECK_FALSE(m.within_bounds());
}
