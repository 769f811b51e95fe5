// Conics flattened with an O(1) exact bound per trial: the blossom, the standard-form sagitta and the
// walk. Derivation, proof and rounding analysis in flatten_conic.h.
#include "flatten_conic.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "flatness_bound.h"
#include "flatten_step_search.h"

namespace curvescan::detail {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
// Margin relative to R = max(|q1 - q0|, |q2 - q0|), as the general bound's kRoundingMargin.
constexpr double kRelativeMargin = 1e-9;
// Ulps of the largest coordinate per unit of R/L (flatten_conic.h "Rounding"): the projected points carry
// a few ulps each, the cross product over the chord length turns that into ~4·eps·M·R/L.
constexpr double kVertexUlps = 16.0;
// The closed form is used only when 16 ulps of the largest coordinate are at most this fraction of the
// tolerance; finer tolerances, near the coordinates' resolution, take the general walk.
constexpr double kMaxVertexMarginFraction = 1.6e-5;
// Coordinates and scaled weights within this range: the products and squares neither overflow nor
// underflow.
constexpr double kSafeHigh = 1e100;
constexpr double kSafeLow = 1e-100;
// sqrt(DBL_MIN): a vector shorter than this may have a squared length that underflows to 0 or a subnormal,
// so its measured length can be low by up to this much. Chords that short take branch (iii) of bound(),
// which pays it as an absolute slack (fuzz regression raster_stroke/subnormal_conic_endless_walk: a conic
// ~1e-308 wide measured a zero chord, took NaN into the overshoot branch, and the walk crept by ulps).
constexpr double kUnderflowLength = 1.5e-154;
// Below this ratio L/R the chord direction is not trusted (flatten_conic.h (iii)).
constexpr double kTrustedChord = 1e-4;

struct Homogeneous {
  double wx, wy, w;
};

// The general walk's lerp and projection (flatten.cpp), so that vertices are the same bit for bit.
Homogeneous lerp(Homogeneous a, Homogeneous b, double u) noexcept {
  return {a.wx + (b.wx - a.wx) * u, a.wy + (b.wy - a.wy) * u, a.w + (b.w - a.w) * u};
}
Point project(Homogeneous h) noexcept {
  return {h.wx / h.w, h.wy / h.w};
}

/// One conic's homogeneous control points (weights scaled by their maximum, as flatten_rational does)
/// and constants.
class Conic {
 public:
  Conic(std::span<const Point> ctrl, std::span<const double> weights) noexcept {
    const double w_max = std::max({weights[0], weights[1], weights[2]});
    double largest = 0.0, lightest = 1.0;
    for (std::size_t i = 0; i < 3; ++i) {
      const double w = weights[i] / w_max;
      h_[i] = {ctrl[i].x * w, ctrl[i].y * w, w};
      largest = std::max({largest, std::abs(ctrl[i].x), std::abs(ctrl[i].y)});
      lightest = std::min(lightest, w);
    }
    largest_coordinate_ = largest;
    lightest_weight_ = lightest;
    vertex_margin_ = kVertexUlps * kEpsilon * largest;
  }

  /// Whether the closed form's rounding analysis holds for this conic at `tolerance`.
  [[nodiscard]] bool applicable(double tolerance) const noexcept {
    return largest_coordinate_ <= kSafeHigh && lightest_weight_ >= kSafeLow &&
           vertex_margin_ <= kMaxVertexMarginFraction * tolerance && tolerance >= 1e3 * kUnderflowLength;
  }

  /// The conic's point at t, by de Casteljau on the homogeneous points (the general walk's vertex).
  [[nodiscard]] Point at(double t) const noexcept { return project(blossom(t, t)); }

  /// Proven bound on Hausdorff(sub-arc [a, b], chord), margins included (flatten_conic.h).
  [[nodiscard]] double bound(double a, double b) const noexcept {
    const Homogeneous s0 = blossom(a, a), s1 = blossom(a, b), s2 = blossom(b, b);
    const Point q0 = project(s0), q1 = project(s1), q2 = project(s2);
    const Vec2 chord = q2 - q0, handle = q1 - q0;
    const double length = std::sqrt(chord.length_squared());
    const double radius = std::max(length, std::sqrt(handle.length_squared()));
    if (!(length > kUnderflowLength) || !(length >= kTrustedChord * radius)) {
      // (iii), also for a chord too short to measure (a single point, or a sub-arc so small that its squared
      // lengths underflow: then both lengths may read low by up to kUnderflowLength each) and NaN (NaN out).
      return radius + kRelativeMargin * radius + 2.0 * vertex_margin_ + 2.0 * kUnderflowLength;
    }
    const double along = chord.dot(handle) / length;
    double distance;
    if (along >= 0.0 && along <= length) {
      const double k = s1.w / std::sqrt(s0.w * s2.w);  // standard-form middle weight
      distance = k / (1.0 + k) * std::abs(chord.cross(handle)) / length;
    } else {
      // (ii): the sub-arc overshoots an end of its chord; the general exact bound takes it.
      const std::array<Point, 3> points{q0, q1, q2};
      const std::array<double, 3> weights{s0.w, s1.w, s2.w};
      distance = chord_distance_bound(points, weights);
    }
    return distance + kRelativeMargin * radius + vertex_margin_ * (1.0 + radius / length);
  }

 private:
  /// H(u, v): the blossom of the homogeneous quadratic; H(a, a), H(a, b), H(b, b) control [a, b].
  [[nodiscard]] Homogeneous blossom(double u, double v) const noexcept {
    return lerp(lerp(h_[0], h_[1], u), lerp(h_[1], h_[2], u), v);
  }

  std::array<Homogeneous, 3> h_{};
  double largest_coordinate_ = 0.0;
  double lightest_weight_ = 0.0;
  double vertex_margin_ = 0.0;
};

}  // namespace

double conic_arc_chord_bound(std::span<const Point> ctrl, std::span<const double> weights, double a,
                             double b) noexcept {
  return Conic(ctrl, weights).bound(a, b);
}

std::optional<FlattenOutcome> flatten_conic(std::span<const Point> ctrl, std::span<const double> weights,
                                            double tolerance, std::vector<Point>& out,
                                            std::size_t max_segments) {
  if (ctrl.size() != 3 || weights.size() != 3) return std::nullopt;
  const Conic conic(ctrl, weights);
  if (!conic.applicable(tolerance)) return std::nullopt;
  double a = 0.0;      // parameter of the last vertex
  double guess = 1.0;  // first trial length, as a fraction of the rest [a, 1]
  bool within_tolerance = true;
  WalkTrials trials(max_segments);
  for (std::size_t segments = 1;; ++segments) {
    if (segments >= max_segments) {
      out.push_back(ctrl[2]);
      return FlattenOutcome::kSegmentLimit;
    }
    const double rest = 1.0 - a;
    auto end_of = [a, rest](double u) { return u >= 1.0 ? 1.0 : a + u * rest; };
    StepSearch search(guess, tolerance, trials.next_cap());
    for (bool done = false; !done;) done = search.record(conic.bound(a, end_of(search.length())));
    if (!search.passed()) within_tolerance = false;  // unreachable where applicable(); kept total
    double b = end_of(search.accepted());
    if (b >= 1.0) break;
    if (!trials.spend(search.evaluations())) {  // the walk's allowance is spent: end as at the segment cap
      out.push_back(ctrl[2]);
      return FlattenOutcome::kSegmentLimit;
    }
    if (!(b > a)) b = std::nextafter(a, 2.0);  // t strictly increases
    out.push_back(conic.at(b));
    // Next step: the accepted length, corrected by the u^2 model, as a fraction of the new rest.
    guess = (b - a) * StepSearch::predicted_growth(search.accepted_error(), tolerance) / (1.0 - b);
    a = b;
  }
  out.push_back(ctrl[2]);  // exactly the end point, not a projection
  return within_tolerance ? FlattenOutcome::kOk : FlattenOutcome::kSegmentLimit;
}

}  // namespace curvescan::detail
