// Quadratic Béziers flattened in closed form: the bound, the Newton step and the walk. Derivation, proof
// and rounding analysis in flatten_quadratic.h.
#include "flatten_quadratic.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "flatten_step_search.h"

namespace curvescan::detail {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
// Margin relative to 2h(|E| + |D|), an upper bound of the sub-arc's control polygon radius (as the
// general bound's kRoundingMargin): covers the < 1e-11 rounding of the closed form (flatten_quadratic.h).
constexpr double kRelativeMargin = 1e-9;
// Margin in ulps of the largest coordinate: the two vertices of a chord are de Casteljau points (two
// lerp levels, <= ~4 ulps each coordinate), and moving a chord's ends by delta moves the chord by <= delta.
constexpr double kVertexUlps = 16.0;
// The closed form is used only when the vertex margin is at most this fraction of the tolerance (then it
// costs nothing measurable); finer tolerances, near the coordinates' resolution, take the general walk,
// whose step search reports what cannot be certified.
constexpr double kMaxVertexMarginFraction = 1.6e-5;
// Coordinates and differences within this range: squares and products neither overflow nor underflow.
constexpr double kSafeHigh = 1e100;
constexpr double kSafeLow = 1e-100;
// Below this fraction of |E| + |D| the half-speed |V(m)| is not trusted as a chord direction (its relative
// rounding would exceed 1e-11): the piece takes Wang's bound h^2|D|/4 instead.
constexpr double kTrustedSpeed = 1e-4;
// Newton aims the across-chord error at this fraction of the tolerance: the margins (<= 6e-4 of the
// tolerance where the closed form applies) fit under it, so the exact check passes at the first trial
// and the piece is >= sqrt(0.995) = 99.7 % of the longest one.
constexpr double kNewtonTarget = 0.995;
// Newton converges quadratically from the small-step estimate (off by the change of |V| over the piece,
// a few % on a flat piece): 2 steps land well inside the 0.5 % headroom, and the exact check catches the
// rest (measured: 1.04 checks per segment on the glyph quadratics).
constexpr int kNewtonSteps = 2;

/// One parabola's constants, hoisted out of the walk.
class Parabola {
 public:
  Parabola(Point p0, Point p1, Point p2) noexcept
      : p0_(p0), p1_(p1), p2_(p2), e_(p1 - p0), d_((p2 - p1) - (p1 - p0)) {
    cross_ = std::abs(e_.cross(d_));
    d_length_ = std::sqrt(d_.length_squared());
    scale_ = std::sqrt(e_.length_squared()) + d_length_;
    // Pairwise maxima (the initializer-list form cost a tenth of a glyph quadratic). A NaN coordinate may
    // be dropped here, but then scale_ is NaN and applicable() fails all the same.
    largest_coordinate_ =
        std::max(std::max(std::max(std::abs(p0.x), std::abs(p0.y)), std::max(std::abs(p1.x), std::abs(p1.y))),
                 std::max(std::abs(p2.x), std::abs(p2.y)));
    vertex_margin_ = kVertexUlps * kEpsilon * largest_coordinate_;
  }

  /// Whether the closed form's rounding analysis holds for this curve at `tolerance`.
  [[nodiscard]] bool applicable(double tolerance) const noexcept {
    return largest_coordinate_ <= kSafeHigh && scale_ >= kSafeLow && scale_ <= kSafeHigh &&
           vertex_margin_ <= kMaxVertexMarginFraction * tolerance;
  }

  /// B(t) by de Casteljau from the original control points (the general walk's vertex, bit for bit).
  [[nodiscard]] Point at(double t) const noexcept { return lerp(lerp(p0_, p1_, t), lerp(p1_, p2_, t), t); }

  /// Proven bound on Hausdorff(B[a, b], chord), rounding margins included (flatten_quadratic.h (iv)).
  [[nodiscard]] double bound(double a, double b) const noexcept {
    const double h = b - a, h2 = h * h;
    const Vec2 mid = half_derivative(0.5 * (a + b));
    const double speed = std::sqrt(mid.length_squared());
    double distance = 0.25 * d_length_ * h2;  // Wang: max |g - lerp|, always valid
    if (speed >= kTrustedSpeed * scale_) {
      const double across = cross_ * h2 / (4.0 * speed);
      const double chord = 2.0 * h * speed;
      const double bulge = std::abs(mid.dot(d_)) * h2 / speed;  // |c| of (iii)
      const double over = bulge > chord ? (bulge - chord) * (bulge - chord) / (4.0 * bulge) : 0.0;
      const double exact = std::sqrt(across * across + over * over);
      if (exact < distance) distance = exact;
    }
    return distance + kRelativeMargin * 2.0 * h * scale_ + vertex_margin_;
  }

  /// Newton's estimate of the h for which the piece [a, a + h] is `target` away from its chord (no
  /// overshoot assumed); +inf when any length will do (a straight parabola). Only a guess: the walk checks
  /// it with bound().
  [[nodiscard]] double step_guess(double a, double target) const noexcept {
    const double start_speed = std::sqrt(half_derivative(a).length_squared());
    double h = std::sqrt(4.0 * target * start_speed / cross_);  // small-step estimate; +inf for cross 0
    if (!(h > 0.0) || !(h <= 1.0)) return h > 0.0 ? h : std::numeric_limits<double>::infinity();
    for (int step = 0; step < kNewtonSteps; ++step) {
      // f(h) = |E x D|·h^2 - 4·target·|V(a + h/2)|, f'(h) = 2|E x D|·h - 2·target·(V·D)/|V|.
      const Vec2 v = half_derivative(a + 0.5 * h);
      const double speed = std::sqrt(v.length_squared());
      const double f = cross_ * h * h - 4.0 * target * speed;
      const double slope = 2.0 * cross_ * h - 2.0 * target * v.dot(d_) / speed;
      if (!(slope > 0.0)) break;  // not convex here (or speed 0): keep the current estimate
      double next = h - f / slope;
      if (!(next > 0.0)) next = 0.5 * h;
      h = next;
      if (h > 1.0) break;
    }
    return h;
  }

  [[nodiscard]] double vertex_margin() const noexcept { return vertex_margin_; }

 private:
  /// V(t) = E + t·D = B'(t) / 2.
  [[nodiscard]] Vec2 half_derivative(double t) const noexcept { return e_ + d_ * t; }

  Point p0_, p1_, p2_;
  Vec2 e_, d_;
  double cross_ = 0.0;     // |E x D|, the same for every sub-arc
  double d_length_ = 0.0;  // |D|
  double scale_ = 0.0;     // |E| + |D| >= max over [0, 1] of |V|
  double largest_coordinate_ = 0.0;
  double vertex_margin_ = 0.0;
};

}  // namespace

double quadratic_arc_chord_bound(Point p0, Point p1, Point p2, double a, double b) noexcept {
  return Parabola(p0, p1, p2).bound(a, b);
}

std::optional<FlattenOutcome> flatten_quadratic(std::span<const Point> ctrl, double tolerance,
                                                std::vector<Point>& out, std::size_t max_segments) {
  if (ctrl.size() != 3) return std::nullopt;
  const Parabola parabola(ctrl[0], ctrl[1], ctrl[2]);
  if (!parabola.applicable(tolerance)) return std::nullopt;
  const double target = kNewtonTarget * tolerance - parabola.vertex_margin();
  double a = 0.0;  // parameter of the last vertex
  bool within_tolerance = true;
  WalkTrials trials(max_segments);
  for (std::size_t segments = 1;; ++segments) {
    if (segments >= max_segments) {
      out.push_back(ctrl[2]);
      return FlattenOutcome::kSegmentLimit;
    }
    // Lengths in the step search are fractions of the rest [a, 1]; u = 1 is exactly b = 1.
    const double rest = 1.0 - a;
    auto end_of = [a, rest](double u) { return u >= 1.0 ? 1.0 : a + u * rest; };
    const double guess = parabola.step_guess(a, target) / rest;
    // The StepSearch's first trial, done here: Newton's guess nearly always passes with an error of at
    // least kAcceptFraction of the tolerance (or is the whole rest), which ends the search at once on
    // that trial. Only otherwise is the search run, from the start and deterministically, so the piece
    // accepted is the one the search alone would accept (the first trial is merely evaluated twice).
    const double first = std::min(guess, 1.0);
    double b = end_of(first);
    const double first_error = parabola.bound(a, b);
    const bool accepted_at_once = first > 0.0 && first_error <= tolerance &&
                                  (first >= 1.0 || first_error >= StepSearch::kAcceptFraction * tolerance);
    int evaluations = 1;  // the first trial
    if (!accepted_at_once) {
      StepSearch search(guess, tolerance, trials.next_cap());
      for (bool done = false; !done;) done = search.record(parabola.bound(a, end_of(search.length())));
      if (!search.passed()) within_tolerance = false;  // unreachable where applicable(); kept total
      b = end_of(search.accepted());
      evaluations += search.evaluations();
    }
    if (b >= 1.0) break;
    if (!trials.spend(evaluations)) {  // the walk's allowance is spent: end as at the segment cap
      out.push_back(ctrl[2]);
      return FlattenOutcome::kSegmentLimit;
    }
    if (!(b > a)) b = std::nextafter(a, 2.0);  // t strictly increases
    out.push_back(parabola.at(b));
    a = b;
  }
  out.push_back(ctrl[2]);  // exactly the end point
  return within_tolerance ? FlattenOutcome::kOk : FlattenOutcome::kSegmentLimit;
}

}  // namespace curvescan::detail
