// stroke_path(): validation, the tolerance budget, and the pipeline flatten -> dash -> outline -> Path.
//
// Tolerance budget (user units): the outline's filled area stays within `tolerance` of the exact stroke.
//  - curves are flattened within tolerance/2: the polyline's swept area is then within tolerance/2 of the
//    curve's (the Hausdorff distance of two sets is not increased by adding the same disc to both);
//  - round joins and caps are polygons within tolerance/2 of their arcs (vertices on the circle): their
//    centres are polyline vertices, on the curve, or dash ends inside a chord, within tolerance/2 of it, so
//    they stay within tolerance (tolerance/4 before: 22 segments per half circle at h = 10, tolerance 0.1,
//    now 16; Cairo's pen has 12 there);
//  - the true tangent turns by at most Δ = sqrt(2·tolerance/h) along a chord (h = width/2), so the offset
//    chords between two normal segments fall short of the offset curves by at most h·Δ²/8 = tolerance/4
//    beyond the flattening error (stroker_flatten.cpp); caps, dash ends and corners sit on true normals.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/stroke.h"
#include "dash_contours.h"
#include "stroke_contour.h"
#include "stroke_outline.h"
#include "stroke_reach.h"

namespace curvescan {

double stroke_user_tolerance(const Affine& transform, double device_tolerance) noexcept {
  // Largest singular value of [[a c], [b d]] in closed form: (|(a+d, b-c)| + |(a-d, b+c)|) / 2.
  const double sigma_max = 0.5 * (std::hypot(transform.a + transform.d, transform.b - transform.c) +
                                  std::hypot(transform.a - transform.d, transform.b + transform.c));
  return device_tolerance / sigma_max;
}

Result<Path> stroke_path(const Path& path, const StrokeStyle& style, double tolerance) {
  return stroke_path(path, style, tolerance, kMaxStrokeOutlinePoints);
}

namespace {

Result<Path> stroke_path_culled(const Path& path, const StrokeStyle& style, double tolerance,
                                std::int64_t max_outline_points, const std::optional<Rect>& visible) {
  if (!(std::isfinite(style.width) && style.width >= 0.0)) {
    return Error{ErrorKind::kInvalidArgument,
                 "the stroke width must be a finite number >= 0, not " + std::to_string(style.width)};
  }
  if (!(std::isfinite(style.miter_limit) && style.miter_limit >= 1.0)) {
    return Error{ErrorKind::kInvalidArgument, "the miter limit must be a finite number >= 1 (SVG 2), not " +
                                                  std::to_string(style.miter_limit)};
  }
  if (!(std::isfinite(tolerance) && tolerance > 0.0)) {
    return Error{ErrorKind::kInvalidArgument, "the stroke tolerance must be a finite positive number"};
  }
  CURVESCAN_PROPAGATE(validate_dash(style.dash_array, style.dash_offset));
  if (max_outline_points < 0) {
    return Error{ErrorKind::kInvalidArgument, "the stroke outline budget must be >= 0, not " +
                                                  std::to_string(max_outline_points)};
  }
  if (style.width == 0.0 || path.empty()) return Path();
  const auto budget = static_cast<std::size_t>(max_outline_points);
  const auto over_budget = [max_outline_points] {
    return Error{ErrorKind::kLimitExceeded, "the stroke outline would have more than " +
                                                std::to_string(max_outline_points) +
                                                " points, the stroke outline budget (tolerance too fine for the "
                                                "path's size or width)"};
  };

  const double half_width = 0.5 * style.width;
  // Cut curves so that the tangent turns by at most sqrt(2·tolerance/h) along a chord (capped at π/4:
  // the pieces between normal segments stay far from degenerate); pieces shorter than tolerance/4 are not
  // cut further (cusps: the outline gives them a disc, within tolerance/8 of the cusp's round cap).
  detail::StrokeCurveCuts cuts;
  cuts.max_turn = std::min(std::sqrt(2.0 * tolerance / half_width), std::numbers::pi / 4);
  cuts.min_piece_length = 0.25 * tolerance;
  // Moving a control point by d onto the end point moves the curve by at most d (its Bernstein weight is
  // below 1): at tolerance/64 the path moves by less than a sixtieth of the tolerance. At the default
  // tolerance that is 1/256 px, the step of Cairo's 24.8 fixed-point coordinates, which merge such points.
  cuts.coincident_length = tolerance / 64.0;
  // Every vertex puts at least one point on each side of the outline.
  cuts.max_vertices = budget / 2;
  // Dash ends inside chords are cut on the curve with its exact tangent (dasher.cpp).
  cuts.keep_pieces = dash_is_active(style.dash_array);
  std::vector<detail::FlatContour> flat;
  CURVESCAN_PROPAGATE(detail::flatten_for_stroke(path, 0.5 * tolerance, cuts, flat));
  if (dash_is_active(style.dash_array)) {
    std::vector<detail::FlatContour> dashes;
    // Dashes are made only where the outline can reach the visible box (stroke_reach.h).
    std::optional<Rect> cull;
    if (visible && visible->is_finite()) cull = detail::dash_cull_box(*visible, style, tolerance);
    if (cull && !cull->is_finite()) cull.reset();
    CURVESCAN_PROPAGATE(detail::dash_contours(flat, style.dash_array, style.dash_offset, dashes, cull));
    flat = std::move(dashes);
  }

  detail::OutlineParams params;
  params.half_width = half_width;
  params.join = style.join;
  params.cap = style.cap;
  params.miter_limit = style.miter_limit;
  params.arc_tolerance = 0.5 * tolerance;  // see the budget above
  detail::Polygons polygons;
  params.max_points = budget;
  if (!detail::append_outlines(flat, params, polygons)) return over_budget();

  PathBuilder builder;
  std::size_t begin = 0;
  for (const std::size_t end : polygons.ends) {
    if (end - begin >= 2) builder.polygon(std::span(polygons.points).subspan(begin, end - begin));
    begin = end;
  }
  Result<Path> outline = std::move(builder).build();
  if (!outline) {
    return Error{ErrorKind::kLimitExceeded,
                 "the stroke outline does not fit in double precision (width or coordinates too large): " +
                     outline.error().message};
  }
  return outline;
}

}  // namespace

Result<Path> stroke_path(const Path& path, const StrokeStyle& style, double tolerance,
                         std::int64_t max_outline_points) {
  return stroke_path_culled(path, style, tolerance, max_outline_points, std::nullopt);
}

Result<Path> stroke_path(const Path& path, const StrokeStyle& style, double tolerance,
                         std::int64_t max_outline_points, const Rect& visible) {
  return stroke_path_culled(path, style, tolerance, max_outline_points, visible);
}

}  // namespace curvescan
