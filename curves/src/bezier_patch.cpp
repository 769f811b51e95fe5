// Bicubic Bézier patches (bezier_patch.h): de Casteljau in 3D, rows then columns.
#include "curvescan/curves/bezier_patch.h"

namespace curvescan {
namespace {

Point3 lerp(const Point3& a, const Point3& b, double t) noexcept {
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t};
}

}  // namespace

Point3 de_casteljau_3d(const std::array<Point3, 4>& ctrl, double t) noexcept {
  std::array<Point3, 4> p = ctrl;
  for (int level = 3; level > 0; --level) {
    for (int k = 0; k < level; ++k) p[k] = lerp(p[k], p[k + 1], t);
  }
  return p[0];
}

std::array<Point3, 4> BezierPatch::curve_at_u(double u) const noexcept {
  std::array<Point3, 4> result;
  for (int j = 0; j < 4; ++j) {
    result[j] = de_casteljau_3d({points[j], points[4 + j], points[8 + j], points[12 + j]}, u);
  }
  return result;
}

std::array<Point3, 4> BezierPatch::curve_at_v(double v) const noexcept {
  std::array<Point3, 4> result;
  for (int i = 0; i < 4; ++i) {
    result[i] = de_casteljau_3d({points[4 * i], points[4 * i + 1], points[4 * i + 2], points[4 * i + 3]}, v);
  }
  return result;
}

Point3 BezierPatch::eval(double u, double v) const noexcept {
  return de_casteljau_3d(curve_at_u(u), v);
}

}  // namespace curvescan
