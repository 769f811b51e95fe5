// flatten_for_stroke: a Path -> FlatContours (stroke_contour.h), curves flattened in user space.
//
// Why the ends of a curve are refined: the outline (stroker_outline.cpp) sweeps the pen's normal segment
// along the polyline, so each chord's piece is a rectangle perpendicular to the chord, where the true
// stroke sweeps the normal of the curve. Inside a curve the difference is covered by the neighbouring
// pieces and the round joins; but where the stroke is bounded by a normal line — a butt or square cap, a
// miter or bevel join — a rectangle whose chord leans by an angle δ from the true tangent pokes
// (width/2)·sin δ past that line: several pixels for a 40 px stroke on a gentle curve, with chords that
// only respect the Hausdorff tolerance. So within `end_region` (arc length, measured by the control
// polygon) of each end, the curve is cut (de Casteljau halving, seed 000 eq. 8) into pieces whose
// tangents all lie within `end_angle` of each other, and each piece is flattened on its own. The tangent
// directions of a (rational, positive-weight) Bézier piece lie in the cone spanned by its control
// polygon's edges (the hodograph's convex hull property, seed 000 §2.3; the rational derivative is a
// positive combination of the differences P_j - P_i), and every chord is an average of tangents, so the
// test on the control polygon bounds every chord. Work is bounded by kMaxEndPieces per end.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/flatten.h"
#include "curvescan/curves/rational_bezier.h"
#include "stroke_contour.h"

namespace curvescan::detail {
namespace {

struct Homogeneous {
  double x, y, w;
};

// True when every non-zero edge of the control polygon points within asin(sin_limit) of `tangent`.
bool control_polygon_in_cone(const std::vector<Homogeneous>& ctrl, Vec2 tangent, double sin_limit) noexcept {
  for (std::size_t i = 0; i + 1 < ctrl.size(); ++i) {
    const Vec2 edge{ctrl[i + 1].x / ctrl[i + 1].w - ctrl[i].x / ctrl[i].w,
                    ctrl[i + 1].y / ctrl[i + 1].w - ctrl[i].y / ctrl[i].w};
    const double length = edge.length();
    if (length == 0.0) continue;
    if (!(tangent.dot(edge) > 0.0) || std::abs(tangent.cross(edge)) > sin_limit * length) return false;
  }
  return true;
}

// Replaces `ctrl` by the control points of its left half [0, 1/2] (in-place de Casteljau: after step k,
// ctrl[k] is the level-k point b_0^k, which is the left half's k-th control point).
void keep_left_half(std::vector<Homogeneous>& ctrl) noexcept {
  const std::size_t n = ctrl.size();
  for (std::size_t k = 1; k < n; ++k) {
    for (std::size_t i = n - 1; i >= k; --i) {
      ctrl[i] = {0.5 * (ctrl[i - 1].x + ctrl[i].x), 0.5 * (ctrl[i - 1].y + ctrl[i].y),
                 0.5 * (ctrl[i - 1].w + ctrl[i].w)};
    }
  }
}

std::vector<Homogeneous> homogeneous(std::span<const Point> points, std::span<const double> weights,
                                     bool from_back) {
  std::vector<Homogeneous> ctrl(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::size_t j = from_back ? points.size() - 1 - i : i;
    const double w = weights.empty() ? 1.0 : weights[j];
    ctrl[i] = {points[j].x * w, points[j].y * w, w};
  }
  return ctrl;
}

double control_polygon_length(const std::vector<Homogeneous>& ctrl) noexcept {
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < ctrl.size(); ++i) {
    length += std::hypot(ctrl[i + 1].x / ctrl[i + 1].w - ctrl[i].x / ctrl[i].w,
                         ctrl[i + 1].y / ctrl[i + 1].w - ctrl[i].y / ctrl[i].w);
  }
  return length;
}

// The largest t = 2^-k (k <= kMaxEndHalvings) such that the piece [0, t] of the curve (control points
// given from the end of interest on) has a control polygon no longer than `region` (>= its arc length).
double end_region_parameter(std::span<const Point> points, std::span<const double> weights, bool from_back,
                            double region) {
  std::vector<Homogeneous> ctrl = homogeneous(points, weights, from_back);
  double t = 1.0;
  for (int halving = 0; halving < kMaxEndHalvings && control_polygon_length(ctrl) > region; ++halving) {
    keep_left_half(ctrl);
    t *= 0.5;
  }
  return t;
}

// Splits `ctrl` at 1/2 into `left` and `right` (de Casteljau, homogeneous).
void split_half(const std::vector<Homogeneous>& ctrl, std::vector<Homogeneous>& left,
                std::vector<Homogeneous>& right) {
  std::vector<Homogeneous> level = ctrl;
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
// first non-zero edge).
bool narrow_cone(const std::vector<Homogeneous>& ctrl, double angle) noexcept {
  for (std::size_t i = 0; i + 1 < ctrl.size(); ++i) {
    const Vec2 edge{ctrl[i + 1].x / ctrl[i + 1].w - ctrl[i].x / ctrl[i].w,
                    ctrl[i + 1].y / ctrl[i + 1].w - ctrl[i].y / ctrl[i].w};
    if (edge.length() > 0.0) return control_polygon_in_cone(ctrl, edge.normalized(), std::sin(0.5 * angle));
  }
  return true;
}

class ContourFlattener {
 public:
  ContourFlattener(double tolerance, double end_angle, double end_region, bool whole, std::vector<FlatContour>& out)
      : tolerance_(tolerance), end_angle_(end_angle), end_region_(end_region), whole_(whole), out_(out) {}

  [[nodiscard]] double end_angle() const noexcept { return end_angle_; }

  void move_to(Point p) {
    finish();
    current_.vertices.assign(1, FlatVertex{p, {}, {}, false});
    current_.closed = false;
    segment_count_ = 0;
    open_ = true;
  }

  Status segment(std::span<const Point> points, std::span<const double> weights, bool refine_start,
                 bool refine_end) {
    const Point start = points.front();
    const Point end = points.back();
    const auto first_off = std::find_if(points.begin(), points.end(), [&](Point p) { return p != start; });
    if (first_off == points.end()) return Status::ok();  // zero length: no direction, nothing to draw
    const auto last_off = std::find_if(points.rbegin(), points.rend(), [&](Point p) { return p != end; });
    const Vec2 start_tangent = (*first_off - start).normalized();
    const Vec2 end_tangent = (end - *last_off).normalized();

    FlatVertex& joint = current_.vertices.back();
    joint.corner = segment_count_ > 0;
    joint.tangent_out = start_tangent;
    ++segment_count_;

    if (points.size() > 2) CURVESCAN_PROPAGATE(flatten_curve(points, weights, refine_start, refine_end));
    push({end, end_tangent, {}, false});
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
    if (current_.vertices.back().point == v.point) {
      if (v.tangent_in != Vec2{}) current_.vertices.back().tangent_in = v.tangent_in;
      return;
    }
    current_.vertices.push_back(v);
  }

  // Appends the curve's interior vertices (smooth), its end regions refined as the header essay explains.
  Status flatten_curve(std::span<const Point> points, std::span<const double> weights, bool refine_start,
                       bool refine_end) {
    if (!(end_region_ > 0.0 && end_angle_ < std::numbers::pi / 2)) refine_start = refine_end = false;
    if (whole_ && end_angle_ < std::numbers::pi / 2) return refine(points, weights, 0.0, 1.0, true);
    if (!refine_start && !refine_end) return flatten_piece(points, weights, true);
    const double a = refine_start ? end_region_parameter(points, weights, false, end_region_) : 0.0;
    const double b = refine_end ? 1.0 - end_region_parameter(points, weights, true, end_region_) : 1.0;
    if ((refine_start && refine_end && a >= b) || a >= 1.0 || b <= 0.0) return refine(points, weights, 0.0, 1.0, true);
    if (refine_start) CURVESCAN_PROPAGATE(refine(points, weights, 0.0, a, false));
    CURVESCAN_PROPAGATE(flatten_piece_between(points, weights, a, b, !refine_end));
    if (refine_end) CURVESCAN_PROPAGATE(refine(points, weights, b, 1.0, true));
    return Status::ok();
  }

  Status flatten_piece_between(std::span<const Point> points, std::span<const double> weights, double t0,
                               double t1, bool last) {
    if (weights.empty()) {
      const Bezier piece = Bezier(std::vector<Point>(points.begin(), points.end())).subsegment(t0, t1);
      return flatten_piece(piece.points(), {}, last);
    }
    const RationalBezier piece = RationalBezier(std::vector<Point>(points.begin(), points.end()),
                                                std::vector<double>(weights.begin(), weights.end()))
                                     .subsegment(t0, t1);
    return flatten_piece(piece.points(), piece.weights(), last);
  }

  // Cuts [t0, t1] into pieces whose tangents lie within end_angle_ of each other (explicit stack, at most
  // kMaxEndPieces pieces) and flattens each in order.
  Status refine(std::span<const Point> points, std::span<const double> weights, double t0, double t1,
                bool last) {
    std::vector<Homogeneous> whole;
    if (t0 == 0.0 && t1 == 1.0) {
      whole = homogeneous(points, weights, false);
    } else if (weights.empty()) {
      const Bezier piece = Bezier(std::vector<Point>(points.begin(), points.end())).subsegment(t0, t1);
      whole = homogeneous(piece.points(), {}, false);
    } else {
      const RationalBezier piece = RationalBezier(std::vector<Point>(points.begin(), points.end()),
                                                  std::vector<double>(weights.begin(), weights.end()))
                                       .subsegment(t0, t1);
      whole = homogeneous(piece.points(), piece.weights(), false);
    }
    std::vector<std::vector<Homogeneous>> stack{std::move(whole)};
    std::vector<Homogeneous> left, right;
    int pieces = 0;
    while (!stack.empty()) {
      std::vector<Homogeneous> piece = std::move(stack.back());
      stack.pop_back();
      if (pieces + static_cast<int>(stack.size()) < kMaxEndPieces && !narrow_cone(piece, end_angle_)) {
        split_half(piece, left, right);
        stack.push_back(right);
        stack.push_back(left);
        continue;
      }
      ++pieces;
      piece_points_.resize(piece.size());
      piece_weights_.resize(piece.size());
      for (std::size_t i = 0; i < piece.size(); ++i) {
        piece_points_[i] = {piece[i].x / piece[i].w, piece[i].y / piece[i].w};
        piece_weights_[i] = piece[i].w;
      }
      CURVESCAN_PROPAGATE(flatten_piece(piece_points_, weights.empty() ? std::span<const double>() : piece_weights_,
                                        last && stack.empty()));
    }
    return Status::ok();
  }

  // Flattens one piece and appends its vertices as smooth ones; the last vertex of the curve's last piece
  // is left out (segment() pushes the exact end point with its tangent).
  Status flatten_piece(std::span<const Point> points, std::span<const double> weights, bool last) {
    scratch_.clear();
    const FlattenOutcome outcome = weights.empty() ? flatten_bezier(points, tolerance_, scratch_)
                                                   : flatten_rational(points, weights, tolerance_, scratch_);
    if (outcome == FlattenOutcome::kNonFinite || outcome == FlattenOutcome::kInvalid) {
      return Error{ErrorKind::kLimitExceeded,
                   "a curve of the stroked path could not be flattened: its coordinates overflow double "
                   "arithmetic"};
    }
    const std::size_t keep = last ? scratch_.size() - 1 : scratch_.size();
    for (std::size_t j = 0; j < keep; ++j) push({scratch_[j], {}, {}, false});
    return Status::ok();
  }

  double tolerance_;
  double end_angle_;
  double end_region_;
  bool whole_;
  std::vector<FlatContour>& out_;
  std::vector<Point> piece_points_;
  std::vector<double> piece_weights_;
  FlatContour current_;
  std::vector<Point> scratch_;
  int segment_count_ = 0;
  bool open_ = false;
};

}  // namespace

namespace {

struct SegmentView {
  std::span<const Point> points;
  std::span<const double> weights;
  Vec2 start_tangent, end_tangent;  // zero for a zero-length segment
};

// Feeds one contour's segments to the flattener, deciding for each end whether it needs refinement: an
// open end when caps need it, a corner when joins need it and the tangents actually turn there (a
// tangent-continuous junction, e.g. between the conics of a circle, is no corner for the stroke).
Status flatten_contour(ContourFlattener& flattener, std::vector<SegmentView>& segments, bool closed,
                       const StrokeEndRefinement& refinement) {
  for (SegmentView& s : segments) {
    const Point start = s.points.front(), end = s.points.back();
    const auto first_off = std::find_if(s.points.begin(), s.points.end(), [&](Point p) { return p != start; });
    if (first_off == s.points.end()) continue;
    const auto last_off = std::find_if(s.points.rbegin(), s.points.rend(), [&](Point p) { return p != end; });
    s.start_tangent = (*first_off - start).normalized();
    s.end_tangent = (end - *last_off).normalized();
  }
  std::vector<std::size_t> drawn;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (segments[i].start_tangent != Vec2{}) drawn.push_back(i);
  }
  const double sin_smooth = std::sin(flattener.end_angle());
  const auto turns = [&](Vec2 u, Vec2 v) { return !(u.dot(v) > 0.0 && std::abs(u.cross(v)) <= sin_smooth); };
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const SegmentView& s = segments[k];
    const auto position = std::find(drawn.begin(), drawn.end(), k);
    bool refine_start = false, refine_end = false;
    if (position != drawn.end()) {
      const std::size_t j = static_cast<std::size_t>(position - drawn.begin());
      const bool has_prev = j > 0 || closed, has_next = j + 1 < drawn.size() || closed;
      const SegmentView& prev = segments[drawn[(j + drawn.size() - 1) % drawn.size()]];
      const SegmentView& next = segments[drawn[(j + 1) % drawn.size()]];
      refine_start = has_prev ? refinement.corners && turns(prev.end_tangent, s.start_tangent) : refinement.caps;
      refine_end = has_next ? refinement.corners && turns(s.end_tangent, next.start_tangent) : refinement.caps;
    }
    CURVESCAN_PROPAGATE(flattener.segment(s.points, s.weights, refine_start, refine_end));
  }
  if (closed) flattener.close();
  return Status::ok();
}

}  // namespace

Status flatten_for_stroke(const Path& path, double curve_tolerance, const StrokeEndRefinement& refinement,
                          std::vector<FlatContour>& out) {
  ContourFlattener flattener(curve_tolerance, refinement.angle, refinement.region, refinement.whole, out);
  std::vector<SegmentView> segments;
  Point contour_start, current;
  Point closing_line[2];
  for (const PathElement& element : path) {
    switch (element.verb) {
      case PathVerb::kMove:
        if (!segments.empty()) CURVESCAN_PROPAGATE(flatten_contour(flattener, segments, false, refinement));
        segments.clear();
        flattener.move_to(element.start);
        contour_start = current = element.start;
        break;
      case PathVerb::kClose:
        closing_line[0] = current;
        closing_line[1] = contour_start;
        segments.push_back({closing_line, {}, {}, {}});
        CURVESCAN_PROPAGATE(flatten_contour(flattener, segments, true, refinement));
        segments.clear();
        break;
      default:
        segments.push_back({element.points, element.weights, {}, {}});
        current = element.end;
        break;
    }
  }
  if (!segments.empty()) CURVESCAN_PROPAGATE(flatten_contour(flattener, segments, false, refinement));
  flattener.finish();
  return Status::ok();
}

double contour_length(const FlatContour& contour) noexcept {
  double length = 0.0;
  const std::size_t n = contour.vertices.size();
  for (std::size_t i = 0; i + 1 < n; ++i) length += contour.vertices[i].point.distance(contour.vertices[i + 1].point);
  if (contour.closed && n > 1) length += contour.vertices[n - 1].point.distance(contour.vertices[0].point);
  return length;
}

}  // namespace curvescan::detail
