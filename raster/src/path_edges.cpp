// Path -> edges. Each segment goes through flatten_bezier or flatten_rational, whose polyline ends exactly
// at the segment's end point (flatten.h), so consecutive segments share their joints and each contour's
// edges form a closed loop: the winding number is then well defined everywhere (the rasterizer needs
// nothing else). A fill closes every contour; an explicit kClose adds the same closing edge.
#include "path_edges.h"

#include "curvescan/curves/flatten.h"

namespace curvescan::detail {
namespace {

// Walks one segment's polyline from `from`; if the flattener refused (which the Path Guarantees rule out,
// short of overflow inside it), a straight edge to the segment's end keeps the contour closed.
void add_polyline(Point from, Point end, FlattenOutcome outcome, const std::vector<Point>& polyline,
                  Rasterizer& rasterizer) {
  Point current = from;
  if (outcome == FlattenOutcome::kOk || outcome == FlattenOutcome::kSegmentLimit) {
    for (const Point p : polyline) {
      rasterizer.add_line(current, p);
      current = p;
    }
  }
  if (current != end) rasterizer.add_line(current, end);
}

}  // namespace

void add_path_edges(const Path& path, double tolerance, Rasterizer& rasterizer,
                    std::vector<Point>& polyline) {
  Point contour_start;
  Point current;
  for (const PathElement& element : path) {
    switch (element.verb) {
      case PathVerb::kMove:
        if (current != contour_start) rasterizer.add_line(current, contour_start);  // implicit close
        contour_start = current = element.start;
        break;
      case PathVerb::kLine:
      case PathVerb::kClose:
        if (element.start != element.end) rasterizer.add_line(element.start, element.end);
        current = element.end;
        break;
      case PathVerb::kQuad:
      case PathVerb::kCubic:
      case PathVerb::kBezier:
      case PathVerb::kConic:
      case PathVerb::kRationalBezier: {
        polyline.clear();
        const FlattenOutcome outcome =
            element.is_rational() ? flatten_rational(element.points, element.weights, tolerance, polyline)
                                  : flatten_bezier(element.points, tolerance, polyline);
        add_polyline(element.start, element.end, outcome, polyline, rasterizer);
        current = element.end;
        break;
      }
    }
  }
  if (current != contour_start) rasterizer.add_line(current, contour_start);
}

}  // namespace curvescan::detail
