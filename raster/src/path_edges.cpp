// Path -> edges. Each segment goes through flatten_bezier or flatten_rational, whose polyline ends exactly
// at the segment's end point (flatten.h), so consecutive segments share their joints and each contour's
// edges form a closed loop: the winding number is then well defined everywhere (the rasterizer needs
// nothing else). A fill closes every contour; an explicit kClose adds the same closing edge.
#include "path_edges.h"

#include "curve_clip_cull.h"

#include "curvescan/curves/flatten.h"

namespace curvescan::detail {
namespace {

// Walks one segment's polyline from `from`; if the flattener refused (which the Path Guarantees rule out,
// short of overflow inside it), a straight edge to the segment's end keeps the contour closed.
// Returns the number of edges added.
std::size_t add_polyline(Point from, Point end, FlattenOutcome outcome, const std::vector<Point>& polyline,
                         Rasterizer& rasterizer) {
  Point current = from;
  std::size_t edges = 0;
  if (outcome == FlattenOutcome::kOk || outcome == FlattenOutcome::kSegmentLimit) {
    for (const Point p : polyline) {
      rasterizer.add_line(current, p);
      current = p;
    }
    edges = polyline.size();
  }
  if (current != end) {
    rasterizer.add_line(current, end);
    ++edges;
  }
  return edges;
}

}  // namespace

std::size_t add_path_edges(const Path& path, double tolerance, Rasterizer& rasterizer, std::vector<Point>& polyline,
                           std::size_t max_edges) {
  // Only the rasterizer's clip box is ever covered: curves (or halves of huge curves) that miss it are
  // replaced by their chords, exactly (curve_clip_cull.h).
  const IntRect clip = rasterizer.clip();
  const Rect visible_box{static_cast<double>(clip.x0), static_cast<double>(clip.y0), static_cast<double>(clip.x1),
                         static_cast<double>(clip.y1)};
  Point contour_start;
  Point current;
  std::size_t edges = 0;
  for (const PathElement& element : path) {
    if (edges > max_edges) return edges;
    switch (element.verb) {
      case PathVerb::kMove:
        if (current != contour_start) {
          rasterizer.add_line(current, contour_start);  // implicit close
          ++edges;
        }
        contour_start = current = element.start;
        break;
      case PathVerb::kLine:
      case PathVerb::kClose:
        if (element.start != element.end) {
          rasterizer.add_line(element.start, element.end);
          ++edges;
        }
        current = element.end;
        break;
      case PathVerb::kQuad:
      case PathVerb::kCubic:
      case PathVerb::kBezier:
      case PathVerb::kConic:
      case PathVerb::kRationalBezier: {
        polyline.clear();
        // Pieces that cannot be seen become chords (curve_clip_cull.h); the clip box is not readable from
        // the Rasterizer, so the cull uses the box holding every clip.
        const FlattenOutcome outcome = flatten_visible(element, tolerance, visible_box, polyline);
        edges += add_polyline(element.start, element.end, outcome, polyline, rasterizer);
        current = element.end;
        break;
      }
    }
  }
  if (current != contour_start) {
    rasterizer.add_line(current, contour_start);
    ++edges;
  }
  return edges;
}

}  // namespace curvescan::detail
