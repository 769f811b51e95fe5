// Edge clipping in double precision, before any other step of the rasterizer.
//
// A directed line a -> b is cut against the clip box so that what remains is exactly what the pixels
// inside the box can see:
//   - the parts above or below the box are dropped: a horizontal scanline inside the box never meets them;
//   - the part left of the box is kept as a vertical edge on the box's left side, with the same y extent
//     and direction, so the winding number of every pixel right of it is unchanged (the classic trick of
//     FreeType's and Skia's scan converters, done here in double before any rounding);
//   - the part right of the box is dropped: a pixel's winding number only depends on the edges on its left
//     (ray cast to -x), so edges beyond the right side cannot change a pixel inside.
// Horizontal edges are dropped as well: they change no winding number along any horizontal line, and
// contribute zero area to the trapezoid decomposition.
// All arithmetic is in double on the original coordinates, so an edge at ±1e9 px keeps its winding and
// nothing can overflow (no fixed point anywhere).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "curvescan/curves/point.h"
#include "curvescan/raster/rasterizer.h"

namespace curvescan::detail {

/// A clipped edge, oriented top to bottom (y_top < y_bot), with the winding direction it had.
struct ClippedEdge {
  double x_top = 0.0;
  double y_top = 0.0;
  double x_bot = 0.0;
  double y_bot = 0.0;
  double dxdy = 0.0;  ///< (x_bot - x_top) / (y_bot - y_top)
  /// +1 if the original edge went downward (increasing y), -1 if upward. One byte, beside linked_above:
  /// the edge is 48 bytes instead of 56, and every pass of a fill reads all of them (a polygon of 10^6
  /// edges is 48 MB, past the caches: docs/benchmarks.md).
  std::int8_t dir = 0;
  /// Whether some edge continues into this one from above; and the edge that continues this one below
  /// (same direction, starting exactly at (x_bot, y_bot)), or kNoEdge. Set by the rasterizer before a
  /// scan (links between consecutive add_line calls), so that the joints of a finely flattened curve do
  /// not cut the rows into bands.
  bool linked_above = false;
  std::uint32_t below = kNoEdge;

  static constexpr std::uint32_t kNoEdge = 0xffffffffu;

  /// x of the edge's line at height y, clamped to the edge's y range; exact at both ends so that the
  /// edges of a contour still meet at the same points after clipping.
  [[nodiscard]] double x_at(double y) const noexcept {
    if (y <= y_top) return x_top;
    if (y >= y_bot) return x_bot;
    return x_top + (y - y_top) * dxdy;
  }
};

/// Appends to `out` the pieces of a -> b that can affect pixels of `clip` (0 to 3 pieces), in the order
/// they are travelled from a to b.
/// Non-finite input (NaN, inf) is dropped: it cannot bound an area.
void clip_edge(Point a, Point b, IntRect clip, std::vector<ClippedEdge>& out);

/// clip_edge on every edge points[i] -> points[i + 1] of the open polyline `points`, in order: the same
/// pieces in the same order. Faster for the common case of a polyline inside the clip box (a glyph
/// inside its mask): each vertex is tested against the box once, an edge with both ends inside is built
/// directly (clip_edge's own first case, the same arithmetic), and `out` grows once per call, not per edge.
void clip_polyline(std::span<const Point> points, IntRect clip, std::vector<ClippedEdge>& out);

}  // namespace curvescan::detail
