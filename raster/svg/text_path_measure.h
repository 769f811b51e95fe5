// Distance along a <textPath>'s path (SVG 1.1 10.13, SVG 2 11.8.3 step 8 "position on path"): the path
// flattened once into a polyline within a tolerance far below a glyph's size, its cumulative arc length,
// and the point and unit tangent at any distance — what placing a glyph by its midpoint needs.
#pragma once

#include <optional>
#include <vector>

#include "curvescan/curves/point.h"
#include "curvescan/raster/path.h"

namespace curvescan::svg::detail {

/// Most polyline vertices one path is flattened into (each 24 bytes with its length): beyond, the rest of
/// the path is not followed, and glyphs past its end are hidden as for any path.
inline constexpr std::size_t kMaxPathMeasurePoints = std::size_t{1} << 20;

class PathMeasure {
 public:
  /// The subpaths of `path` joined end to end in order (SVG 1.1 10.13: a textPath follows the path's
  /// subpaths in sequence; the gap of a move is not part of the length), flattened within `tolerance`
  /// user units. `reverse` walks the path from its end (SVG 2 side="right"). nullopt for a path of zero
  /// length.
  [[nodiscard]] static std::optional<PathMeasure> measure(const Path& path, double tolerance, bool reverse);

  [[nodiscard]] double length() const noexcept { return lengths_.back(); }
  [[nodiscard]] bool closed() const noexcept { return closed_; }

  struct Sample {
    Point point;
    Vec2 tangent;  ///< unit length, in the direction of travel
  };
  /// The point at `distance` from the start, clamped into [0, length()]. Logarithmic in the vertices.
  [[nodiscard]] Sample at(double distance) const noexcept;
  /// As at(), with the tangent turning continuously: blended between the tangents of neighbouring segments
  /// of the polyline from one segment's middle to the next one's (the bisector at a vertex), as the tangent
  /// of the curve the polyline stands for turns. What bending a glyph along the path needs (textPath
  /// method="stretch"): at() keeps one tangent along a whole segment, which would bend a glyph only where
  /// it crosses a vertex.
  [[nodiscard]] Sample at_smooth(double distance) const noexcept;

 private:
  std::vector<Point> points_;    // the polyline; a move starts a new piece of zero-length joint
  std::vector<double> lengths_;  // cumulative length at each point
  std::vector<bool> starts_piece_;
  bool closed_ = false;

  // The index of the segment (its end point) at `distance`, skipping joints and zero-length segments.
  [[nodiscard]] std::size_t segment_at(double distance) const noexcept;
  // The unit direction of segment `end`, or nothing for a joint or a zero-length segment.
  [[nodiscard]] std::optional<Vec2> direction(std::size_t end) const noexcept;
};

}  // namespace curvescan::svg::detail
