// Dash trains on curves against the swept-area reference: seeded random cubics stroked 16-60 wide with
// round caps and dash gaps shorter than the width, so that consecutive caps overlap and the stroker
// traces runs of dashes as one polygon (stroker_outline.cpp, continues_curved_train) wherever its
// containment checks allow. Bounds: the fill oracle's (MaskComparison::within_bounds); the reference
// dashes by arc length along densely sampled curves and unions every dash's pieces (stroke_scene.h).
#include <catch2/catch.hpp>
#include <cstddef>
#include <numbers>
#include <random>

#include "curvescan/raster/stroke.h"
#include "stroke_scene.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

std::size_t contour_count(const Path& path) {
  std::size_t count = 0;
  for (const PathElement& element : path) count += element.verb == PathVerb::kMove ? 1 : 0;
  return count;
}

}  // namespace

TEST_CASE("dash trains: wide round-capped dashes on seeded random cubics match the swept reference",
          "[oracle][stroke][dash]") {
  constexpr double kTolerance = 0.02;  // as in the hard cases
  std::mt19937 rng(5150);
  std::uniform_real_distribution<double> coordinate(24.0, 104.0);
  std::uniform_real_distribution<double> width(16.0, 60.0);
  std::uniform_real_distribution<double> offset(-20.0, 20.0);
  const std::vector<std::vector<double>> arrays = {{12, 6}, {9, 4, 2}, {20, 8}};
  for (int i = 0; i < 12; ++i) {
    StrokeScene s;
    s.name = "dash train " + std::to_string(i);
    const SceneCommand move{SceneCommand::kMove, {{coordinate(rng), coordinate(rng)}}};
    const SceneCommand cubic{SceneCommand::kCubic,
                             {{coordinate(rng), coordinate(rng)},
                              {coordinate(rng), coordinate(rng)},
                              {coordinate(rng), coordinate(rng)}}};
    s.commands = {move, cubic};
    s.style.width = width(rng);
    s.style.cap = LineCap::kRound;
    s.style.join = i % 2 == 0 ? LineJoin::kRound : LineJoin::kMiter;
    s.style.dash_array = arrays[static_cast<std::size_t>(i) % arrays.size()];
    s.style.dash_offset = offset(rng);
    const MaskComparison m = compare_masks(render_scene_curvescan(s, kTolerance), render_scene_reference(s));
    INFO(s.name << " width " << s.style.width << " vs reference: far " << m.far_mismatches << " max "
                << m.max_diff << " mean " << m.mean_diff << " total " << m.total_ours << " vs "
                << m.total_other);
    CHECK(m.within_bounds());
  }
}

TEST_CASE(
    "dash trains: round-capped dashes along a wide arc merge where the checks allow and match the reference",
    "[oracle][stroke][dash]") {
  // Radius 2000 (tangents 0.009 rad apart across a gap: not the straight case), h = 10, dashes 12 with
  // gaps 6 < h: every gap's caps overlap. A gap is bridged where the chord after it holds the end cap's
  // part in front of the next dash's normal (about 4 px), and the chord before it the start cap's part
  // behind the previous dash's end: the flattener's chords are sqrt(8·2000·0.01) = 12.6 px here, so about
  // half the gaps. The check is exact, hence conservative: the other gaps stay unbridged.
  constexpr double kTolerance = 0.02;
  StrokeScene s;
  s.name = "dashed arc";
  s.commands = {SceneCommand{SceneCommand::kArc,
                             {{64, 2064}},
                             2000,
                             -0.5 * std::numbers::pi - 0.03,
                             -0.5 * std::numbers::pi + 0.03}};
  s.style.width = 20;
  s.style.cap = LineCap::kRound;
  s.style.dash_array = {12, 6};
  const MaskComparison m = compare_masks(render_scene_curvescan(s, kTolerance), render_scene_reference(s));
  INFO("vs reference: far " << m.far_mismatches << " max " << m.max_diff << " mean " << m.mean_diff
                            << " total " << m.total_ours << " vs " << m.total_other);
  CHECK(m.within_bounds());
  const Path path = scene_path(s);
  const Result<Path> outline = stroke_path(path, s.style, kTolerance);
  const Result<Path> dashed = dash_path(path, s.style.dash_array, s.style.dash_offset, kTolerance);
  REQUIRE((outline.is_ok() && dashed.is_ok()));
  INFO(contour_count(*dashed) << " dashes, " << contour_count(*outline) << " outline contours");
  CHECK(contour_count(*dashed) >= 6);
  CHECK(contour_count(*outline) < contour_count(*dashed));
}
