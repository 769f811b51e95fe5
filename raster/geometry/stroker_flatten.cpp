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
// by at most max_turn. The ends of each piece get their exact tangents (the first and last non-zero control
// polygon edges); the flattener's vertices inside a piece get theirs from the piece itself
// (tangent_at_vertex: the vertex's parameter found by bracketed Newton steps, the tangent from de Casteljau).
// Pieces shorter than min_piece_length are not cut further: the cone of a piece holding a cusp never narrows,
// and the outline covers such a chord with the sectors its normal sweeps (a disc at a cusp). Work is bounded
// by kMaxTurnPieces per curve.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/flatten.h"
#include "curvescan/curves/rational_bezier.h"
#include "stroke_contour.h"
#include "stroke_curve_piece.h"
#include "vector_length.h"

namespace curvescan::detail {
namespace {

// True when every non-zero edge of the control polygon points within asin(sin_limit) of `tangent`.
bool control_polygon_in_cone(std::span<const HomogeneousPoint> ctrl, Vec2 tangent,
                             double sin_limit) noexcept {
  for (std::size_t i = 0; i + 1 < ctrl.size(); ++i) {
    const Vec2 edge{ctrl[i + 1].x / ctrl[i + 1].w - ctrl[i].x / ctrl[i].w,
                    ctrl[i + 1].y / ctrl[i + 1].w - ctrl[i].y / ctrl[i].w};
    const double length = vector_length(edge);
    if (length == 0.0) continue;
    if (!(tangent.dot(edge) > 0.0) || std::abs(tangent.cross(edge)) > sin_limit * length) return false;
  }
  return true;
}

// The control points in homogeneous form, written over `ctrl` (its storage is reused from curve to curve).
void homogeneous(std::span<const Point> points, std::span<const double> weights,
                 std::vector<HomogeneousPoint>& ctrl) {
  ctrl.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    ctrl[i] = {points[i].x * w, points[i].y * w, w};
  }
}

double control_polygon_length(std::span<const HomogeneousPoint> ctrl) noexcept {
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < ctrl.size(); ++i) {
    length += vector_length({ctrl[i + 1].x / ctrl[i + 1].w - ctrl[i].x / ctrl[i].w,
                             ctrl[i + 1].y / ctrl[i + 1].w - ctrl[i].y / ctrl[i].w});
  }
  return length;
}

// Splits `ctrl` at 1/2 into `left` and `right` (de Casteljau, homogeneous); `level` is scratch.
void split_half(std::span<const HomogeneousPoint> ctrl, std::vector<HomogeneousPoint>& left,
                std::vector<HomogeneousPoint>& right, std::vector<HomogeneousPoint>& level) {
  level.assign(ctrl.begin(), ctrl.end());
  const std::size_t n = ctrl.size();
  left.resize(n);
  right.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    left[k] = level[0];
    right[n - 1 - k] = level[n - 1 - k];
    for (std::size_t i = 0; i + 1 + k < n; ++i) {
      level[i] = {0.5 * (level[i].x + level[i + 1].x), 0.5 * (level[i].y + level[i + 1].y),
                  0.5 * (level[i].w + level[i + 1].w)};
    }
  }
}

// True when the control polygon's edges all lie within `angle` of each other (within angle/2 of the
// first non-zero edge), given sin_half_angle = sin(angle/2).
bool narrow_cone(std::span<const HomogeneousPoint> ctrl, double sin_half_angle) noexcept {
  for (std::size_t i = 0; i + 1 < ctrl.size(); ++i) {
    const Vec2 edge{ctrl[i + 1].x / ctrl[i + 1].w - ctrl[i].x / ctrl[i].w,
                    ctrl[i + 1].y / ctrl[i + 1].w - ctrl[i].y / ctrl[i].w};
    if (edge != Vec2{}) return control_polygon_in_cone(ctrl, unit_vector(edge), sin_half_angle);
  }
  return true;
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
      : tolerance_(tolerance), cuts_(cuts), out_(out), sin_half_turn_(std::sin(0.5 * cuts.max_turn)) {}

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
    const bool cut = cuts_.max_turn < std::numbers::pi / 2;
    // The stack of pieces still to cut, each n control points, in one array (no allocation per piece).
    const std::size_t n = points.size();
    homogeneous(points, weights, piece_);
    stack_.assign(piece_.begin(), piece_.end());
    at_curve_start_ = true;
    int pieces = 0;
    while (!stack_.empty()) {
      piece_.assign(stack_.end() - static_cast<std::ptrdiff_t>(n), stack_.end());
      stack_.resize(stack_.size() - n);
      const std::span<const HomogeneousPoint> piece = piece_;
      const auto pieces_waiting = static_cast<int>(stack_.size() / n);
      if (vertex_count_ > cuts_.max_vertices) return over_budget();
      if (cut && pieces + pieces_waiting < kMaxTurnPieces &&
          control_polygon_length(piece) > cuts_.min_piece_length && !narrow_cone(piece, sin_half_turn_)) {
        split_half(piece, left_, right_, level_);
        stack_.insert(stack_.end(), right_.begin(), right_.end());
        stack_.insert(stack_.end(), left_.begin(), left_.end());
        continue;
      }
      ++pieces;
      piece_points_.resize(piece.size());
      piece_weights_.resize(piece.size());
      for (std::size_t i = 0; i < piece.size(); ++i) {
        piece_points_[i] = {piece[i].x / piece[i].w, piece[i].y / piece[i].w};
        piece_weights_[i] = piece[i].w;
      }
      CURVESCAN_PROPAGATE(flatten_piece(
          piece_points_, weights.empty() ? std::span<const double>() : piece_weights_, stack_.empty()));
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
    homogeneous(points, weights, homogeneous_);
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
  double sin_half_turn_;                 // sin(cuts_.max_turn / 2), narrow_cone's bound
  std::vector<HomogeneousPoint> stack_;  // flatten_curve's pieces to cut, n control points each
  std::vector<HomogeneousPoint> piece_, left_, right_, level_, homogeneous_;
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
