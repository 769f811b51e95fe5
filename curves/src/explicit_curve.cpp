// Certified flattening of explicit curves y = f(x) (explicit_curve.h). The subdivision is a loop over an
// explicit stack, left to right, so that accepted pieces append to the current polyline in order.
#include "curvescan/curves/explicit_curve.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace curvescan {
namespace {

struct Piece {
  double a, b, fa, fb;
  int depth;
};

// Certified results are compared with the tolerance shrunk by this factor, which absorbs the rounding of
// the final bound computation (a handful of roundings of about 1e-16 each).
constexpr double kToleranceMargin = 1.0 - 1e-9;

enum class Verdict { kAccept, kSplit, kGap, kClippedGap };

class ExplicitFlattener {
 public:
  ExplicitFlattener(const Expression& f, const ExplicitCurveOptions& options) : f_(f), options_(options) {}

  Verdict judge(const Piece& piece) const {
    const Interval x{piece.a, piece.b};
    const IntervalGradient g = f_.evaluate_gradient(x, Interval::point(0.0));
    const Interval& value = g.value;
    if (value.empty) return Verdict::kGap;  // undefined on the whole piece
    if (!value.partial && (value.lo > options_.y_max || value.hi < options_.y_min))
      return Verdict::kClippedGap;
    const bool ends_finite = std::isfinite(piece.fa) && std::isfinite(piece.fb);
    if (!ends_finite || value.partial || !value.is_bounded()) return Verdict::kSplit;
    const double tolerance = options_.tolerance * kToleranceMargin;
    // The box test: graph and chord both inside [a, b] × value.
    if (std::hypot(piece.b - piece.a, value.hi - value.lo) <= tolerance) return Verdict::kAccept;
    // The slope test: needs a bounded derivative.
    if (g.dx.partial || !g.dx.is_bounded()) return Verdict::kSplit;
    const Interval fa = Interval::point(piece.fa), fb = Interval::point(piece.fb);
    const Interval slope = (fb - fa) / (Interval::point(piece.b) - Interval::point(piece.a));
    const double end_error = std::max((f_.evaluate(Interval::point(piece.a)) - fa).magnitude(),
                                      (f_.evaluate(Interval::point(piece.b)) - fb).magnitude());
    const Interval half_width = (Interval::point(piece.b) - Interval::point(piece.a)) * Interval::point(0.5);
    const Interval bound =
        Interval::point(end_error) + half_width * Interval::point((g.dx - slope).magnitude());
    if (bound.is_bounded() && bound.hi <= tolerance) return Verdict::kAccept;
    return Verdict::kSplit;
  }

  const Expression& f_;
  const ExplicitCurveOptions& options_;
};

std::string short_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

}  // namespace

Result<ExplicitCurve> flatten_explicit_curve(const Expression& f, double x0, double x1,
                                             const ExplicitCurveOptions& options) {
  if (!std::isfinite(x0) || !std::isfinite(x1) || !(x0 < x1) || !std::isfinite(x1 - x0)) {
    return Error{ErrorKind::kInvalidArgument,
                 "the x range must be two finite numbers x0 < x1 (and x1 − x0 finite)"};
  }
  if (!(options.tolerance > 0) || !std::isfinite(options.tolerance) || options.max_depth < 1 ||
      options.max_depth > 60 || !(options.y_min < options.y_max)) {
    return Error{ErrorKind::kInvalidArgument,
                 "invalid options for an explicit curve (tolerance > 0, y_min < y_max)"};
  }
  const ExplicitFlattener flattener(f, options);
  ExplicitCurve curve;
  std::vector<Point>* current = nullptr;
  auto end_polyline = [&] {
    if (current != nullptr && current->size() < 2) curve.polylines.pop_back();
    current = nullptr;
  };
  auto add_split = [&](double a, double b) {
    if (!curve.splits.empty() && curve.splits.back().second == a) {
      curve.splits.back().second = b;
    } else {
      curve.splits.emplace_back(a, b);
    }
  };
  std::vector<Piece> stack{{x0, x1, f.evaluate(x0), f.evaluate(x1), 0}};
  const std::size_t terms = std::max<std::size_t>(1, f.program().size());
  const std::size_t max_pieces =
      std::min(options.max_pieces, std::max<std::size_t>(1, options.max_work / terms));
  std::size_t examined = 0;
  while (!stack.empty()) {
    const Piece piece = stack.back();
    stack.pop_back();
    if (++examined > max_pieces) {
      return Error{ErrorKind::kLimitExceeded,
                   "the graph needs more than " + std::to_string(max_pieces) + " pieces at the tolerance " +
                       short_number(options.tolerance) +
                       (max_pieces < options.max_pieces
                            ? " (the work limit for an expression of " + std::to_string(terms) + " terms)"
                            : std::string()) +
                       " (near x = " + short_number(piece.a) +
                       "; raise the tolerance or narrow the x range)"};
    }
    Verdict verdict = flattener.judge(piece);
    const double middle = piece.a + (piece.b - piece.a) / 2;
    const bool can_split = piece.depth < options.max_depth && piece.a < middle && middle < piece.b;
    if (verdict == Verdict::kSplit && !can_split) verdict = Verdict::kGap;
    switch (verdict) {
      case Verdict::kAccept:
        if (current == nullptr || current->back() != Point{piece.a, piece.fa}) {
          end_polyline();
          current = &curve.polylines.emplace_back();
          current->push_back({piece.a, piece.fa});
        }
        current->push_back({piece.b, piece.fb});
        break;
      case Verdict::kSplit: {
        const double fm = f.evaluate(middle);
        stack.push_back({middle, piece.b, fm, piece.fb, piece.depth + 1});
        stack.push_back({piece.a, middle, piece.fa, fm, piece.depth + 1});
        break;
      }
      case Verdict::kClippedGap:
        curve.clipped = true;
        end_polyline();
        break;
      case Verdict::kGap:
        end_polyline();
        add_split(piece.a, piece.b);
        break;
    }
  }
  end_polyline();
  return curve;
}

}  // namespace curvescan
