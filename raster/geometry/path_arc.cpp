// PathBuilder::arc: an ellipse arc in centre form, appended as the exact conics of curves/arc.h.
#include <cmath>
#include <vector>

#include "curvescan/curves/arc.h"
#include "curvescan/raster/path_builder.h"

namespace curvescan {

PathBuilder& PathBuilder::arc(Point center, double rx, double ry, double x_rotation, double start_angle,
                              double sweep_angle) {
  constexpr const char* kName = "arc";
  if (!begin_command()) return *this;
  const double parameters[] = {center.x, center.y, rx, ry, x_rotation, start_angle, sweep_angle};
  for (const double value : parameters) {
    if (!std::isfinite(value)) {
      fail(kName, ErrorKind::kInvalidArgument, "the centre, radii and angles must be finite");
      return *this;
    }
  }
  // The start point by the same construction as the conics (translate·rotate·scale of the unit circle,
  // arc.h), so that the joining line meets the first conic's start.
  const std::vector<RationalBezier> conics =
      elliptical_arc_conics(center, rx, ry, x_rotation, start_angle, sweep_angle);
  const double cs = std::cos(x_rotation), sn = std::sin(x_rotation);
  const double ux = rx * std::cos(start_angle), uy = ry * std::sin(start_angle);
  const Point start = conics.empty() ? Point{center.x + cs * ux - sn * uy, center.y + sn * ux + cs * uy}
                                     : conics.front().points().front();
  if (!start.is_finite()) {
    fail(kName, ErrorKind::kInvalidArgument, "the arc's points overflow the finite range");
    return *this;
  }
  // cairo_arc semantics: join the current point to the arc start with a line, or start a contour there.
  if (!current_) {
    pending_move_ = start;
    current_ = start;
  } else if (*current_ != start) {
    if (!ensure_contour(kName)) return *this;
    push_segment(PathVerb::kLine, {&start, 1}, {});
  }
  for (const RationalBezier& conic : conics) {
    const std::span<const Point> points = conic.points().subspan(1);
    if (!check_points(kName, points) || !ensure_contour(kName)) return *this;
    push_segment(PathVerb::kConic, points, conic.weights());
  }
  return *this;
}

}  // namespace curvescan
