// B-spline evaluation, derivative, knot insertion and Bézier decomposition (Umetani, *Parametric Curve*, §3, eq. 5–9;
// Ince, *Curves*, "B-spline Curves"; Gallivan, *Parametric Curves*, "B-spline Curves"; The NURBS Book, Piegl & Tiller, ch. 2, 3, 5).
#include "curvescan/curves/bspline.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "curvescan/curves/knot_vector.h"

namespace curvescan {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// de Boor and Cox–de Boor need p + 1 scratch entries; degrees up to this run on the stack.
constexpr std::size_t kStackEntries = 16;

// A scratch array of `size` entries: on the stack for small degrees, on the heap otherwise.
template <class T>
class Scratch {
 public:
  explicit Scratch(std::size_t size) : size_(size) {
    if (size > kStackEntries) heap_.resize(size);
  }
  T& operator[](std::size_t i) noexcept { return size_ > kStackEntries ? heap_[i] : stack_[i]; }

 private:
  std::size_t size_;
  std::array<T, kStackEntries> stack_{};
  std::vector<T> heap_;
};

Status check_points_finite(std::span<const Point> points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].is_finite()) {
      return Status::invalid("control point " + std::to_string(i) + " has a NaN or infinite coordinate.");
    }
  }
  return Status::ok();
}

}  // namespace

std::size_t find_knot_span(std::span<const double> knots, int degree, double u) noexcept {
  if (degree < 0 || knots.size() < static_cast<std::size_t>(degree) + 2) return 0;
  const std::size_t p = static_cast<std::size_t>(degree);
  const std::size_t n = knots.size() - p - 1;
  // First knot > u among u_{p+1} .. u_{n-1}; the span is the one just before it, so k in [p, n-1].
  const auto first = knots.begin() + static_cast<std::ptrdiff_t>(p + 1);
  const auto last = knots.begin() + static_cast<std::ptrdiff_t>(n);
  std::size_t k = static_cast<std::size_t>(std::upper_bound(first, last, u) - knots.begin()) - 1;
  // Only the two end spans can be empty here: span n-1 (u at or past u_n with u_{n-1} == u_n: use the last
  // non-empty span, the right-end convention) and span p (u before u_{p+1} with u_p == u_{p+1}).
  if (knots[k] == knots[k + 1]) {
    if (k == n - 1) {
      while (k > p && knots[k] == knots[k + 1]) --k;
    } else {
      while (k < n - 1 && knots[k] == knots[k + 1]) ++k;
    }
  }
  return k;
}

namespace {

constexpr std::size_t kNoSpan = static_cast<std::size_t>(-1);

// The degree-0 span for the basis functions themselves. On the curve domain [u_p, u_n] it is the curve's
// span (find_knot_span, with its right-end convention), so the basis and de Boor agree there. Outside the
// domain the basis functions are still defined by eq. 6 on [u_0, u_m] — N_{0,1}(0.5) on knots 0,1,2,… is
// 0.5, not the extension of a domain polynomial — so the span is the literal half-open one there (u = u_m
// takes the last non-empty span), and beyond [u_0, u_m] every basis function is zero (kNoSpan).
std::size_t basis_span(std::span<const double> knots, std::size_t p, std::size_t n, double u) noexcept {
  if (u >= knots[p] && u <= knots[n]) return find_knot_span(knots, static_cast<int>(p), u);
  if (!(u >= knots.front() && u <= knots.back())) return kNoSpan;
  std::size_t k = static_cast<std::size_t>(std::upper_bound(knots.begin(), knots.end(), u) - knots.begin());
  k = k == 0 ? 0 : k - 1;
  if (k >= knots.size() - 1) k = knots.size() - 2;
  while (k > 0 && knots[k] == knots[k + 1]) --k;
  return knots[k] < knots[k + 1] ? k : kNoSpan;
}

}  // namespace

double bspline_basis(std::span<const double> knots, int degree, std::size_t i, double u) noexcept {
  if (degree < 0 || knots.size() < static_cast<std::size_t>(degree) + 2) return kNaN;
  const std::size_t p = static_cast<std::size_t>(degree);
  const std::size_t n = knots.size() - p - 1;
  if (i >= n) return 0.0;
  const std::size_t span = basis_span(knots, p, n, u);
  if (span == kNoSpan) return std::isnan(u) ? kNaN : 0.0;
  // N[j] holds N_{i+j, r} while raising r from 0 to p (Umetani, *Parametric Curve*, eq. 7); N_{i+j,0} is 1 on the chosen span.
  Scratch<double> basis(p + 1);
  for (std::size_t j = 0; j <= p; ++j) basis[j] = (i + j == span) ? 1.0 : 0.0;
  for (std::size_t r = 1; r <= p; ++r) {
    for (std::size_t j = 0; j + r <= p; ++j) {
      const std::size_t a = i + j;
      const double left_den = knots[a + r] - knots[a];
      const double right_den = knots[a + r + 1] - knots[a + 1];
      // 0/0 := 0: a zero-length support means that lower-degree basis function vanishes identically.
      const double left = left_den > 0.0 ? (u - knots[a]) / left_den * basis[j] : 0.0;
      const double right = right_den > 0.0 ? (knots[a + r + 1] - u) / right_den * basis[j + 1] : 0.0;
      basis[j] = left + right;
    }
  }
  return std::isnan(u) ? kNaN : basis[0];
}

Result<BSpline> BSpline::create(std::vector<Point> points, std::vector<double> knots, int degree) {
  CURVESCAN_PROPAGATE(check_points_finite(points));
  CURVESCAN_PROPAGATE(validate_knots(knots, points.size(), degree));
  return BSpline(std::move(points), std::move(knots), degree);
}

Result<BSpline> BSpline::clamped(std::vector<Point> points, int degree) {
  auto knots = clamped_knots(points.size(), degree);
  if (!knots) return knots.error();
  return create(std::move(points), std::move(knots).value(), degree);
}

Result<BSpline> BSpline::uniform(std::vector<Point> points, int degree) {
  auto knots = uniform_knots(points.size(), degree);
  if (!knots) return knots.error();
  return create(std::move(points), std::move(knots).value(), degree);
}

Result<BSpline> BSpline::closed(std::vector<Point> points, int degree) {
  CURVESCAN_PROPAGATE(check_points_finite(points));
  auto knots = periodic_knots(points.size(), degree);
  if (!knots) return knots.error();
  // Wrap the first p points to the end: the last p spans then blend back into the first (Gallivan, *Parametric Curves*).
  for (int j = 0; j < degree; ++j) points.push_back(points[static_cast<std::size_t>(j)]);
  return create(std::move(points), std::move(knots).value(), degree);
}

double BSpline::domain_start() const noexcept {
  return knots_[static_cast<std::size_t>(degree_)];
}
double BSpline::domain_end() const noexcept {
  return knots_[points_.size()];
}

std::size_t BSpline::find_span(double u) const noexcept {
  return find_knot_span(knots_, degree_, u);
}

double BSpline::basis(std::size_t i, double u) const noexcept {
  return bspline_basis(knots_, degree_, i, u);
}

Point BSpline::eval(double u) const noexcept {
  const std::size_t p = static_cast<std::size_t>(degree_);
  const std::size_t k = find_span(u);
  // de Boor: d_j starts as P_{k-p+j} and is lerped p times; the denominators are >= u_{k+1} - u_k > 0.
  Scratch<Point> d(p + 1);
  for (std::size_t j = 0; j <= p; ++j) d[j] = points_[k - p + j];
  for (std::size_t r = 1; r <= p; ++r) {
    for (std::size_t j = p; j >= r; --j) {
      const std::size_t i = k - p + j;
      const double alpha = (u - knots_[i]) / (knots_[i + p + 1 - r] - knots_[i]);
      d[j] = lerp(d[j - 1], d[j], alpha);
    }
  }
  return std::isnan(u) ? Point{kNaN, kNaN} : d[p];
}

Point BSpline::eval_reference(double u) const noexcept {
  Vec2 sum{};
  for (std::size_t i = 0; i < points_.size(); ++i) sum += points_[i].to_vec() * basis(i, u);
  return Point::from_vec(sum);
}

BSpline BSpline::derivative() const noexcept {
  const std::size_t n = points_.size();
  if (degree_ == 0) return BSpline(std::vector<Point>(n, Point{0.0, 0.0}), knots_, 0);
  const std::size_t p = static_cast<std::size_t>(degree_);
  std::vector<Point> coefficients(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double support = knots_[i + p + 1] - knots_[i + 1];
    coefficients[i] =
        support > 0.0 ? Point::from_vec((points_[i + 1] - points_[i]) * (static_cast<double>(p) / support))
                      : Point{0.0, 0.0};
  }
  std::vector<double> knots(knots_.begin() + 1, knots_.end() - 1);
  return BSpline(std::move(coefficients), std::move(knots), degree_ - 1);
}

BSpline BSpline::insert_knot(double u) const noexcept {
  if (!(u >= domain_start() && u <= domain_end())) return *this;
  const std::size_t p = static_cast<std::size_t>(degree_);
  if (static_cast<std::size_t>(std::count(knots_.begin(), knots_.end(), u)) >= p + 1) return *this;
  const std::size_t k = find_span(u);
  const std::size_t n = points_.size();
  std::vector<Point> refined(n + 1);
  for (std::size_t i = 0; i <= n; ++i) {
    if (i + p <= k) {
      refined[i] = points_[i];
    } else if (i >= k + 1) {
      refined[i] = points_[i - 1];
    } else {
      // k - p + 1 <= i <= k: u_{i+p} >= u_{k+1} > u_k >= u_i, so the denominator is positive.
      const double a = (u - knots_[i]) / (knots_[i + p] - knots_[i]);
      refined[i] = lerp(points_[i - 1], points_[i], a);
    }
  }
  std::vector<double> knots;
  knots.reserve(knots_.size() + 1);
  knots.insert(knots.end(), knots_.begin(), knots_.begin() + static_cast<std::ptrdiff_t>(k + 1));
  knots.push_back(u);
  knots.insert(knots.end(), knots_.begin() + static_cast<std::ptrdiff_t>(k + 1), knots_.end());
  return BSpline(std::move(refined), std::move(knots), degree_);
}

std::vector<double> BSpline::bezier_breakpoints() const noexcept {
  const std::size_t p = static_cast<std::size_t>(degree_);
  const std::size_t n = points_.size();
  std::vector<double> breaks;
  for (std::size_t k = p; k < n; ++k) {
    if (knots_[k] < knots_[k + 1]) breaks.push_back(knots_[k]);
  }
  breaks.push_back(knots_[n]);
  return breaks;
}

std::vector<Bezier> BSpline::to_beziers() const noexcept {
  // The same insertions as to_beziers_reference, in the same order and with the same arithmetic, but on a
  // growing prefix of the refined curve instead of a fresh copy of the whole curve per inserted knot
  // (a 10^5-point curve took minutes that way). Inserting v into span k changes only points k-p+1 .. k,
  // shifts the rest, and reads knots up to u_{k+p}; every later insertion is at a larger value, so it never
  // touches what lies left of its own window. The prefix therefore only needs the original points and knots
  // moved in up to the current window, and the insertion into it shifts at most about p + 1 entries: each
  // span costs O(p^2), the curve O(n p^2) (the streaming decomposition of The NURBS Book, Piegl & Tiller,
  // A5.6). The result is bit-for-bit that of to_beziers_reference (tests/unit/splines hold them to it).
  const std::size_t p = static_cast<std::size_t>(degree_);
  const std::vector<double> breaks = bezier_breakpoints();
  std::vector<Point> points;
  std::vector<double> knots;
  points.reserve(points_.size() + p * breaks.size());
  knots.reserve(knots_.size() + p * breaks.size());
  std::size_t next_point = 0, next_knot = 0;  // the first original entries not yet in the prefix
  auto pull_knots = [&](std::size_t count) {
    while (knots.size() < count && next_knot < knots_.size()) knots.push_back(knots_[next_knot++]);
  };
  auto pull_points = [&](std::size_t count) {
    while (points.size() < count && next_point < points_.size()) points.push_back(points_[next_point++]);
  };
  for (std::size_t b = 0; b < breaks.size(); ++b) {
    const double value = breaks[b];
    while (next_knot < knots_.size() && knots_[next_knot] <= value) knots.push_back(knots_[next_knot++]);
    // Only the knots pulled in for the previous window (at most about p + 1) can lie beyond `value`.
    std::size_t after = knots.size();
    while (after > 0 && knots[after - 1] > value) --after;
    std::size_t first = after;
    while (first > 0 && knots[first - 1] == value) --first;
    // find_knot_span's choice: the span ending at the last copy of an interior value; at the domain end
    // u_n (the last breakpoint) the last non-empty span, just before the first copy. Both are >= p.
    std::size_t k = b + 1 == breaks.size() ? first - 1 : after - 1;
    for (std::size_t multiplicity = after - first; multiplicity < p; ++multiplicity) {
      pull_knots(k + p + 1);
      pull_points(k + 1);
      const Point last = points[k];
      points.insert(points.begin() + static_cast<std::ptrdiff_t>(k + 1), last);
      // Downwards, so points[i - 1] and points[i] are still the unrefined P_{i-1}, P_i (insert_knot's rule).
      for (std::size_t i = k; i + p >= k + 1; --i) {
        const double a = (value - knots[i]) / (knots[i + p] - knots[i]);
        points[i] = lerp(points[i - 1], points[i], a);
      }
      knots.insert(knots.begin() + static_cast<std::ptrdiff_t>(k + 1), value);
      if (b + 1 != breaks.size()) ++k;  // an interior copy goes after the span, the end copy before it
    }
  }
  pull_knots(knots_.size() + p * breaks.size());
  pull_points(points_.size() + p * breaks.size());
  std::vector<Bezier> segments;
  segments.reserve(breaks.size());
  for (std::size_t k = p; k < points.size(); ++k) {
    if (!(knots[k] < knots[k + 1])) continue;
    const auto begin = points.begin() + static_cast<std::ptrdiff_t>(k - p);
    segments.emplace_back(std::vector<Point>(begin, begin + static_cast<std::ptrdiff_t>(p + 1)));
  }
  return segments;
}

std::vector<Bezier> BSpline::to_beziers_reference() const noexcept {
  const std::size_t p = static_cast<std::size_t>(degree_);
  BSpline refined = *this;
  for (const double value : bezier_breakpoints()) {
    auto multiplicity = [&] {
      return static_cast<std::size_t>(std::count(refined.knots_.begin(), refined.knots_.end(), value));
    };
    // Each insertion adds one copy (value is in the domain and below multiplicity p + 1), so this ends.
    for (std::size_t s = multiplicity(); s < p; ++s) refined = refined.insert_knot(value);
  }
  std::vector<Bezier> segments;
  for (std::size_t k = p; k < refined.points_.size(); ++k) {
    if (!(refined.knots_[k] < refined.knots_[k + 1])) continue;
    const auto begin = refined.points_.begin() + static_cast<std::ptrdiff_t>(k - p);
    segments.emplace_back(std::vector<Point>(begin, begin + static_cast<std::ptrdiff_t>(p + 1)));
  }
  return segments;
}

}  // namespace curvescan
