// bezier_patch and view_transform: projected isoparametric curves against the surface evaluated directly
// (de Casteljau in 3D, then projected).
#include "curvescan/curves/bezier_patch.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "curvescan/curves/rational_bezier.h"
#include "curvescan/curves/view_transform.h"

using curvescan::BezierPatch;
using curvescan::Camera;
using curvescan::Point;
using curvescan::Point3;
using curvescan::ProjectedCubic;
using curvescan::ViewTransform;

namespace {

// The plane point of the projected cubic at t: the rational de Casteljau of curves/ (rational_bezier.h).
Point eval_projected(const ProjectedCubic& cubic, double t) {
  return curvescan::rational_de_casteljau(cubic.points, cubic.weights, t);
}

BezierPatch random_patch(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  BezierPatch patch;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      // A wavy sheet over the 4 × 4 grid.
      patch.points[4 * i + j] = {i + 0.3 * coordinate(rng), j + 0.3 * coordinate(rng), coordinate(rng)};
    }
  }
  return patch;
}

}  // namespace

TEST_CASE("bezier patch: projected iso-curves equal the projected surface", "[bezier_patch]") {
  std::mt19937_64 rng(2323);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const BezierPatch patch = random_patch(rng);
    Camera camera;
    camera.eye = {-6.0 + unit(rng), -8.0 + unit(rng), 5.0 + unit(rng)};
    camera.target = {1.5, 1.5, 0.0};
    camera.centre = {200, 150};
    if (trial % 2 == 0) {
      camera.focal = 400.0;
    } else {
      camera.scale = 50.0;
    }
    const auto view = ViewTransform::look_at(camera);
    REQUIRE(view.is_ok());
    for (const double fixed : {0.0, 0.25, 0.6, 1.0}) {
      const auto along_v = curvescan::project_cubic(patch.curve_at_u(fixed), *view);
      const auto along_u = curvescan::project_cubic(patch.curve_at_v(fixed), *view);
      REQUIRE(along_v.is_ok());
      REQUIRE(along_u.is_ok());
      CHECK(along_v->is_rational() == camera.focal.has_value());
      for (int k = 0; k <= 20; ++k) {
        const double t = k / 20.0;
        const Point direct_v = view->project(patch.eval(fixed, t));
        const Point direct_u = view->project(patch.eval(t, fixed));
        // Picture coordinates up to about 1000 units; the two evaluations round differently (a dozen
        // operations each, 1e-16 relative): 1e-9 units.
        CHECK(eval_projected(*along_v, t).x == Approx(direct_v.x).margin(1e-9));
        CHECK(eval_projected(*along_v, t).y == Approx(direct_v.y).margin(1e-9));
        CHECK(eval_projected(*along_u, t).x == Approx(direct_u.x).margin(1e-9));
        CHECK(eval_projected(*along_u, t).y == Approx(direct_u.y).margin(1e-9));
      }
    }
  }
}

TEST_CASE("bezier patch: corners interpolate and the camera's conventions", "[bezier_patch]") {
  std::mt19937_64 rng(7);
  const BezierPatch patch = random_patch(rng);
  CHECK(patch.eval(0, 0) == patch.points[0]);
  CHECK(patch.eval(1, 1) == patch.points[15]);
  CHECK(patch.eval(1, 0) == patch.points[12]);
  Camera camera;
  camera.eye = {0, -10, 0};
  camera.target = {0, 0, 0};
  camera.focal = 100.0;
  camera.centre = {50, 50};
  const auto view = ViewTransform::look_at(camera);
  REQUIRE(view.is_ok());
  // The target is at the centre; +z (up) is up in the picture, so a smaller picture y; +x is to the right.
  CHECK(view->project({0, 0, 0}).x == Approx(50.0));
  CHECK(view->project({0, 0, 0}).y == Approx(50.0));
  CHECK(view->project({0, 0, 1}).y == Approx(40.0));  // 100 · 1 / 10 above the centre
  CHECK(view->project({1, 0, 0}).x == Approx(60.0));
  // A control point behind the eye is an error, not a curve through infinity.
  CHECK_FALSE(curvescan::project_cubic({Point3{0, -20, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, *view).is_ok());
  camera.up = {0, 1, 0};  // parallel to the line of sight
  CHECK_FALSE(ViewTransform::look_at(camera).is_ok());
  camera.up = {0, 0, 1};
  camera.target = camera.eye;
  CHECK_FALSE(ViewTransform::look_at(camera).is_ok());
}
