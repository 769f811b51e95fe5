// flatten_for_stroke: a Path -> FlatContours (stroke_contour.h), curves flattened in user space.
//
// Why the ends of a curve are cut first: the stroke of a polyline ends (or meets a join) perpendicular to
// its last chord, the true stroke perpendicular to the curve's end tangent. The two differ by
// (width/2)·sin(angle between them) at the outline's corner — several pixels for a 100 px stroke on a
// gentle curve. The tangent directions of a (rational, positive-weight) Bézier piece lie in the cone
// spanned by its control polygon's edges (the hodograph's convex hull property, seed 000 §2.3 for the
// polynomial case; the rational derivative is a positive combination of the differences P_j - P_i, seed 001
// "Derivatives of rational curves"), and every chord of the piece is an average of tangents. So halving
// the end piece (de Casteljau at 1/2, seed 000 eq. 8) until its control polygon lies within `end_angle`
// of the end tangent bounds the angle of every chord of that piece.
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

// The largest t = 2^-k (k <= kMaxEndHalvings) such that the piece [0, t] of the curve, whose control
// points are given from the end of interest on, stays within the cone around `tangent`.
double end_piece_parameter(std::span<const Point> points, std::span<const double> weights, bool from_back,
                           Vec2 tangent, double sin_limit) {
  std::vector<Homogeneous> ctrl(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::size_t j = from_back ? points.size() - 1 - i : i;
    const double w = weights.empty() ? 1.0 : weights[j];
    ctrl[i] = {points[j].x * w, points[j].y * w, w};
  }
  double t = 1.0;
  for (int halving = 0; halving < kMaxEndHalvings; ++halving) {
    if (control_polygon_in_cone(ctrl, tangent, sin_limit)) break;
    keep_left_half(ctrl);
    t *= 0.5;
  }
  return t;
}

class ContourFlattener {
 public:
  ContourFlattener(double tolerance, double end_angle, std::vector<FlatContour>& out)
      : tolerance_(tolerance), end_angle_(end_angle), out_(out) {}

  void move_to(Point p) {
    finish();
    current_.vertices.assign(1, FlatVertex{p, {}, {}, false});
    current_.closed = false;
    segment_count_ = 0;
    open_ = true;
  }

  Status segment(std::span<const Point> points, std::span<const double> weights) {
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

    if (points.size() > 2) CURVESCAN_PROPAGATE(flatten_curve(points, weights, start_tangent, end_tangent));
    push({end, end_tangent, {}, false});
    return Status::ok();
  }

  Status close() {
    const Point start = current_.vertices.front().point;
    if (current_.vertices.back().point != start) {
      const Point line[2] = {current_.vertices.back().point, start};
      CURVESCAN_PROPAGATE(segment(line, {}));
    }
    current_.closed = true;
    if (current_.vertices.size() > 1) {
      // The last vertex is the start again: fold it into vertex 0, which becomes the closing join.
      current_.vertices.front().tangent_in = current_.vertices.back().tangent_in;
      current_.vertices.front().corner = true;
      current_.vertices.pop_back();
    }
    finish();
    return Status::ok();
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

  // Appends the curve's interior vertices (smooth), its end pieces cut as the header essay explains.
  Status flatten_curve(std::span<const Point> points, std::span<const double> weights, Vec2 start_tangent,
                       Vec2 end_tangent) {
    double a = 1.0, b = 0.0;  // the end pieces are [0, a] and [b, 1]
    if (end_angle_ < std::numbers::pi / 2) {
      const double sin_limit = std::sin(end_angle_);
      a = end_piece_parameter(points, weights, false, start_tangent, sin_limit);
      b = 1.0 - end_piece_parameter(points, weights, true, -end_tangent, sin_limit);
    }
    double cuts[4] = {0.0, a, b, 1.0};
    std::size_t cut_count = 4;
    if (a >= b) {
      // The end pieces overlap: one cut between them leaves two pieces, each inside an end piece.
      if (a == 1.0 && b == 0.0) {
        cuts[1] = 1.0;
        cut_count = 2;
      } else {
        cuts[1] = 0.5 * (a + b);
        cuts[2] = 1.0;
        cut_count = 3;
      }
    }
    for (std::size_t i = 0; i + 1 < cut_count; ++i) {
      scratch_.clear();
      FlattenOutcome outcome;
      if (cut_count == 2) {
        outcome = weights.empty() ? flatten_bezier(points, tolerance_, scratch_)
                                  : flatten_rational(points, weights, tolerance_, scratch_);
      } else if (weights.empty()) {
        const Bezier piece =
            Bezier(std::vector<Point>(points.begin(), points.end())).subsegment(cuts[i], cuts[i + 1]);
        outcome = flatten_bezier(piece.points(), tolerance_, scratch_);
      } else {
        const RationalBezier piece =
            RationalBezier(std::vector<Point>(points.begin(), points.end()),
                           std::vector<double>(weights.begin(), weights.end()))
                .subsegment(cuts[i], cuts[i + 1]);
        outcome = flatten_rational(piece.points(), piece.weights(), tolerance_, scratch_);
      }
      if (outcome == FlattenOutcome::kNonFinite || outcome == FlattenOutcome::kInvalid) {
        return Error{ErrorKind::kLimitExceeded,
                     "a curve of the stroked path could not be flattened: its coordinates overflow double "
                     "arithmetic"};
      }
      // The last vertex of the last piece is the curve's end point, pushed exactly by segment().
      const std::size_t keep = i + 2 == cut_count ? scratch_.size() - 1 : scratch_.size();
      for (std::size_t j = 0; j < keep; ++j) push({scratch_[j], {}, {}, false});
    }
    return Status::ok();
  }

  double tolerance_;
  double end_angle_;
  std::vector<FlatContour>& out_;
  FlatContour current_;
  std::vector<Point> scratch_;
  int segment_count_ = 0;
  bool open_ = false;
};

}  // namespace

Status flatten_for_stroke(const Path& path, double curve_tolerance, double end_angle,
                          std::vector<FlatContour>& out) {
  ContourFlattener flattener(curve_tolerance, end_angle, out);
  for (const PathElement& element : path) {
    switch (element.verb) {
      case PathVerb::kMove:
        flattener.move_to(element.start);
        break;
      case PathVerb::kClose:
        CURVESCAN_PROPAGATE(flattener.close());
        break;
      default:
        CURVESCAN_PROPAGATE(flattener.segment(element.points, element.weights));
        break;
    }
  }
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
