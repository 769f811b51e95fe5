// A fill flattens no curve past the segment budget of its render. Regression:
// fuzz/regressions/raster_stroke/conic_weight_dbl_max_flattened_past_budget_{1,2,3} — a conic from the
// canvas to (DBL_MAX, DBL_MAX) with weights 1, DBL_MAX, 1, filled under a budget of 2^14 segments, was
// flattened to the flattener's own cap of 2^22 segments (add_path_edges checked the budget only between
// path elements, and push_clip() passed none): 26 to 34 s in one fuzz execution, before the fill was refused.
#include <catch2/catch.hpp>
#include <cstdint>
#include <limits>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/rasterizer.h"
#include "scan/path_edges.h"

using namespace curvescan;

namespace {

constexpr std::int64_t kBudget = std::int64_t{1} << 14;  // the raster_stroke fuzz target's

/// The fuzz input's geometry: a small conic on the canvas, an arc of an ellipse 1e-300 thin, then the
/// conic to (DBL_MAX, DBL_MAX) whose middle weight DBL_MAX makes its scaled end weights subnormal (the
/// walk then runs at the coordinates' resolution, where a piece can be at most ~1e-5 of DBL_MAX long).
Path hostile_conic_path() {
  constexpr double kMax = std::numeric_limits<double>::max();
  PathBuilder builder;
  builder.move_to({16, 16});
  builder.conic_to({28.5, 28.5}, {28.5, 28.5}, 13.5);
  builder.arc({28.5, 28.5}, 12.75, 1e-300, 12.5, 12.5, 12.5);
  builder.conic_to({24.25, kMax}, {kMax, kMax}, kMax);
  builder.close();
  Result<Path> path = builder.build();
  REQUIRE(path.is_ok());
  return std::move(path).value();
}

RenderLimits limits_with_budget() {
  RenderLimits limits;
  limits.max_segments = kBudget;
  return limits;
}

TEST_CASE("a fill stops flattening a curve at the render's segment budget", "[raster][limits]") {
  const Path path = hostile_conic_path();
  // What Canvas::fill does with the path: the edges it adds may exceed the budget by the one segment that
  // tells it to refuse, not by a curve's worth (before: 2^22 edges from the one conic).
  Rasterizer rasterizer(IntRect{0, 0, 32, 32});
  std::vector<Point> scratch;
  const auto budget = static_cast<std::size_t>(kBudget);
  const std::size_t edges = detail::add_path_edges(path, 0.25, rasterizer, scratch, budget);
  CHECK(edges > budget);  // the conic needs more than the budget at this tolerance: refused
  CHECK(edges <= budget + 1);
  CHECK(detail::add_path_edges_reference(path, 0.25, rasterizer, scratch, budget) == edges);

  Result<Canvas> canvas = Canvas::create(32, 32, limits_with_budget());
  REQUIRE(canvas.is_ok());
  FillOptions options;
  options.tolerance = 0.25;
  const Status filled =
      canvas->fill(path, Paint::solid({0.1, 0.5, 0.9, 0.7}), FillRule::kNonZero, Affine::identity(), options);
  REQUIRE_FALSE(filled.is_ok());
  CHECK(filled.error().kind == ErrorKind::kLimitExceeded);
  CHECK(canvas->segments_used() == 0);
}

TEST_CASE("push_clip() refuses a clip path that flattens past the whole segment budget", "[raster][limits]") {
  Result<Canvas> canvas = Canvas::create(32, 32, limits_with_budget());
  REQUIRE(canvas.is_ok());
  FillOptions options;
  options.tolerance = 0.25;
  const Status clipped =
      canvas->push_clip(hostile_conic_path(), FillRule::kNonZero, Affine::identity(), options);
  REQUIRE_FALSE(clipped.is_ok());
  CHECK(clipped.error().kind == ErrorKind::kLimitExceeded);
  CHECK(canvas->clip_depth() == 0);
  // A clip within the budget is pushed as before.
  PathBuilder square;
  square.move_to({4, 4}).line_to({28, 4}).line_to({28, 28}).line_to({4, 28}).close();
  REQUIRE(canvas->push_clip(*square.build(), FillRule::kNonZero).is_ok());
  CHECK(canvas->clip_depth() == 1);
}

}  // namespace
