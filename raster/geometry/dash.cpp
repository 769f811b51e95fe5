// Dashing (stroke.h): validation of SVG dash properties and dash_path(), the dasher (dasher.cpp) for callers.
#include "curvescan/raster/stroke.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "curvescan/raster/path_builder.h"
#include "dash_contours.h"
#include "stroke_contour.h"

namespace curvescan {

Status validate_dash(std::span<const double> dash_array, double dash_offset) {
  for (std::size_t i = 0; i < dash_array.size(); ++i) {
    if (!(std::isfinite(dash_array[i]) && dash_array[i] >= 0.0)) {
      return Status::invalid("dash array entry " + std::to_string(i) + " is " + std::to_string(dash_array[i]) +
                             ": dash lengths must be finite and >= 0 (SVG 2 makes such a dash array invalid, "
                             "which renders as a solid stroke)");
    }
  }
  if (!std::isfinite(dash_offset)) return Status::invalid("the dash offset must be a finite number");
  return Status::ok();
}

bool dash_is_active(std::span<const double> dash_array) noexcept {
  return std::any_of(dash_array.begin(), dash_array.end(), [](double l) { return l > 0.0; });
}

Result<Path> dash_path(const Path& path, std::span<const double> dash_array, double dash_offset,
                       double tolerance) {
  CURVESCAN_PROPAGATE(validate_dash(dash_array, dash_offset));
  if (!(std::isfinite(tolerance) && tolerance > 0.0)) {
    return Error{ErrorKind::kInvalidArgument, "the dash tolerance must be a finite positive number"};
  }
  std::vector<detail::FlatContour> flat;
  // Cuts at π/8 so that the vertices' tangents (which the dasher's arc-length correction uses) are exact
  // at the cuts and interpolated within narrow pieces only.
  detail::StrokeCurveCuts cuts;
  cuts.max_turn = std::numbers::pi / 8;
  cuts.min_piece_length = 0.5 * tolerance;
  CURVESCAN_PROPAGATE(detail::flatten_for_stroke(path, tolerance, cuts, flat));
  std::vector<detail::FlatContour> dashes;
  if (dash_is_active(dash_array)) {
    CURVESCAN_PROPAGATE(detail::dash_contours(flat, dash_array, dash_offset, dashes, std::nullopt));
  } else {
    dashes = std::move(flat);
  }
  PathBuilder builder;
  for (const detail::FlatContour& dash : dashes) {
    builder.move_to(dash.vertices.front().point);
    if (dash.vertices.size() == 1) builder.line_to(dash.vertices.front().point);  // a zero-length dash
    for (std::size_t i = 1; i < dash.vertices.size(); ++i) builder.line_to(dash.vertices[i].point);
    if (dash.closed) builder.close();
  }
  return std::move(builder).build();
}

}  // namespace curvescan
