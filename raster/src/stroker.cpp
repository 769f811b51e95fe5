// stroke_path(): validation, the tolerance budget, and the pipeline flatten -> dash -> outline -> Path.
//
// Tolerance budget (user units): the outline's filled area stays within `tolerance` of the exact stroke.
//  - curves are flattened within tolerance/2: the polyline's swept area is then within tolerance/2 of the
//    curve's (the Hausdorff distance of two sets is not increased by adding the same disc to both);
//  - round joins and caps are polygons within tolerance/4 of their arcs;
//  - chords within 4h of a segment end (h = width/2) lean at most tolerance/(4·h) from the true tangent,
//    so a piece pokes at most h·sin(angle) <= tolerance/4 past a cap's or join's normal line.
#include "curvescan/raster/stroke.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "curvescan/raster/dash.h"
#include "curvescan/raster/path_builder.h"
#include "dash_contours.h"
#include "stroke_contour.h"
#include "stroke_outline.h"

namespace curvescan {

double stroke_user_tolerance(const Affine& transform, double device_tolerance) noexcept {
  // Largest singular value of [[a c], [b d]] in closed form: (|(a+d, b-c)| + |(a-d, b+c)|) / 2.
  const double sigma_max = 0.5 * (std::hypot(transform.a + transform.d, transform.b - transform.c) +
                                  std::hypot(transform.a - transform.d, transform.b + transform.c));
  return device_tolerance / sigma_max;
}

Result<Path> stroke_path(const Path& path, const StrokeStyle& style, double tolerance) {
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
  if (style.width == 0.0 || path.empty()) return Path();

  const double half_width = 0.5 * style.width;
  // Refine curve ends only where the stroke is bounded by a normal line (stroker_flatten.cpp): butt and
  // square caps, miter and bevel corners. Round ones are parts of the Minkowski sum of the path and the
  // pen, which contains every piece of the outline whatever the chords' directions.
  detail::StrokeEndRefinement refinement;
  refinement.angle = std::min(0.25 * tolerance / half_width, std::numbers::pi / 2);
  refinement.region = 4.0 * half_width;
  refinement.caps = style.cap != LineCap::kRound;
  refinement.corners = style.join != LineJoin::kRound;
  // Dash ends inside curves are not refined (refinement.whole): on thick strokes the cost (thousands of
  // pieces per curve) stalls the rasterizer. Their caps follow the chord: off by up to h·(chord turn)/2.
  std::vector<detail::FlatContour> flat;
  CURVESCAN_PROPAGATE(detail::flatten_for_stroke(path, 0.5 * tolerance, refinement, flat));
  if (dash_is_active(style.dash_array)) {
    std::vector<detail::FlatContour> dashes;
    CURVESCAN_PROPAGATE(detail::dash_contours(flat, style.dash_array, style.dash_offset, dashes));
    flat = std::move(dashes);
  }

  detail::OutlineParams params;
  params.half_width = half_width;
  params.join = style.join;
  params.cap = style.cap;
  params.miter_limit = style.miter_limit;
  params.arc_tolerance = 0.25 * tolerance;
  params.inner_slack = 0.25 * tolerance;
  detail::Polygons polygons;
  detail::append_outlines(flat, params, polygons);

  PathBuilder builder;
  std::size_t begin = 0;
  for (const std::size_t end : polygons.ends) {
    if (end - begin >= 2) {
      builder.move_to(polygons.points[begin]);
      for (std::size_t i = begin + 1; i < end; ++i) builder.line_to(polygons.points[i]);
      builder.close();
    }
    begin = end;
  }
  Result<Path> outline = builder.build();
  if (!outline) {
    return Error{ErrorKind::kLimitExceeded,
                 "the stroke outline does not fit in double precision (width or coordinates too large): " +
                     outline.error().message};
  }
  return outline;
}

}  // namespace curvescan
