// SVG endpoint arcs: the conversion to centre form of SVG 1.1 appendix F.6.5, with the out-of-range radii
// correction of F.6.6, and PathBuilder::svg_arc_to, which appends the result as exact conics.
//
// Notation follows the spec: (x1, y1) = from, (x2, y2) = to, φ = x_rotation, fA = large_arc, fS = sweep.
// Step 1 moves the midpoint of the chord to the origin and unrotates: (x1', y1'). Step 2 finds the centre
// (cx', cy') on the side chosen by fA != fS. Step 3 rotates and translates it back. Step 4 takes the start
// angle θ1 and the sweep Δθ as angles between vectors, Δθ adjusted to the sign fS asks for.
#include <cmath>
#include <numbers>
#include <vector>

#include "curvescan/curves/arc.h"
#include "curvescan/raster/path_builder.h"

namespace curvescan {
namespace {

// The signed angle from u to v in (-π, π] (F.6.5.4's formula, by atan2 for accuracy near 0 and π).
double angle_between(Vec2 u, Vec2 v) noexcept {
  return std::atan2(u.cross(v), u.dot(v));
}

}  // namespace

std::optional<SvgArcCenter> svg_arc_center(Point from, Point to, double rx, double ry, double x_rotation,
                                           bool large_arc, bool sweep) noexcept {
  // F.6.2: identical endpoints omit the arc; a zero radius makes it a straight line (the caller's job).
  if (from == to || rx == 0.0 || ry == 0.0) return std::nullopt;
  rx = std::fabs(rx);  // F.6.6 step 1: negative radii are taken as absolute values
  ry = std::fabs(ry);
  const double cs = std::cos(x_rotation), sn = std::sin(x_rotation);

  // F.6.5 step 1 (eq. F.6.5.1).
  const double hx = 0.5 * (from.x - to.x), hy = 0.5 * (from.y - to.y);
  const double x1p = cs * hx + sn * hy;
  const double y1p = -sn * hx + cs * hy;

  // F.6.6 step 3 (eq. F.6.6.2-3): scale the radii up uniformly when the ellipse cannot reach both ends.
  const double lambda = (x1p * x1p) / (rx * rx) + (y1p * y1p) / (ry * ry);
  if (lambda > 1.0) {
    const double grow = std::sqrt(lambda);
    rx *= grow;
    ry *= grow;
  }

  // F.6.5 step 2 (eq. F.6.5.2). The radicand is 0 in exact arithmetic after the scaling above; rounding
  // can make it slightly negative, which must mean "centre at the chord midpoint", hence the clamp.
  const double rx2 = rx * rx, ry2 = ry * ry;
  const double numerator = rx2 * ry2 - rx2 * y1p * y1p - ry2 * x1p * x1p;
  const double denominator = rx2 * y1p * y1p + ry2 * x1p * x1p;
  double coefficient = std::sqrt(std::fmax(0.0, numerator / denominator));
  if (large_arc == sweep) coefficient = -coefficient;
  const double cxp = coefficient * rx * y1p / ry;
  const double cyp = -coefficient * ry * x1p / rx;

  // F.6.5 step 3 (eq. F.6.5.3).
  SvgArcCenter arc;
  arc.center = {cs * cxp - sn * cyp + 0.5 * (from.x + to.x), sn * cxp + cs * cyp + 0.5 * (from.y + to.y)};
  arc.rx = rx;
  arc.ry = ry;

  // F.6.5 step 4 (eq. F.6.5.5-6).
  const Vec2 u{(x1p - cxp) / rx, (y1p - cyp) / ry};
  const Vec2 v{(-x1p - cxp) / rx, (-y1p - cyp) / ry};
  arc.start_angle = angle_between({1.0, 0.0}, u);
  double delta = angle_between(u, v);
  if (!sweep && delta > 0.0) delta -= 2.0 * std::numbers::pi;
  if (sweep && delta < 0.0) delta += 2.0 * std::numbers::pi;
  arc.sweep_angle = delta;
  return arc;
}

PathBuilder& PathBuilder::svg_arc_to(double rx, double ry, double x_rotation, bool large_arc, bool sweep,
                                     Point to) {
  constexpr const char* kName = "svg_arc_to";
  if (!begin_command() || !check_points(kName, {&to, 1})) return *this;
  if (!std::isfinite(rx) || !std::isfinite(ry) || !std::isfinite(x_rotation)) {
    fail(kName, ErrorKind::kInvalidArgument, "the radii and rotation must be finite");
    return *this;
  }
  if (current_ && *current_ == to) return *this;  // F.6.2: the arc is omitted (and adds no contour)
  if (!ensure_contour(kName)) return *this;
  const Point from = *current_;
  const std::optional<SvgArcCenter> arc = svg_arc_center(from, to, rx, ry, x_rotation, large_arc, sweep);
  if (!arc) {  // F.6.2: a zero radius makes the arc a straight line
    push_segment(PathVerb::kLine, {&to, 1}, {});
    return *this;
  }
  const std::vector<RationalBezier> conics =
      elliptical_arc_conics(arc->center, arc->rx, arc->ry, x_rotation, arc->start_angle, arc->sweep_angle);
  for (std::size_t i = 0; i < conics.size(); ++i) {
    // Each conic starts where the previous one ended (arc.h), and the first at `from` up to rounding: the
    // path keeps `from` as the start. The last ends exactly at `to`, as the SVG command says.
    Point control_and_end[] = {conics[i].points()[1], conics[i].points()[2]};
    if (i + 1 == conics.size()) control_and_end[1] = to;
    if (!check_points(kName, control_and_end)) return *this;
    push_segment(PathVerb::kConic, control_and_end, conics[i].weights());
  }
  return *this;
}

}  // namespace curvescan
