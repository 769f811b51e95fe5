// flatten_for_stroke: a Path -> FlatContours (stroke_contour.h), curves flattened in user space, with the
// true tangent of the curve at every vertex.
//
// Why tangents at every vertex: the outline (stroker_outline.cpp) sweeps the pen's normal segment from
// vertex to vertex, each piece being the hull of the true normal segments at the two ends of a chord
// (Nehab 2020 §3: the stroke of a C1 curve is the area swept by its normal segment). Where the stroke is
// bounded by a normal line — a butt or square cap, a dash end, a miter or bevel corner — the piece then
// ends exactly on that line; a rectangle perpendicular to the chord would poke (width/2)·sin(lean) past
// it, several pixels on a wide stroke. Between two vertices the piece's offset sides are chords of the
// offset curves: with the tangent turning by Δ along the chord they fall short of the offset curve by
// (R + h)·Δ²/8 (R the radius of curvature, h = width/2). The flattener bounds the R part (R·Δ²/8 is the
// chord's own deviation); the h part is bounded by cutting every curve (de Casteljau halving, Umetani,
// *Parametric Curve* eq. 8) into pieces whose control polygon edges lie within max_turn/2 of the first one:
// the tangent directions of a (rational, positive-weight) Bézier piece lie in the cone spanned by its control
// polygon's edges (the hodograph's convex hull property, Umetani, *Parametric Curve*, §2.3; the rational
// derivative is a positive combination of the differences P_j - P_i), so any two tangents of the piece differ
// by at most max_turn. The cone is conservative: a piece of a polynomial quadratic or cubic whose exact
// turn is within max_turn (turn_within: no inflection or cusp, the end tangents within max_turn) is not cut
// even where its control polygon fans wider, and one that turns one way by more is cut where its tangent has
// turned by max_turn (exact_turn_cut), not halved: 2,947 → 1,128 pieces on bench/stroke_bench.cpp's 20 px
// cubics (docs/stroking.md). Other pieces (inflections, cusps, rational curves) are halved. The ends of
// each piece get their exact tangents (the first and last non-zero control polygon edges); the flattener's
// vertices inside a piece get theirs from the piece itself (tangent_at_vertex: the vertex's parameter found
// by bracketed Newton steps, the tangent from de Casteljau). Pieces shorter than min_piece_length are not cut
// further: the cone of a piece holding a cusp never narrows, and the outline covers such a chord with the
// sectors its normal sweeps (a disc at a cusp). Work is bounded by kMaxTurnPieces per curve.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/flatten.h"
#include "curvescan/curves/rational_bezier.h"
#include "curvescan/raster/limits.h"
#include "stroke_contour.h"
#include "stroke_curve_piece.h"
#include "vector_length.h"

namespace curvescan::detail {
namespace {

// The control points in homogeneous form, written over `ctrl` (its storage is reused from curve to curve).
void homogeneous(std::span<const Point> points, std::span<const double> weights,
                 std::vector<HomogeneousPoint>& ctrl) {
  ctrl.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    ctrl[i] = {points[i].x * w, points[i].y * w, w};
  }
}

// The cutting below runs on homogeneous control points (rational curves) or on plain points (polynomial
// ones, every weight 1): a homogeneous step with w = 1 multiplies and divides by an exact 1 and halves
// 1 + 1, so both give the same doubles for a polynomial curve; the plain one skips that arithmetic.
Vec2 edge_between(const HomogeneousPoint& a, const HomogeneousPoint& b) noexcept {
  return {b.x / b.w - a.x / a.w, b.y / b.w - a.y / a.w};
}
Vec2 edge_between(Point a, Point b) noexcept {
  return b - a;
}
HomogeneousPoint halfway(const HomogeneousPoint& a, const HomogeneousPoint& b) noexcept {
  return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y), 0.5 * (a.w + b.w)};
}
Point halfway(Point a, Point b) noexcept {
  return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
}

// Whether the tangent of a polynomial quadratic or cubic piece (plain control points, n = 3 or 4) turns
// monotonically and by at most `angle` (< π/2) along it: then any two of its tangents differ by at most
// `angle`, what the cone test above asks, without cutting pieces whose control polygon fans wider than the
// curve turns. The hodograph of a Bézier of degree n is n·Σ B_i,n-1(t)·E_i with the control polygon's
// edges E_i (Umetani, *Parametric Curve*, §2.3). For a quadratic it is the segment E0 → E1, whose
// direction sweeps the short way from E0 to E1 when E0·E1 > 0 (the segment then misses the origin). For a
// cubic, B′ × B″ ∝ (1 − t)²(E0 × E1) + t(1 − t)(E0 × E2) + t²(E1 × E2), a quadratic in Bernstein form with
// coefficients E0 × E1, (E0 × E2)/2, E1 × E2: when all three have one strict sign, B′ × B″ keeps it on
// [0, 1] (the convex hull property), so B′ never vanishes (no cusp) and the direction turns one way only,
// from E0 to E2, by atan2(|E0 × E2|, E0·E2) when E0·E2 > 0 (the turn is then the short one, below π/2).
// The test compares squares (no square root): (E0 × E2)² <= sin²(angle)·|E0|²·|E2|². Rounding: a cross
// product's sign is misjudged only when it is within a few ulps of |Ei|·|Ej| of zero, where the direction
// could turn back by an angle of that order near the piece's end; `sin2_angle` carries a relative margin
// of 1e-9 (stroker_flatten's caller), orders of magnitude above it. Anything else (a zero edge, a sign
// change, a turn past the bound) answers false and the cone test decides.
// The way a cubic with control polygon edges e0, e1, e2 turns when B′ × B″ keeps one strict sign on [0, 1]
// (its Bernstein coefficients e0 × e1, (e0 × e2)/2, e1 × e2 all of it): +1 or -1, else 0 (turn_within).
int cubic_turn_sign(Vec2 e0, Vec2 e1, Vec2 e2) noexcept {
  const double a = e0.cross(e1), b = e0.cross(e2), d = e1.cross(e2);
  if (a > 0.0 && b > 0.0 && d > 0.0) return 1;
  if (a < 0.0 && b < 0.0 && d < 0.0) return -1;
  return 0;
}

bool turn_within(std::span<const Point> ctrl, double sin2_angle) noexcept {
  if (ctrl.size() == 3) {
    const Vec2 e0 = ctrl[1] - ctrl[0], e1 = ctrl[2] - ctrl[1];
    const double c = e0.cross(e1);
    return e0.dot(e1) > 0.0 && c * c <= sin2_angle * e0.dot(e0) * e1.dot(e1);
  }
  if (ctrl.size() != 4) return false;
  const Vec2 e0 = ctrl[1] - ctrl[0], e1 = ctrl[2] - ctrl[1], e2 = ctrl[3] - ctrl[2];
  const double b = e0.cross(e2);
  return cubic_turn_sign(e0, e1, e2) != 0 && e0.dot(e2) > 0.0 &&
         b * b <= sin2_angle * e0.dot(e0) * e2.dot(e2);
}

// Whether a piece is cut again: its control polygon is longer than `min_length` and its edges do not all
// lie within `angle` of each other (within angle/2 of the first non-zero edge: every non-zero edge points
// within asin(sin_half_angle) of it), sin_half_angle = sin(angle/2).
// The edges' lengths are measured once (up to kKeptLengths edges: a cubic has three), not again for the
// first edge's direction and the cone test (a square root each: 2 % of the 20 px cubic stroke's
// flattening, bench/stroke_bench.cpp). The same values, so the same answer.
template <class Control>
bool needs_cut(std::span<const Control> ctrl, double min_length, double sin_half_angle,
               double sin2_angle) noexcept {
  if constexpr (std::is_same_v<Control, Point>) {
    if (turn_within(ctrl, sin2_angle)) return false;
  }
  constexpr std::size_t kKeptLengths = 8;
  const std::size_t count = ctrl.size() - 1;
  const bool kept = count <= kKeptLengths;
  double lengths[kKeptLengths];
  const auto length_of = [&](std::size_t i, Vec2 edge) { return kept ? lengths[i] : vector_length(edge); };
  double length = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const double edge_length = vector_length(edge_between(ctrl[i], ctrl[i + 1]));
    if (kept) lengths[i] = edge_length;
    length += edge_length;
  }
  if (!(length > min_length)) return false;
  std::size_t first = 0;
  while (first < count && edge_between(ctrl[first], ctrl[first + 1]) == Vec2{}) ++first;
  if (first == count) return false;
  const Vec2 first_edge = edge_between(ctrl[first], ctrl[first + 1]);
  const Vec2 tangent = first_edge / length_of(first, first_edge);  // unit_vector(first_edge)
  for (std::size_t i = 0; i < count; ++i) {
    const Vec2 edge = edge_between(ctrl[i], ctrl[i + 1]);
    const double edge_length = length_of(i, edge);
    if (edge_length == 0.0) continue;
    if (!(tangent.dot(edge) > 0.0) || std::abs(tangent.cross(edge)) > sin_half_angle * edge_length)
      return true;
  }
  return false;
}

// Splits the n control points at `ctrl` at 1/2 (de Casteljau): the left half is written to `left`, the right
// half over `ctrl` (level k of the construction overwrites ctrl[0 .. n-1-k) and leaves ctrl[n-1-k], the right
// half's point n-1-k, in place).
template <class Control>
void split_half(Control* ctrl, std::size_t n, Control* left) noexcept {
  for (std::size_t k = 0; k < n; ++k) {
    left[k] = ctrl[0];
    for (std::size_t i = 0; i + 1 + k < n; ++i) ctrl[i] = halfway(ctrl[i], ctrl[i + 1]);
  }
}

// The parameter at which a polynomial quadratic or cubic piece (plain points, n = 3 or 4) whose tangent
// turns one way only (turn_within's sign condition holds) but by more than an angle α has turned by α:
// the piece is cut there, so its first part passes turn_within and the cuts follow the exact turn
// (about the fewest pieces, where halving makes up to twice as many). The hodograph H(t) = Σ B_i(t)·E_i
// (up to the degree) points along u when H(t) × u = 0 and H(t)·u > 0; with turn_within's sign condition
// the direction turns monotonically, so the first such t in (0, 1) is the one. Returns -1 when the piece
// does not qualify or no root is found (rounding): the caller halves the piece then.
// `cos_angle` and `sin_angle` are cos α and sin α, computed once per stroke (ContourFlattener).
double exact_turn_cut(std::span<const Point> ctrl, double cos_angle, double sin_angle) noexcept {
  const std::size_t n = ctrl.size();
  if (n != 3 && n != 4) return -1.0;
  const Vec2 e0 = ctrl[1] - ctrl[0], e1 = ctrl[2] - ctrl[1];
  const Vec2 e2 = n == 4 ? ctrl[3] - ctrl[2] : e1;
  double sign = 0.0;
  if (n == 3) {
    const double c = e0.cross(e1);
    sign = c > 0.0 ? 1.0 : c < 0.0 ? -1.0 : 0.0;
  } else {
    sign = cubic_turn_sign(e0, e1, e2);
  }
  const double length0 = vector_length(e0);
  if (sign == 0.0 || !(length0 > 0.0)) return -1.0;
  const Vec2 t0 = e0 / length0;
  const double c = cos_angle, s = sign * sin_angle;
  const Vec2 u{t0.x * c - t0.y * s, t0.x * s + t0.y * c};
  // H(t) × u in Bernstein form (a quadratic's hodograph as a degree-elevated quadratic: E0, (E0+E1)/2, E1).
  const Vec2 m = n == 4 ? e1 : (e0 + e1) * 0.5;
  const double q0 = e0.cross(u), q1 = m.cross(u), q2 = e2.cross(u);
  // q0 + 2(q1 - q0)t + (q0 - 2q1 + q2)t² = 0.
  const double A = q0 - 2.0 * q1 + q2, B = 2.0 * (q1 - q0), C = q0;
  double roots[2];
  int count = 0;
  if (std::abs(A) <= 1e-12 * (std::abs(B) + std::abs(C))) {
    if (B != 0.0) roots[count++] = -C / B;
  } else {
    const double disc = B * B - 4.0 * A * C;
    if (disc >= 0.0) {
      const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
      roots[count++] = q / A;
      if (q != 0.0) roots[count++] = C / q;
    }
  }
  double best = -1.0;
  for (int i = 0; i < count; ++i) {
    const double t = roots[i];
    if (!(t > 1e-9 && t < 1.0 - 1e-9) || (best >= 0.0 && t >= best)) continue;
    const double r = 1.0 - t;
    const Vec2 h = e0 * (r * r) + m * (2.0 * r * t) + e2 * (t * t);
    if (h.dot(u) > 0.0) best = t;
  }
  return best;
}

// Splits the n control points at `ctrl` at t (de Casteljau), as split_half does at 1/2.
void split_at(Point* ctrl, std::size_t n, double t, Point* left) noexcept {
  for (std::size_t k = 0; k < n; ++k) {
    left[k] = ctrl[0];
    for (std::size_t i = 0; i + 1 + k < n; ++i) ctrl[i] = ctrl[i] + (ctrl[i + 1] - ctrl[i]) * t;
  }
}

Point plain_point(const HomogeneousPoint& c) noexcept {
  return {c.x / c.w, c.y / c.w};
}
Point plain_point(Point p) noexcept {
  return p;
}

// The direction from the end point (from_back: the last one) to the first control point farther than
// `coincident` from it, in control polygon order: the curve's exact tangent there when coincident is 0
// (the first non-zero edge), the direction SVG 2 gives coincident points otherwise (StrokeCurveCuts::
// coincident_length). When every control point is that close, the exact tangent (the first non-zero
// edge); the zero vector when every control point is the same.
Vec2 end_tangent(std::span<const Point> points, bool from_back, double coincident = 0.0) noexcept {
  const std::size_t n = points.size();
  if (coincident > 0.0) {
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const Vec2 edge = from_back ? points[n - 1] - points[n - 2 - k] : points[k + 1] - points[0];
      if (vector_length(edge) > coincident) return unit_vector(edge);
    }
  }
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const Vec2 edge = from_back ? points[n - 1] - points[n - 2 - k] : points[k + 1] - points[0];
    if (edge != Vec2{}) return unit_vector(edge);
  }
  return {};
}

class ContourFlattener {
 public:
  ContourFlattener(double tolerance, const StrokeCurveCuts& cuts, std::vector<FlatContour>& out)
      : tolerance_(tolerance),
        cuts_(cuts),
        out_(out),
        sin_half_turn_(std::sin(0.5 * cuts.max_turn)),
        sin2_turn_(std::sin(cuts.max_turn) * std::sin(cuts.max_turn) * (1.0 - 1e-9)),
        cos_cut_turn_(std::cos(cuts.max_turn * (1.0 - 1e-6))),
        sin_cut_turn_(std::sin(cuts.max_turn * (1.0 - 1e-6))) {}

  void move_to(Point p) {
    finish();
    current_.vertices.assign(1, FlatVertex{p, {}, {}, false});
    ++vertex_count_;
    current_.closed = false;
    segment_count_ = 0;
    open_ = true;
  }

  Status segment(std::span<const Point> points, std::span<const double> weights) {
    const Vec2 start_tangent = end_tangent(points, false, cuts_.coincident_length);
    if (start_tangent == Vec2{}) return Status::ok();  // zero length: no direction, nothing to draw
    const Vec2 last_tangent = end_tangent(points, true, cuts_.coincident_length);
    curve_start_tangent_ = start_tangent;
    curve_end_tangent_ = last_tangent;

    FlatVertex& joint = current_.vertices.back();
    joint.corner = segment_count_ > 0;
    joint.tangent_out = start_tangent;
    joint.piece = -1;  // a line; flatten_piece sets the pieces of a curve
    ++segment_count_;

    if (points.size() > 2) CURVESCAN_PROPAGATE(flatten_curve(points, weights));
    push({points.back(), last_tangent, {}, false});
    if (vertex_count_ > cuts_.max_vertices) return over_budget();
    return Status::ok();
  }

  // Ends the contour as closed; the closing line, if any, was given to segment() first.
  void close() {
    current_.closed = true;
    if (current_.vertices.size() > 1) {
      // The last vertex is the start again: fold it into vertex 0, which becomes the closing join.
      current_.vertices.front().tangent_in = current_.vertices.back().tangent_in;
      current_.vertices.front().corner = true;
      current_.vertices.pop_back();
    }
    finish();
  }

  void finish() {
    if (!open_) return;
    out_.push_back(std::move(current_));
    current_ = {};
    open_ = false;
  }

 private:
  void push(const FlatVertex& v) {
    FlatVertex& back = current_.vertices.back();
    if (back.point == v.point) {
      if (v.tangent_in != Vec2{}) back.tangent_in = v.tangent_in;
      return;
    }
    current_.vertices.push_back(v);
    ++vertex_count_;
  }

  Status over_budget() const {
    return Error{ErrorKind::kLimitExceeded,
                 "the stroke's flattened outline would have more than " + std::to_string(cuts_.max_vertices) +
                     " vertices, the stroke outline budget (a tolerance too fine for "
                     "the path's size)"};
  }

  // Cuts the curve into pieces of narrow tangent cone (explicit stack, at most kMaxTurnPieces pieces; see
  // the header essay) and flattens each in order. A curve whose whole cone is narrow is one piece.
  Status flatten_curve(std::span<const Point> points, std::span<const double> weights) {
    at_curve_start_ = true;
    if (weights.empty()) return cut_and_flatten<Point>(points, {}, point_stack_);
    homogeneous(points, weights, piece_);
    return cut_and_flatten<HomogeneousPoint>(piece_, weights, stack_);
  }

  // flatten_curve on the control points `control` (plain points for a polynomial curve, homogeneous ones
  // for a rational one; `weights` empty for the former), the pieces waiting on `stack`, n points each, in
  // one array (no allocation per piece): a piece that needs a cut is replaced by its right half, then its
  // left half on top.
  template <class Control>
  Status cut_and_flatten(std::span<const Control> control, std::span<const double> weights,
                         std::vector<Control>& stack) {
    const bool cut = cuts_.max_turn < std::numbers::pi / 2;
    const std::size_t n = control.size();
    stack.assign(control.begin(), control.end());
    int pieces = 0;
    while (!stack.empty()) {
      const std::size_t top = stack.size() - n;
      const auto pieces_waiting = static_cast<int>(top / n);
      if (vertex_count_ > cuts_.max_vertices) return over_budget();
      if (cut && pieces + pieces_waiting < kMaxTurnPieces &&
          needs_cut(std::span<const Control>(stack).subspan(top, n), cuts_.min_piece_length, sin_half_turn_,
                    sin2_turn_)) {
        stack.resize(stack.size() + n);
        Control* piece = stack.data() + top;
        if constexpr (std::is_same_v<Control, Point>) {
          // The cut at the exact turn, unless either part would be shorter than the piece floor: where the
          // tangent turns that fast (beside a cusp, or a control point nearly on an end point, whose end
          // takes the next control point's direction: StrokeCurveCuts::coincident_length) the halving cuts
          // down to the floor as before, so that no cut lands inside the fast turn (a cut 2e-8 px from such
          // an end, its tangent turned by max_turn, tilted the last normal segment by max_turn beside a
          // butt cap along the chord's normal: tests/oracle/stroke_near_coincident_test.cpp).
          const double t = exact_turn_cut(std::span<const Point>(piece, n), cos_cut_turn_, sin_cut_turn_);
          if (t > 0.0 && n <= 4) {
            Point whole[4];
            std::copy(piece, piece + n, whole);
            split_at(piece, n, t, piece + n);
            double first_length = 0.0, rest_length = 0.0;
            for (std::size_t i = 0; i + 1 < n; ++i) {
              first_length += vector_length(piece[n + i + 1] - piece[n + i]);
              rest_length += vector_length(piece[i + 1] - piece[i]);
            }
            if (first_length > cuts_.min_piece_length && rest_length > cuts_.min_piece_length) continue;
            std::copy(whole, whole + n, piece);
          }
        }
        split_half(piece, n, piece + n);
        continue;
      }
      ++pieces;
      piece_points_.resize(n);
      piece_weights_.resize(n);
      for (std::size_t i = 0; i < n; ++i) {
        piece_points_[i] = plain_point(stack[top + i]);
        if constexpr (std::is_same_v<Control, HomogeneousPoint>) piece_weights_[i] = stack[top + i].w;
      }
      stack.resize(top);
      CURVESCAN_PROPAGATE(flatten_piece(
          piece_points_, weights.empty() ? std::span<const double>() : piece_weights_, stack.empty()));
    }
    return Status::ok();
  }

  // Flattens one piece and appends its vertices with tangents interpolated between the piece's exact end
  // tangents by arc length; the last vertex of the curve's last piece is left out (segment() pushes the
  // exact end point with its tangent). At the curve's own ends (the first piece's start, the last piece's
  // end) the tangents are the curve's end directions, coincident control points skipped (segment()).
  Status flatten_piece(std::span<const Point> points, std::span<const double> weights, bool last) {
    const Vec2 start_direction = end_tangent(points, false);  // computed once: it was twice per piece
    if (start_direction == Vec2{}) return Status::ok();       // a piece of zero length
    const Vec2 t0 = at_curve_start_ ? curve_start_tangent_ : start_direction;
    at_curve_start_ = false;
    const Vec2 t1 = last ? curve_end_tangent_ : end_tangent(points, true);
    // The piece's start tangent is exact; where it differs from the previous piece's end tangent the
    // curve has a cusp at the cut (a vanishing derivative exactly there): the outline then draws a round
    // join between the two, the half disc Nehab's stroke has at a cusp.
    Vec2& previous_out = current_.vertices.back().tangent_out;
    if (!(previous_out.dot(t0) > 0.0 && std::abs(previous_out.cross(t0)) <= 1e-9)) previous_out = t0;
    scratch_.clear();
    // One piece may not make more vertices than the budget has left (+1, so that reaching it is seen):
    // a piece far too fine for the budget then costs at most that much flattening, not kMaxFlattenSegments.
    const std::size_t vertices_left =
        cuts_.max_vertices > vertex_count_ ? cuts_.max_vertices - vertex_count_ : 0;
    const std::size_t piece_cap = std::min(kMaxFlattenSegments, vertices_left + 1);
    const FlattenOutcome outcome =
        weights.empty()
            ? flatten_bezier(points, tolerance_, scratch_, std::max<std::size_t>(piece_cap, 1))
            : flatten_rational(points, weights, tolerance_, scratch_, std::max<std::size_t>(piece_cap, 1));
    if (outcome == FlattenOutcome::kSegmentLimit && scratch_.size() + 1 >= piece_cap) return over_budget();
    if (outcome == FlattenOutcome::kNonFinite || outcome == FlattenOutcome::kInvalid) {
      return Error{ErrorKind::kLimitExceeded,
                   "a curve of the stroked path could not be flattened: its coordinates overflow double "
                   "arithmetic"};
    }
    // The chords' lengths, measured once: their running sum places each vertex's interpolated tangent.
    chord_lengths_.resize(scratch_.size());
    double total = 0.0;
    Point previous = points.front();
    for (std::size_t j = 0; j < scratch_.size(); ++j) {
      chord_lengths_[j] = vector_length(scratch_[j] - previous);
      total += chord_lengths_[j];
      previous = scratch_[j];
    }
    const std::size_t keep = last ? scratch_.size() - 1 : scratch_.size();
    // The piece's homogeneous control points, for the vertices' tangents (a piece flattened to one chord has
    // no vertex inside) and the dasher's pieces.
    if (cuts_.keep_pieces || scratch_.size() > 1) homogeneous(points, weights, homogeneous_);
    std::int32_t piece = -1;
    if (cuts_.keep_pieces && current_.piece_ends.size() < static_cast<std::size_t>(INT32_MAX)) {
      piece = static_cast<std::int32_t>(current_.piece_ends.size());
      current_.piece_control.insert(current_.piece_control.end(), homogeneous_.begin(), homogeneous_.end());
      current_.piece_ends.push_back(current_.piece_control.size());
    }
    current_.vertices.back().piece = piece;  // the chord from the last vertex into this piece
    const Vec2 axis = points.back() - points.front();
    double along = 0.0;
    for (std::size_t j = 0; j < keep; ++j) {
      along += chord_lengths_[j];
      Vec2 tangent = t1;
      if (j + 1 < scratch_.size()) {
        tangent = interpolate_tangent(t0, t1, total > 0.0 ? along / total : 0.0);
        if (axis != Vec2{}) tangent = tangent_at_vertex(scratch_[j], axis, tangent);
      }
      push({scratch_[j], tangent, tangent, false, piece});
    }
    return Status::ok();
  }

  // The exact tangent at the flattener's vertex q of the current piece (homogeneous_): q lies on the
  // piece (a de Casteljau split point, flatten.h) and the piece is monotone along `axis`, its chord
  // (stroke_curve_piece.h). An interpolated tangent can be off by a fraction of the piece's turn where
  // curvature varies, which a cap h away from the curve multiplies by h. Falls back to `guess` if the root
  // is not bracketed (rounding at the ends).
  Vec2 tangent_at_vertex(Point q, Vec2 axis, Vec2 guess) const noexcept {
    const std::optional<CurvePoint> on_curve = curve_point_along(homogeneous_, q, axis);
    return on_curve && on_curve->tangent.dot(guess) > 0.0 ? on_curve->tangent : guess;
  }

  double tolerance_;
  StrokeCurveCuts cuts_;
  std::vector<FlatContour>& out_;
  double sin_half_turn_;                 // sin(cuts_.max_turn / 2), needs_cut's bound
  double sin2_turn_;                     // sin²(cuts_.max_turn), less a relative 1e-9: turn_within's bound
  // exact_turn_cut's turn: max_turn less 1e-6 of it, so that the cut's first part, its control points
  // rounded, passes turn_within (whose margin is 1e-9); its cosine and sine.
  double cos_cut_turn_, sin_cut_turn_;
  std::vector<HomogeneousPoint> stack_;  // cut_and_flatten's pieces to cut, n control points each: rational
  std::vector<Point> point_stack_;       // and polynomial curves
  std::vector<HomogeneousPoint> piece_, homogeneous_;
  std::vector<Point> piece_points_;
  std::vector<double> piece_weights_;
  FlatContour current_;
  std::vector<Point> scratch_;
  std::vector<double> chord_lengths_;             // flatten_piece: |scratch_[j] - the vertex before it|
  Vec2 curve_start_tangent_, curve_end_tangent_;  // the directions at the ends of the curve in segment()
  bool at_curve_start_ = false;                   // no piece of the curve flattened yet
  int segment_count_ = 0;
  std::size_t vertex_count_ = 0;  // over all contours, checked against cuts_.max_vertices
  bool open_ = false;
};

}  // namespace

Status flatten_for_stroke(const Path& path, double curve_tolerance, const StrokeCurveCuts& cuts,
                          std::vector<FlatContour>& out) {
  ContourFlattener flattener(curve_tolerance, cuts, out);
  bool open = false;
  for (const PathElement& element : path) {
    switch (element.verb) {
      case PathVerb::kMove:
        flattener.move_to(element.start);
        open = true;
        break;
      case PathVerb::kClose: {
        const Point closing_line[2] = {element.start, element.end};
        CURVESCAN_PROPAGATE(flattener.segment(closing_line, {}));
        flattener.close();
        open = false;
        break;
      }
      default:
        CURVESCAN_PROPAGATE(flattener.segment(element.points, element.weights));
        break;
    }
  }
  if (open) flattener.finish();
  return Status::ok();
}

double contour_length(const FlatContour& contour) noexcept {
  double length = 0.0;
  const std::size_t n = contour.vertices.size();
  for (std::size_t i = 0; i + 1 < n; ++i)
    length += vector_length(contour.vertices[i + 1].point - contour.vertices[i].point);
  if (contour.closed && n > 1)
    length += vector_length(contour.vertices[0].point - contour.vertices[n - 1].point);
  return length;
}

}  // namespace curvescan::detail
