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
#pragma once

#include <algorithm>
#include <cmath>
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

  /// Starts a search whose first trial is `first` (clamped to 1; must be > 0 or +inf).
  StepSearch(double first, double tolerance) noexcept : tolerance_(tolerance), u_(std::min(first, 1.0)) {}

  /// The length of the next trial.
  [[nodiscard]] double length() const noexcept { return u_; }

  /// Records the proven error bound of the trial of length length(); returns true when the search is
  /// over (then read accepted()). NaN counts as a failure.
  bool record(double err) noexcept {
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
    return ++trials_ >= kMaxTrialsPerSegment;
  }

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
  // Hard cap on bound evaluations per segment. Every failure shrinks u by >= 10 %, usually by far more;
  // 200 trials reach below 1e-9 even in the worst case, long after any finite piece is flat.
  static constexpr int kMaxTrialsPerSegment = 200;
  // Limits on how far one model prediction may move u (the u^2 model is only local).
  static constexpr double kMaxGrowth = 4.0;
  static constexpr double kMinShrink = 1.0 / 256.0;
  static constexpr double kMaxShrink = 0.9;

  double tolerance_;
  double u_;
  double pass_u_ = 0.0, pass_err_ = 0.0;                     // longest passing trial
  double fail_u_ = std::numeric_limits<double>::infinity();  // shortest failing trial
  int improving_ = 0;
  int trials_ = 0;
};

}  // namespace curvescan::detail
