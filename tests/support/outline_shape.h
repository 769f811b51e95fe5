// Test support: a stroke's outline as the polygon contours the oracle tests hand the rasterizer.
#pragma once

#include <catch2/catch.hpp>

#include "coverage_mask.h"
#include "curvescan/raster/stroke.h"

namespace curvescan::testing {

/// The stroke outline of `path` as polygon contours (stroke_path returns kMove, kLine and kClose only).
inline Shape outline_shape(const Path& path, const StrokeStyle& style) {
  const Result<Path> outline = stroke_path(path, style, 0.1);
  REQUIRE(outline);
  Shape shape;
  for (const PathElement& e : *outline) {
    if (e.verb == PathVerb::kMove) {
      shape.emplace_back().push_back(e.start);
    } else if (e.verb == PathVerb::kLine) {
      REQUIRE(!shape.empty());
      shape.back().push_back(e.end);
    } else {
      REQUIRE(e.verb == PathVerb::kClose);  // closing back to the start: add_shape closes every contour
    }
  }
  return shape;
}

}  // namespace curvescan::testing
