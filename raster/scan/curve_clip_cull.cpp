// flatten_visible: chords for the pieces of a curve that cannot be seen (essay in curve_clip_cull.h).
//
// Why a chord is exact. Let a piece C of a curve run from A to B, with control points Q_i (and weights
// w_i > 0 if rational). C lies in the convex hull H of the Q_i (Ince, *Curves* / U. of Toronto, *Parametric Curves*, "Convex hull
// property": the Bernstein weights, times w_i and normalised for a rational curve, are >= 0 and sum to 1),
// and so does the chord [A, B], since A = Q_0 and B = Q_n are in H and H is convex. We test the bounding
// box of the Q_i, a convex set holding H. Replacing C by the chord changes the contour's winding number at
// a point p by the winding number at p of the closed loop L = C followed by the chord reversed (winding
// numbers add over loops joined at A and B). L lies in the hull box; when that box misses the clip box,
// every p of the clip box lies outside a convex set holding L, so a half-plane through p misses L and a ray
// from p inside it never meets L: the winding of L at p is 0. The rasterizer computes coverage only inside
// its clip box (rasterizer.h: edges are clipped to it first), so the fill is unchanged there.
//
// Halving. A piece that meets the box but is much larger than it is split at t = 1/2 by de Casteljau
// (Gallivan, *Parametric Curves*), on homogeneous points (w·x, w·y, w) for a rational curve (Umetani, *Parametric Curve*, §4.1). The midpoints are
// taken as 0.5·a + 0.5·b, which cannot overflow whatever the coordinates. The pieces are walked depth
// first, left to right, on an explicit stack (bounded by kMaxCullDepth, no recursion), so their polylines
// join end to end in curve order.
#include "curve_clip_cull.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace curvescan::detail {
namespace {

struct Homogeneous {
  double wx, wy, w;
};

Point project(Homogeneous h) noexcept {
  return {h.wx / h.w, h.wy / h.w};
}

Homogeneous midpoint(Homogeneous a, Homogeneous b) noexcept {
  return {0.5 * a.wx + 0.5 * b.wx, 0.5 * a.wy + 0.5 * b.wy, 0.5 * a.w + 0.5 * b.w};
}

Rect hull_box(std::span<const Point> points) noexcept {
  Rect box = Rect::from_point(points.front());
  for (const Point p : points) box.include(p);
  return box;
}

bool misses(const Rect& hull, const Rect& box) noexcept {
  return hull.x1 < box.x0 || hull.x0 > box.x1 || hull.y1 < box.y0 || hull.y0 > box.y1;
}

bool within_extent(const Rect& hull, double limit) noexcept {
  return hull.width() <= limit && hull.height() <= limit;  // an overflowing width (inf) is not
}

FlattenOutcome flatten_piece(std::span<const Point> points, std::span<const double> weights, double tolerance,
                             std::vector<Point>& out, std::size_t max_segments) {
  return weights.empty() ? flatten_bezier(points, tolerance, out, max_segments)
                         : flatten_rational(points, weights, tolerance, out, max_segments);
}

}  // namespace

FlattenOutcome flatten_visible(const PathElement& element, double tolerance, const Rect& box,
                               std::vector<Point>& out, std::size_t max_segments, CullStats* stats) {
  CullStats local_stats;
  CullStats& counts = stats != nullptr ? *stats : local_stats;
  const std::span<const Point> ctrl = element.points;
  const std::span<const double> weights = element.weights;
  max_segments = std::max<std::size_t>(max_segments, 1);
  const auto flatten_whole = [&] {
    ++counts.flattened;
    return flatten_piece(ctrl, weights, tolerance, out, max_segments);
  };
  // Input the hull argument does not cover (or the flattener refuses anyway): as before the cull.
  const bool weights_valid =
      std::all_of(weights.begin(), weights.end(), [](double w) { return w > 0.0 && std::isfinite(w); });
  if (ctrl.size() < 2 || (element.is_rational() && weights.size() != ctrl.size()) || !weights_valid ||
      !(tolerance > 0.0) || !std::isfinite(tolerance) || !box.is_finite()) {
    return flatten_whole();
  }
  const Rect hull = hull_box(ctrl);
  if (!hull.is_finite()) return flatten_whole();
  if (misses(hull, box)) {
    ++counts.chorded;
    out.push_back(element.end);
    return FlattenOutcome::kOk;
  }
  const double limit = kFlattenExtentFactor * (std::max(box.width(), box.height()) + 1.0);
  if (within_extent(hull, limit)) return flatten_whole();

  // The huge curve that meets the box: halve. Weights scaled by their maximum (the curve does not change)
  // so that w·x never exceeds |x|.
  const std::size_t count = ctrl.size();
  const double w_max = weights.empty() ? 1.0 : *std::max_element(weights.begin(), weights.end());
  // Weights so far apart that a scaled one underflows (w_min / w_max < DBL_MIN) would project to NaN: such a
  // curve is left whole to the flattener, which reports it.
  if (std::any_of(weights.begin(), weights.end(),
                  [w_max](double w) { return !(w / w_max >= std::numeric_limits<double>::min()); })) {
    return flatten_whole();
  }
  // Every projected de Casteljau point is a convex combination of the P_i (weights lambda_i·w_i >= 0), so
  // the pieces' control points stay finite, inside the curve's hull.
  std::vector<Homogeneous> stack;  // pieces of `count` nodes each, the next piece to walk last
  std::vector<int> depths;
  stack.reserve(count * 64);
  for (std::size_t i = 0; i < count; ++i) {
    const double w = weights.empty() ? 1.0 : weights[i] / w_max;
    stack.push_back({ctrl[i].x * w, ctrl[i].y * w, w});
  }
  depths.push_back(0);
  std::vector<Homogeneous> piece(count), left(count), right(count);
  std::vector<Point> points(count);
  std::vector<double> piece_weights(weights.empty() ? 0 : count);
  bool certified = true;
  const std::size_t start_size = out.size();
  while (!depths.empty()) {
    // The budget: each piece appends at least one vertex, so a curve that fits never gets here with its
    // budget spent. Once it is, the last vertex becomes element.end: the rest of the curve is that chord
    // (the polyline stays complete) and the cut is reported.
    const std::size_t appended = out.size() - start_size;
    if (appended >= max_segments) {
      out.back() = element.end;
      return FlattenOutcome::kSegmentLimit;
    }
    const int depth = depths.back();
    depths.pop_back();
    std::copy(stack.end() - static_cast<std::ptrdiff_t>(count), stack.end(), piece.begin());
    stack.resize(stack.size() - count);
    for (std::size_t i = 0; i < count; ++i) {
      points[i] = project(piece[i]);
      if (!piece_weights.empty()) piece_weights[i] = piece[i].w;
    }
    const Rect piece_hull = hull_box(points);
    if (misses(piece_hull, box)) {
      ++counts.chorded;
      out.push_back(points.back());
      continue;
    }
    if (within_extent(piece_hull, limit) || depth >= kMaxCullDepth) {
      ++counts.flattened;
      const FlattenOutcome outcome =
          flatten_piece(points, piece_weights, tolerance, out, max_segments - appended);
      if (outcome != FlattenOutcome::kOk) certified = false;
      if (outcome == FlattenOutcome::kNonFinite || outcome == FlattenOutcome::kInvalid) {
        out.push_back(points.back());  // nothing was appended: the chord keeps the polyline complete
      }
      continue;
    }
    // de Casteljau at 1/2: the triangle's left edge is [0, 1/2], its right edge [1/2, 1] (Gallivan, *Parametric Curves*).
    ++counts.halved;
    const std::size_t n = count - 1;
    left[0] = piece[0];
    right[n] = piece[n];
    for (std::size_t level = 1; level <= n; ++level) {
      for (std::size_t i = 0; i + level <= n; ++i) piece[i] = midpoint(piece[i], piece[i + 1]);
      left[level] = piece[0];
      right[n - level] = piece[n - level];
    }
    stack.insert(stack.end(), right.begin(), right.end());
    depths.push_back(depth + 1);
    stack.insert(stack.end(), left.begin(), left.end());
    depths.push_back(depth + 1);
  }
  // The last piece ends at the projection of the scaled last node, within an ulp of element.end; the
  // contract (and the next segment's joint) wants it exactly.
  out.back() = element.end;
  return certified ? FlattenOutcome::kOk : FlattenOutcome::kSegmentLimit;
}

}  // namespace curvescan::detail
