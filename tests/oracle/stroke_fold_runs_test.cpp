// Fold runs against the swept-area reference: seeded random cubics with tight bends, stroked much wider
// than their radius of curvature (the normals cross along runs of chords, which stroker_outline.cpp sums
// into one polygon per run). Bounds: the fill oracle's (MaskComparison::within_bounds). Cairo is not the
// oracle here (not strongly correct where the offsets fold: Nehab 2020 §2).
#include <catch2/catch.hpp>
#include <random>

#include "stroke_scene.h"

using namespace curvescan;
using namespace curvescan::testing;

TEST_CASE("fold runs: wide strokes on seeded random cubics match the swept reference",
          "[oracle][stroke][fold]") {
  // Tolerance 0.02 px as in the hard cases: far below the 20/255 bound's worth of edge error.
  constexpr double kTolerance = 0.02;
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<double> coordinate(24.0, 104.0);
  std::uniform_real_distribution<double> width(20.0, 70.0);
  const LineJoin joins[] = {LineJoin::kMiter, LineJoin::kRound, LineJoin::kBevel};
  const LineCap caps[] = {LineCap::kButt, LineCap::kRound, LineCap::kSquare};
  for (int i = 0; i < 12; ++i) {
    StrokeScene s;
    s.name = "fold run " + std::to_string(i);
    SceneCommand move{SceneCommand::kMove, {{coordinate(rng), coordinate(rng)}}};
    SceneCommand cubic{SceneCommand::kCubic,
                       {{coordinate(rng), coordinate(rng)},
                        {coordinate(rng), coordinate(rng)},
                        {coordinate(rng), coordinate(rng)}}};
    s.commands = {move, cubic};
    s.style.width = width(rng);
    s.style.join = joins[i % 3];
    s.style.cap = caps[(i / 3) % 3];
    const MaskComparison m = compare_masks(render_scene_curvescan(s, kTolerance), render_scene_reference(s));
    INFO(s.name << " width " << s.style.width << " vs reference: far " << m.far_mismatches << " max "
                << m.max_diff << " mean " << m.mean_diff << " total " << m.total_ours << " vs "
                << m.total_other);
    CHECK(m.within_bounds());
  }
}
