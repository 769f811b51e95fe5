// flatten_step_search.h (private to the flattener): the search for (nearly) the longest passing piece at
// one vertex, shared by the general de Casteljau walk (flatten.cpp) and the closed-form quadratic walk
// (flatten_quadratic.cpp).
//
// Lengths are relative: u in (0, 1] is the fraction of the rest of the curve, u = 1 the whole rest. The
// caller evaluates the proven error bound of the trial piece of length length() and hands it to record().
// The chord error of a short piece grows like u^2 (the sagitta is curvature·length^2/8), so from one
// trial the longest passing u is predicted as u·sqrt(tol/err); we aim at kTargetFraction of the tolerance,
// keep a bracket [longest pass, shortest fail] and stop once a pass uses >= kAcceptFraction of the
// tolerance, the bracket is tight, or the improving budget is spent. Work is bounded: every failure
// shrinks u by >= 10 %, and there are at most kMaxTrialsPerSegment trials.
//
// WalkTrials bounds a whole walk the same way: its bound evaluations, not only its segments, are bounded
// by the caller's segment budget (see there).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace curvescan::detail {

class StepSearch {
 public:
  // A passing piece whose error is at least this fraction of the tolerance is accepted without trying a
  // longer one: with err ~ u^2 it is >= sqrt(0.9) = 95 % of the longest passing piece.
  static constexpr double kAcceptFraction = 0.9;
  // Trials aim the predicted error at this fraction of the tolerance, so that the prediction errs on the
  // passing side (a pass costs one trial, an overshoot at least two).
  static constexpr double kTargetFraction = 0.96;

  // Hard cap on bound evaluations per segment. Every failure shrinks u by >= 10 %, usually by far more;
  // 200 trials reach below 1e-9 even in the worst case, long after any finite piece is flat.
  static constexpr int kMaxTrialsPerSegment = 200;

  /// Starts a search whose first trial is `first` (clamped to 1; must be > 0 or +inf) and that evaluates
  /// at most `max_trials` (1..kMaxTrialsPerSegment) bounds.
  StepSearch(double first, double tolerance, int max_trials = kMaxTrialsPerSegment) noexcept
      : tolerance_(tolerance),
        u_(std::min(first, 1.0)),
        max_trials_(std::clamp(max_trials, 1, kMaxTrialsPerSegment)) {}

  /// The length of the next trial.
  [[nodiscard]] double length() const noexcept { return u_; }

  /// Records the proven error bound of the trial of length length(); returns true when the search is
  /// over (then read accepted()). NaN counts as a failure.
  bool record(double err) noexcept {
    ++evaluations_;
    // The u^2 model: err(u') ~ err·(u'/u)^2, so u' = u·sqrt(target/err) predicts err(u') = target.
    const double ratio = std::sqrt(kTargetFraction * tolerance_ / err);  // +inf for err = 0, NaN for NaN
    double next;
    if (err <= tolerance_) {
      if (u_ > pass_u_) {
        pass_u_ = u_;
        pass_err_ = err;
      }
      if (u_ >= 1.0 || err >= kAcceptFraction * tolerance_ || ++improving_ > kMaxImprovingTrials) return true;
      next = u_ * std::min(ratio, kMaxGrowth);
    } else {
      fail_u_ = std::min(fail_u_, u_);
      next = u_ * (std::isnan(ratio) ? 0.5 : std::clamp(ratio, kMinShrink, kMaxShrink));
    }
    if (pass_u_ > 0.0) {
      if (fail_u_ <= kTightBracket * pass_u_) return true;
      // Stay strictly inside the bracket; bisect when the model points outside it.
      if (!(next > pass_u_ && next < fail_u_)) next = 0.5 * (pass_u_ + std::min(fail_u_, 1.0));
    }
    u_ = std::min(next, 1.0);
    return evaluations_ >= max_trials_;
  }

  /// The bounds evaluated so far (the calls of record()).
  [[nodiscard]] int evaluations() const noexcept { return evaluations_; }

  /// True when some trial passed. When none did (the budget was spent: only possible when rounding keeps
  /// the bound above a tolerance below the floating-point resolution of the coordinates), accepted() is
  /// the last, tiny, trial length and the piece is not certified.
  [[nodiscard]] bool passed() const noexcept { return pass_u_ > 0.0; }
  [[nodiscard]] double accepted() const noexcept { return passed() ? pass_u_ : u_; }
  /// The error bound of the accepted piece (0 when none passed).
  [[nodiscard]] double accepted_error() const noexcept { return pass_err_; }

  /// The growth factor the u^2 model predicts for the next step after accepting a piece of error `err`.
  [[nodiscard]] static double predicted_growth(double err, double tolerance) noexcept {
    return std::min(std::sqrt(kTargetFraction * tolerance / err), kMaxGrowth);
  }

 private:
  // Once a pass is found, at most this many further trials try to lengthen it.
  static constexpr int kMaxImprovingTrials = 3;
  // Stop refining when the bracket [pass, fail] is this tight (relative).
  static constexpr double kTightBracket = 1.02;
  // Limits on how far one model prediction may move u (the u^2 model is only local).
  static constexpr double kMaxGrowth = 4.0;
  static constexpr double kMinShrink = 1.0 / 256.0;
  static constexpr double kMaxShrink = 0.9;

  double tolerance_;
  double u_;
  double pass_u_ = 0.0, pass_err_ = 0.0;                     // longest passing trial
  double fail_u_ = std::numeric_limits<double>::infinity();  // shortest failing trial
  int improving_ = 0;
  int max_trials_;
  int evaluations_ = 0;
};

/// The bound evaluations left to one walk: kMaxTrialsPerSegment for a single hard segment plus
/// kMeanTrialsPerSegment for each segment of the walk's cap, so that a walk's work, like its output, is
/// bounded by the budget its caller gives. A search that never passes (a piece the bound cannot certify:
/// rounding of subnormal weights, a tolerance at the coordinates' resolution) spends the whole per-segment
/// cap, and before this allowance every segment of the cap could: 200 evaluations each, 8 million for a
/// conic with weights 1 and DBL_MAX at a 2^18 cap (fuzz/regressions/raster_stroke/
/// conic_weight_dbl_max_flattened_past_budget_*). Walks that certify their pieces take 1 to 3 evaluations
/// per segment (docs/flattening.md §3), so the allowance binds only on walks the search cannot certify;
/// when it is spent the walk ends as at its segment cap (the rest is a chord, kSegmentLimit).
class WalkTrials {
 public:
  static constexpr std::size_t kMeanTrialsPerSegment = 8;

  explicit WalkTrials(std::size_t max_segments) noexcept
      : left_(max_segments <= (std::numeric_limits<std::size_t>::max() - kMaxTrials) / kMeanTrialsPerSegment
                  ? kMaxTrials + kMeanTrialsPerSegment * max_segments
                  : std::numeric_limits<std::size_t>::max()) {}

  /// The cap of the next segment's search (>= 1 while anything is left).
  [[nodiscard]] int next_cap() const noexcept {
    return left_ < kMaxTrials ? static_cast<int>(left_) : StepSearch::kMaxTrialsPerSegment;
  }
  /// Charges `evaluations`; false once nothing is left (then the walk must end).
  bool spend(int evaluations) noexcept {
    const auto spent = static_cast<std::size_t>(evaluations);
    left_ = spent < left_ ? left_ - spent : 0;
    return left_ > 0;
  }

 private:
  static constexpr auto kMaxTrials = static_cast<std::size_t>(StepSearch::kMaxTrialsPerSegment);
  std::size_t left_;
};

}  // namespace curvescan::detail
