// Test support for the stroke tests: a stroke's outline rendered to an 8-bit coverage mask, and paths
// written compactly.
#pragma once

#include <catch2/catch.hpp>

#include <initializer_list>

#include "coverage_mask.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/stroke.h"

namespace curvescan::testing {

/// Adds every line of a polygonal path (stroke_path() output: kMove, kLine, kClose) to `rasterizer`.
inline void add_polygon_path(Rasterizer& rasterizer, const Path& path) {
  for (const PathElement& element : path) {
    if (element.verb == PathVerb::kMove) continue;
    REQUIRE((element.verb == PathVerb::kLine || element.verb == PathVerb::kClose));
    rasterizer.add_line(element.start, element.end);
  }
}

/// The outline of `path` under `style`, mapped by `transform` and filled nonzero, as a width x height
/// coverage mask; the device tolerance is `tolerance` pixels.
inline CoverageMask render_stroke(const Path& path, const StrokeStyle& style, int width, int height,
                                  double tolerance = 0.05, const Affine& transform = Affine::identity()) {
  const Result<Path> outline = stroke_path(path, style, stroke_user_tolerance(transform, tolerance));
  REQUIRE(outline.is_ok());
  const Result<Path> device = outline->transformed(transform);
  REQUIRE(device.is_ok());
  CoverageMask mask(width, height);
  Rasterizer rasterizer(IntRect{0, 0, width, height});
  add_polygon_path(rasterizer, *device);
  MaskSink sink(mask);
  rasterizer.rasterize(FillRule::kNonZero, Antialias::kExact, sink);
  CHECK(sink.violations == 0);
  return mask;
}

inline Path polyline_path(std::initializer_list<Point> points, bool closed = false) {
  PathBuilder builder;
  bool first = true;
  for (const Point p : points) {
    if (first) builder.move_to(p); else builder.line_to(p);
    first = false;
  }
  if (closed) builder.close();
  Result<Path> path = builder.build();
  REQUIRE(path.is_ok());
  return *path;
}

}  // namespace curvescan::testing
