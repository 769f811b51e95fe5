// classify_join on constructed joins: C0 only, G1 not C1, C1, C2, G2 not C1 (continuity.h; U. of Toronto, *Parametric Curves*
// "Geometric and Parametric Continuity", Dill, *Introduction to Parametric Curves*, "Joining Bezier Curves").
#include "curvescan/curves/continuity.h"

#include <catch2/catch.hpp>
#include <cmath>

using curvescan::Bezier;
using curvescan::classify_join;
using curvescan::JoinContinuity;
using curvescan::Point;

namespace {

// A: ends at P3 = (3,0) with A'(1) = 3(P3 - P2) = (3,-3) and A''(1) = 6(P3 - 2P2 + P1) = (6,-6)·... below.
const Bezier kA({{0, 0}, {1, 2}, {2, 1}, {3, 0}});

// The Q2 that makes B''(0) = 6(Q0 - 2Q1 + Q2) equal A''(1) = 6(P1 - 2P2 + P3).
Point c2_partner(Point q0, Point q1) {
  const auto p = kA.points();
  return q0 + ((p[1] - p[2]) - (p[2] - p[3])) + (q1 - q0) * 2.0;
}

}  // namespace

TEST_CASE("continuity: C0 only (a corner)", "[continuity]") {
  const Bezier b({{3, 0}, {4, 1}, {5, 1}, {6, 0}});
  REQUIRE(classify_join(kA, b) == JoinContinuity{0, 0});
}

TEST_CASE("continuity: G1 but not C1 (same direction, twice the speed)", "[continuity]") {
  const Bezier b({{3, 0}, {5, -2}, {6, 0}, {7, 0}});
  REQUIRE(classify_join(kA, b) == JoinContinuity{0, 1});
}

TEST_CASE("continuity: C1 (collinear P2, P3 = Q0, Q1 at equal spacing)", "[continuity]") {
  const Bezier b({{3, 0}, {4, -1}, {6, 0}, {7, 0}});
  REQUIRE(classify_join(kA, b) == JoinContinuity{1, 1});
}

TEST_CASE("continuity: C2 (five points constrained, Dill, *Introduction to Parametric Curves*)", "[continuity]") {
  const Point q0{3, 0}, q1{4, -1};
  const Bezier b({q0, q1, c2_partner(q0, q1), {9, 1}});
  REQUIRE(classify_join(kA, b) == JoinContinuity{2, 2});
}

TEST_CASE("continuity: the two halves of a split are G2 but not C1 when t != 1/2", "[continuity]") {
  // Splitting at 0.3 reparametrizes both halves by different factors (0.3 and 0.7): velocities differ,
  // the geometry (tangent and curvature) does not.
  const Bezier curve({{0, 0}, {1, 3}, {4, 3}, {6, -1}});
  const auto [left, right] = curve.split(0.3);
  REQUIRE(classify_join(left, right) == JoinContinuity{0, 2});
  const auto [l2, r2] = curve.split(0.5);
  REQUIRE(classify_join(l2, r2) == JoinContinuity{2, 2});
}

TEST_CASE("continuity: tolerance, disjoint curves, degenerate tangents", "[continuity]") {
  // Disjoint.
  REQUIRE(classify_join(kA, Bezier({{3.5, 0}, {4, 1}})) == JoinContinuity{-1, -1});
  // A gap of 1e-12 of the drawing size is within the default 1e-9; 1e-6 is not.
  const Bezier near({{3 + 1e-12, 0}, {4, -1}, {6, 0}, {7, 0}});
  REQUIRE(classify_join(kA, near) == JoinContinuity{1, 1});
  const Bezier far({{3 + 1e-6, 0}, {4, -1}, {6, 0}, {7, 0}});
  REQUIRE(classify_join(kA, far).parametric == -1);
  REQUIRE(classify_join(kA, far, 1e-3) == JoinContinuity{1, 1});
  // A zero end tangent (P2 == P3) has no direction: reported G0 even though the positions meet.
  const Bezier stalled({{0, 0}, {1, 2}, {3, 0}, {3, 0}});
  REQUIRE(classify_join(stalled, Bezier({{3, 0}, {3, 0}, {5, 1}})).geometric == 0);
  // NaN anywhere and empty curves.
  REQUIRE(classify_join(kA, Bezier({{3, 0}, {std::nan(""), 0}})) == JoinContinuity{-1, -1});
  REQUIRE(classify_join(kA, Bezier()) == JoinContinuity{-1, -1});
  REQUIRE(classify_join(kA, kA.reversed(), std::nan("")) == JoinContinuity{-1, -1});
  // Lines meeting straight on: C2 (second derivatives both zero) and G2 (zero curvature both sides).
  REQUIRE(classify_join(Bezier({{0, 0}, {1, 1}}), Bezier({{1, 1}, {2, 2}})) == JoinContinuity{2, 2});
}
