// Bezier::bounding_box: contains the curve and is touched by it on all four sides (bezier.h).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "curvescan/curves/bezier.h"
#include "random_curves.h"

using curvescan::Bezier;
using curvescan::Point;
using curvescan::Rect;
using curvescan::test::sampled_box;

namespace {

constexpr int kSamples = 20000;

// Dense samples in [0, 1]: their box is inside the true box and approaches it from inside. Near an
// extremum t*, a coordinate differs from its extreme by |B''|/2 · Δt² with Δt <= 1/(2·kSamples); with
// coordinates <= 100 and degree <= 10, |B''| <= n(n-1)·4·100 = 36000, so the gap is <= 36000/2 · 6.25e-10
// ≈ 1.2e-5 (and is one-sided: samples never exceed the true extreme).
constexpr double kTouchTolerance = 2e-5;
// The box itself comes from eval() at computed roots: rounding ~1e-14 at coordinates ~100.
constexpr double kContainSlack = 1e-11;

void require_tight(const Bezier& curve) {
  curvescan::test::require_tight_box(curve.bounding_box(), sampled_box(curve, kSamples), kContainSlack,
                                     kTouchTolerance);
}

}  // namespace

TEST_CASE("bezier bounds: tight for random curves of degree 1..10", "[bezier][bounds]") {
  std::mt19937_64 rng(5551212);
  for (int degree = 1; degree <= 10; ++degree) {
    for (int trial = 0; trial < 12; ++trial) require_tight(curvescan::test::random_bezier(rng, degree));
  }
}

TEST_CASE("bezier bounds: closed form (degree <= 3) agrees with subdivision (elevated copies)",
          "[bezier][bounds]") {
  // Elevation keeps the curve, so an elevated cubic's box (found by Bernstein subdivision) must equal the
  // cubic's (found by the quadratic formula): the two root finders are held to the same answer.
  std::mt19937_64 rng(777);
  for (int degree = 2; degree <= 3; ++degree) {
    for (int trial = 0; trial < 200; ++trial) {
      const Bezier curve = curvescan::test::random_bezier(rng, degree);
      const Rect closed = curve.bounding_box();
      for (const Bezier& raised : {curve.elevate(), curve.elevate().elevate().elevate()}) {
        const Rect subdivided = raised.bounding_box();
        // Both evaluate the curve at its extremal t; the t differ by root-finding rounding (~1e-15), the
        // coordinate by |B'|·Δt + |B''|Δt²: at an extremum |B'| = 0 in that axis, so agreement is ~1e-13.
        REQUIRE(std::abs(closed.x0 - subdivided.x0) <= 1e-10);
        REQUIRE(std::abs(closed.y0 - subdivided.y0) <= 1e-10);
        REQUIRE(std::abs(closed.x1 - subdivided.x1) <= 1e-10);
        REQUIRE(std::abs(closed.y1 - subdivided.y1) <= 1e-10);
      }
    }
  }
}

TEST_CASE("bezier bounds: known boxes", "[bezier][bounds]") {
  // Symmetric arch: y(t) = 6t(1-t) peaks at t = 1/2 with y = 1.5, far below the control point y = 2.
  const Rect arch = Bezier({{0, 0}, {1, 2}, {3, 2}, {4, 0}}).bounding_box();
  REQUIRE(arch.x0 == 0.0);
  REQUIRE(arch.x1 == 4.0);
  REQUIRE(arch.y0 == 0.0);
  REQUIRE(arch.y1 == Approx(1.5).epsilon(1e-15));
  // A degree-6 curve with a derivative root of multiplicity 3 in y at t = 1/2 (y = (2t - 1)^4 shape in
  // Bernstein form is hard to write; instead: all control y equal except the middle one, symmetric).
  const Rect bump = Bezier({{0, 0}, {1, 0}, {2, 0}, {3, 4}, {4, 0}, {5, 0}, {6, 0}}).bounding_box();
  // y(t) = 4·B_{6,3}(t) = 80 t³(1-t)³, maximal at t = 1/2: 80/64 = 1.25.
  REQUIRE(bump.y1 == Approx(1.25).epsilon(1e-14));
  REQUIRE(bump.y0 == 0.0);
}

TEST_CASE("bezier bounds: degenerate input", "[bezier][bounds]") {
  REQUIRE(!Bezier().bounding_box().is_finite());
  REQUIRE(!Bezier({{0, 0}, {std::nan(""), 1}, {2, 2}}).bounding_box().is_finite());
  REQUIRE(Bezier({{2, 3}}).bounding_box() == Rect{2, 3, 2, 3});
  // A curve whose derivative is identically zero in y (horizontal) must not loop in the root finder.
  const Rect flat = Bezier({{0, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 1}}).bounding_box();
  REQUIRE(flat == Rect{0, 1, 5, 1});
}
