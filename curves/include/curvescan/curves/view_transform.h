// Views of 3D space onto the plane: a 3×4 projective matrix taking (x, y, z, 1) to homogeneous (X, Y, W),
// the plane point (X / W, Y / W). A parallel (orthographic) view has W = 1; a perspective view has W the
// depth in front of the eye. Used to draw Bézier surface patches (bezier_patch.h).
#pragma once

#include <array>
#include <optional>

#include "curvescan/curves/bezier_patch.h"
#include "curvescan/curves/point.h"
#include "curvescan/status.h"

namespace curvescan {

/// A camera looking from `eye` at `target` with `up` towards the top of the picture. The picture's y axis
/// points down (as in SVG and images), its origin is `centre`.
struct Camera {
  Point3 eye;
  Point3 target;
  Point3 up{0, 0, 1};
  /// Perspective: plane units per unit of (lateral offset / depth). Absent: orthographic.
  std::optional<double> focal;
  double scale = 1.0;  ///< orthographic: plane units per unit of space
  Point centre{0, 0};
};

/// A 3×4 projective matrix, rows (X, Y, W).
struct ViewTransform {
  std::array<std::array<double, 4>, 3> rows{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}};

  /// The view of `camera`; fails if eye == target, up is parallel to the line of sight, or a number is
  /// not finite or not positive where it must be.
  static Result<ViewTransform> look_at(const Camera& camera);

  /// Homogeneous image (X, Y, W) of p.
  [[nodiscard]] std::array<double, 3> apply(const Point3& p) const noexcept;
  /// The plane point of p (W may be <= 0 behind the eye: the caller checks).
  [[nodiscard]] Point project(const Point3& p) const noexcept;
};

/// A projected cubic: plane control points and weights (all 1 for an orthographic view).
struct ProjectedCubic {
  std::array<Point, 4> points;
  std::array<double, 4> weights;
  [[nodiscard]] bool is_rational() const noexcept;
};

/// The exact projection of the 3D cubic `ctrl` (bezier_patch.h). Fails when a control point's W is not
/// positive (at or behind the eye: the projection would pass through infinity) or not finite.
Result<ProjectedCubic> project_cubic(const std::array<Point3, 4>& ctrl, const ViewTransform& view);

}  // namespace curvescan
