// Views of 3D space (view_transform.h): the look-at camera and the exact projection of cubics.
#include "curvescan/curves/view_transform.h"

#include <cmath>

namespace curvescan {
namespace {

struct V3 {
  double x, y, z;
};
V3 sub(const Point3& a, const Point3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
V3 cross(V3 a, V3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dot(V3 a, V3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
std::optional<V3> normalized(V3 a) {
  const double length = std::sqrt(dot(a, a));
  if (!(length > 0) || !std::isfinite(length)) return std::nullopt;
  return V3{a.x / length, a.y / length, a.z / length};
}
bool finite(const Point3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

}  // namespace

Result<ViewTransform> ViewTransform::look_at(const Camera& camera) {
  if (!finite(camera.eye) || !finite(camera.target) || !finite(camera.up) ||
      !std::isfinite(camera.centre.x) || !std::isfinite(camera.centre.y)) {
    return Error{ErrorKind::kInvalidArgument, "the camera's eye, target, up and centre must be finite"};
  }
  const std::optional<V3> forward = normalized(sub(camera.target, camera.eye));
  if (!forward) return Error{ErrorKind::kInvalidArgument, "the camera's eye and target must differ"};
  const std::optional<V3> right = normalized(cross(*forward, sub(camera.up, Point3{})));
  if (!right) {
    return Error{ErrorKind::kInvalidArgument, "the camera's up must not be parallel to the line of sight"};
  }
  const V3 up = cross(*right, *forward);
  const V3 eye{camera.eye.x, camera.eye.y, camera.eye.z};
  // Camera coordinates: lateral r·(p − eye), vertical u·(p − eye), depth f·(p − eye).
  auto row = [&](V3 axis) { return std::array<double, 4>{axis.x, axis.y, axis.z, -dot(axis, eye)}; };
  const std::array<double, 4> lateral = row(*right), vertical = row(up), depth = row(*forward);
  ViewTransform view;
  if (camera.focal) {
    const double focal = *camera.focal;
    if (!(focal > 0) || !std::isfinite(focal))
      return Error{ErrorKind::kInvalidArgument, "'focal' must be a positive number"};
    // X = focal · lateral + cx · depth, Y = −focal · vertical + cy · depth, W = depth.
    for (int k = 0; k < 4; ++k) {
      view.rows[0][k] = focal * lateral[k] + camera.centre.x * depth[k];
      view.rows[1][k] = -focal * vertical[k] + camera.centre.y * depth[k];
      view.rows[2][k] = depth[k];
    }
    return view;
  }
  if (!(camera.scale > 0) || !std::isfinite(camera.scale)) {
    return Error{ErrorKind::kInvalidArgument, "'scale' must be a positive number"};
  }
  for (int k = 0; k < 4; ++k) {
    view.rows[0][k] = camera.scale * lateral[k];
    view.rows[1][k] = -camera.scale * vertical[k];
    view.rows[2][k] = 0.0;
  }
  view.rows[0][3] += camera.centre.x;
  view.rows[1][3] += camera.centre.y;
  view.rows[2][3] = 1.0;
  return view;
}

std::array<double, 3> ViewTransform::apply(const Point3& p) const noexcept {
  std::array<double, 3> h{};
  for (int r = 0; r < 3; ++r) h[r] = rows[r][0] * p.x + rows[r][1] * p.y + rows[r][2] * p.z + rows[r][3];
  return h;
}

Point ViewTransform::project(const Point3& p) const noexcept {
  const std::array<double, 3> h = apply(p);
  return {h[0] / h[2], h[1] / h[2]};
}

bool ProjectedCubic::is_rational() const noexcept {
  return !(weights[0] == weights[1] && weights[1] == weights[2] && weights[2] == weights[3]);
}

Result<ProjectedCubic> project_cubic(const std::array<Point3, 4>& ctrl, const ViewTransform& view) {
  ProjectedCubic cubic;
  for (int j = 0; j < 4; ++j) {
    const std::array<double, 3> h = view.apply(ctrl[j]);
    if (!(h[2] > 0) || !std::isfinite(h[0]) || !std::isfinite(h[1]) || !std::isfinite(h[2])) {
      return Error{
          ErrorKind::kInvalidArgument,
          "a control point is at or behind the eye (or the view's numbers overflow): the projection would "
          "pass through infinity"};
    }
    cubic.points[j] = {h[0] / h[2], h[1] / h[2]};
    cubic.weights[j] = h[2];
    if (!std::isfinite(cubic.points[j].x) || !std::isfinite(cubic.points[j].y)) {
      return Error{ErrorKind::kInvalidArgument, "a projected control point is not finite"};
    }
  }
  return cubic;
}

}  // namespace curvescan
