// Cubic Béziers flattened with a closed-form bound per sub-arc: the bound and the walk. Derivation, proof
// and rounding analysis in flatten_cubic.h (docs/flattening.md §1c).
#include "flatten_cubic.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "flatten_step_search.h"

namespace curvescan::detail {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
// 1/(12·sqrt 3): max |s(1-s)(s - 1/2)| on [0, 1] times 4, the factor of the h^3 term in (i).
constexpr double kThirdDifferenceFactor = 0.048112522432468816;  // = 1 / (12 * 1.7320508075688772)
// Margin relative to h·S (S = 3·sum |P_{i+1} - P_i|, >= the sub-arc's control polygon length / h): covers
// the few-ulp rounding of every product and sum in the closed form, as flatten_quadratic.cpp's margin.
constexpr double kRelativeMargin = 1e-9;
// δ in ulps of the largest coordinate: a vertex is three lerp levels from the control points (<= ~9 ulps
// per coordinate, 13 as a vector); moving a chord's ends by <= δ moves the chord by <= δ.
constexpr double kVertexUlps = 16.0;
// The chord-direction term of the margin is 20δ·W/L (flatten_cubic.h "Rounding").
constexpr double kDirectionMarginFactor = 20.0;
// The chord frame is used only when the computed chord is at least this many δ long (then 1/L of the
// exact chord is <= 8/7 of 1/L of the computed one, which the factor 20 above assumes).
constexpr double kMinChordVertexMargins = 16.0;
// Below this fraction of h·S the chord direction is not trusted (a chord that nearly closes on itself:
// its direction margin would dwarf the bound): the piece takes the frame-free (Wang-like) bound.
constexpr double kTrustedChord = 1e-4;
// Same applicability limits as the quadratic closed form (flatten_quadratic.cpp).
constexpr double kMaxVertexMarginFraction = 1.6e-5;
constexpr double kSafeHigh = 1e100;
constexpr double kSafeLow = 1e-100;
// The step guess aims the bound at this fraction of the tolerance: the middle of the window [0.9, 1] in
// which the step search accepts a piece at once (flatten_step_search.h).
constexpr double kGuessTarget = 0.95;
// A learnt correction of the model beyond this factor (near a cusp or an inflection, where the model's
// rate is ~0) is not trusted for the next piece.
constexpr double kMaxRateCorrection = 16.0;

double length(Vec2 v) noexcept { return std::sqrt(v.length_squared()); }
Vec2 lerp_vec(Vec2 a, Vec2 b, double t) noexcept { return a + (b - a) * t; }

/// One cubic's constants, hoisted out of the walk.
class CubicArc {
 public:
  CubicArc(Point p0, Point p1, Point p2, Point p3) noexcept
      : p0_(p0), p1_(p1), p2_(p2), p3_(p3), d0_((p0 - p1) + (p2 - p1)), d1_((p1 - p2) + (p3 - p2)) {
    j_ = d1_ - d0_;
    e0_ = p1 - p0;
    e1_ = p2 - p1;
    e2_ = p3 - p2;
    d0_length_ = length(d0_);
    d1_length_ = length(d1_);
    j_length_ = length(j_);
    scale_ = 3.0 * (length(p1 - p0) + length(p2 - p1) + length(p3 - p2));
    // Pairwise maxima; a NaN coordinate may be dropped here, but then scale_ is NaN and applicable() fails.
    largest_coordinate_ =
        std::max(std::max(std::max(std::abs(p0.x), std::abs(p0.y)), std::max(std::abs(p1.x), std::abs(p1.y))),
                 std::max(std::max(std::abs(p2.x), std::abs(p2.y)), std::max(std::abs(p3.x), std::abs(p3.y))));
    vertex_margin_ = kVertexUlps * kEpsilon * largest_coordinate_;
  }

  /// Whether the closed form's rounding analysis holds for this curve at `tolerance`.
  [[nodiscard]] bool applicable(double tolerance) const noexcept {
    return largest_coordinate_ <= kSafeHigh && scale_ >= kSafeLow && scale_ <= kSafeHigh &&
           vertex_margin_ <= kMaxVertexMarginFraction * tolerance;
  }

  /// B(t) by de Casteljau from the original control points, exactly P0 and P3 at the ends (the general
  /// walk's vertex, bit for bit, inside).
  [[nodiscard]] Point at(double t) const noexcept {
    if (t <= 0.0) return p0_;
    if (t >= 1.0) return p3_;
    const Point q0 = lerp(p0_, p1_, t), q1 = lerp(p1_, p2_, t), q2 = lerp(p2_, p3_, t);
    return lerp(lerp(q0, q1, t), lerp(q1, q2, t), t);
  }

  /// Proven bound on Hausdorff(B[a, b], [start, end]), start = at(a) and end = at(b), rounding margins
  /// included (flatten_cubic.h (iii)).
  [[nodiscard]] double bound(double a, double b, Point start, Point end) const noexcept {
    const double h = b - a, h2 = h * h, h3 = h2 * h;
    const double m = 0.5 * (a + b);
    const Vec2 k = d0_ + j_ * m;  // K(m) = B''(m) / 6
    // W: the (Wang-like) bracket with |K(m)| <= (1-m)|D0| + m|D1| (no square root).
    const double wang_cheap = 0.75 * h2 * ((1.0 - m) * d0_length_ + m * d1_length_) + kThirdDifferenceFactor * h3 * j_length_;
    const double arithmetic = kRelativeMargin * h * scale_ + 2.0 * vertex_margin_;
    const Vec2 chord = end - start;
    const double chord_length = length(chord);
    if (!(chord_length >= kTrustedChord * h * scale_ && chord_length >= kMinChordVertexMargins * vertex_margin_)) {
      return wang_cheap + arithmetic;  // NaN propagates
    }
    const Vec2 unit = chord / chord_length;
    const double across = 0.75 * h2 * std::abs(unit.cross(k)) + kThirdDifferenceFactor * h3 * std::abs(unit.cross(j_));
    const double bulge = 3.0 * h2 * std::abs(unit.dot(k)) + 0.5 * h3 * std::abs(unit.dot(j_));  // c of (ii)
    const double direction_margin = kDirectionMarginFactor * vertex_margin_ * wang_cheap / chord_length;
    if (!(bulge > chord_length)) return across + direction_margin + arithmetic;
    // Overshoot past an end of the chord (rare: a piece whose end tangent points back along the chord).
    const double over = (bulge - chord_length) * (bulge - chord_length) / (4.0 * bulge);
    const double frame = std::sqrt(across * across + over * over) + direction_margin;
    const double wang = 0.75 * h2 * length(k) + kThirdDifferenceFactor * h3 * j_length_;
    return std::min(frame, wang) + arithmetic;
  }

  /// The small-piece model of the across term at t: with the tangent V(t) = B'(t)/3 for the chord
  /// direction, across ~ h^2 · 3/4 · |V x K(t)| / |V| (the h^3 term and the margins left to the correction
  /// the walk learns from the last piece). NaN where the tangent vanishes (a cusp). Only a step guess.
  [[nodiscard]] double across_rate(double t) const noexcept {
    const Vec2 tangent = lerp_vec(lerp_vec(e0_, e1_, t), lerp_vec(e1_, e2_, t), t);
    return 0.75 * std::abs(tangent.cross(d0_ + j_ * t)) / length(tangent);
  }

 private:
  Point p0_, p1_, p2_, p3_;
  Vec2 d0_, d1_, j_;
  Vec2 e0_, e1_, e2_;  // first differences: B'(t) / 3 is their quadratic Bézier
  double d0_length_ = 0.0, d1_length_ = 0.0, j_length_ = 0.0;
  double scale_ = 0.0;  // S = 3·sum |P_{i+1} - P_i| >= max |B'|
  double largest_coordinate_ = 0.0;
  double vertex_margin_ = 0.0;  // δ
};

}  // namespace

double cubic_arc_chord_bound(Point p0, Point p1, Point p2, Point p3, double a, double b) noexcept {
  const CubicArc arc(p0, p1, p2, p3);
  return arc.bound(a, b, arc.at(a), arc.at(b));
}

std::optional<FlattenOutcome> flatten_cubic(std::span<const Point> ctrl, double tolerance, std::vector<Point>& out,
                                            std::size_t max_segments) {
  if (ctrl.size() != 4) return std::nullopt;
  const CubicArc arc(ctrl[0], ctrl[1], ctrl[2], ctrl[3]);
  if (!arc.applicable(tolerance)) return std::nullopt;
  double a = 0.0;        // parameter of the last vertex
  Point start = ctrl[0];  // the last vertex, as emitted
  double guess = 1.0;    // first trial length, as a fraction of the rest [a, 1]
  double rate_correction = 1.0;  // bound / (across_rate · h^2) on the last piece
  bool within_tolerance = true;
  WalkTrials trials(max_segments);
  for (std::size_t segments = 1;; ++segments) {
    if (segments >= max_segments) {
      out.push_back(ctrl[3]);
      return FlattenOutcome::kSegmentLimit;
    }
    // Lengths in the step search are fractions of the rest [a, 1]; u = 1 is exactly b = 1.
    const double rest = 1.0 - a;
    auto end_of = [a, rest](double u) { return u >= 1.0 ? 1.0 : a + u * rest; };
    // Step guess: the previous length (grown by the u^2 model) locates the next piece's middle; the model
    // across_rate there, corrected by what it missed on the last piece, predicts the length whose bound is
    // kGuessTarget of the tolerance. Only a guess: the search checks it with the bound.
    const double middle = std::min(a + 0.5 * guess * rest, 1.0);
    const double rate = arc.across_rate(middle);
    if (a > 0.0 && rate > 0.0) guess = std::sqrt(kGuessTarget * tolerance / (rate * rate_correction)) / rest;
    StepSearch search(guess, tolerance, trials.next_cap());
    for (bool done = false; !done;) {
      const double trial_end = end_of(search.length());
      done = search.record(arc.bound(a, trial_end, start, arc.at(trial_end)));
    }
    if (!search.passed()) within_tolerance = false;  // unreachable where applicable(); kept total
    double b = end_of(search.accepted());
    if (b >= 1.0) break;
    if (!trials.spend(search.evaluations())) {  // the walk's allowance is spent: end as at the segment cap
      out.push_back(ctrl[3]);
      return FlattenOutcome::kSegmentLimit;
    }
    if (!(b > a)) b = std::nextafter(a, 2.0);  // t strictly increases
    if (b >= 1.0) break;
    start = arc.at(b);
    out.push_back(start);
    // Next step: the accepted parameter length, corrected by the u^2 model, as a fraction of the new rest.
    guess = (b - a) * StepSearch::predicted_growth(search.accepted_error(), tolerance) / (1.0 - b);
    const double correction = search.accepted_error() / (rate * (b - a) * (b - a));
    rate_correction = correction > 0.0 && correction < kMaxRateCorrection ? correction : 1.0;
    a = b;
  }
  out.push_back(ctrl[3]);  // exactly the end point
  return within_tolerance ? FlattenOutcome::kOk : FlattenOutcome::kSegmentLimit;
}

}  // namespace curvescan::detail
