// Edge clipping in double: see edge_clip.h for what is kept and why.
#include "edge_clip.h"

#include <algorithm>

namespace curvescan::detail {

namespace {

/// Appends the piece (xa, ya) -> (xb, yb), ya < yb, already clamped to the clip's x range.
void push_piece(double xa, double ya, double xb, double yb, int dir, std::vector<ClippedEdge>& out) {
  if (!(yb > ya)) return;  // zero height after splitting: contributes neither winding nor area
  out.push_back(
      {xa, ya, xb, yb, (xb - xa) / (yb - ya), static_cast<std::int8_t>(dir), false, ClippedEdge::kNoEdge});
}

/// Whether `p` lies in the closed box (the test of clip_edge's first case; false for NaN).
bool inside(Point p, double cx0, double cy0, double cx1, double cy1) noexcept {
  return p.x >= cx0 && p.x <= cx1 && p.y >= cy0 && p.y <= cy1;
}

}  // namespace

// Flattened: left to itself, the compiler called the vector's push_back out of line in the loop below once
// ClippedEdge became 48 bytes (23 instructions more per edge on a polygon of 10^5 edges).
[[gnu::flatten]] void clip_polyline(std::span<const Point> points, IntRect clip,
                                    std::vector<ClippedEdge>& out) {
  if (points.size() < 2) return;
  // At most one piece per edge in the common case; grow geometrically (a reserve of the exact size per
  // call would reallocate on every contour of a path).
  const std::size_t wanted = out.size() + points.size() - 1;
  if (out.capacity() < wanted) out.reserve(std::max(wanted, 2 * out.capacity()));
  const double cx0 = clip.x0;
  const double cx1 = clip.x1;
  const double cy0 = clip.y0;
  const double cy1 = clip.y1;
  Point a = points[0];
  bool a_inside = inside(a, cx0, cy0, cx1, cy1);
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Point b = points[i];
    const bool b_inside = inside(b, cx0, cy0, cx1, cy1);
    if (a_inside && b_inside) {
      // clip_edge's first case, term for term.
      if (a.y < b.y) {
        out.push_back({a.x, a.y, b.x, b.y, (b.x - a.x) / (b.y - a.y), 1, false, ClippedEdge::kNoEdge});
      } else if (b.y < a.y) {
        out.push_back({b.x, b.y, a.x, a.y, (a.x - b.x) / (a.y - b.y), -1, false, ClippedEdge::kNoEdge});
      }
    } else {
      clip_edge(a, b, clip, out);
    }
    a = b;
    a_inside = b_inside;
  }
}

void clip_edge(Point a, Point b, IntRect clip, std::vector<ClippedEdge>& out) {
  // The common case first: the edge lies inside the box. Written with comparisons that are false for
  // NaN, so non-finite input takes the general path below and is dropped there.
  const double cx0 = clip.x0;
  const double cx1 = clip.x1;
  const double cy0 = clip.y0;
  const double cy1 = clip.y1;
  if (a.x >= cx0 && a.x <= cx1 && b.x >= cx0 && b.x <= cx1 && a.y >= cy0 && a.y <= cy1 && b.y >= cy0 &&
      b.y <= cy1) {
    if (a.y == b.y) return;
    // One push for either direction (one call site lets the compiler inline the vector's growth check).
    const bool down = a.y < b.y;
    const Point top = down ? a : b;
    const Point bot = down ? b : a;
    out.push_back({top.x, top.y, bot.x, bot.y, (bot.x - top.x) / (bot.y - top.y),
                   static_cast<std::int8_t>(down ? 1 : -1), false, ClippedEdge::kNoEdge});
    return;
  }
  if (!a.is_finite() || !b.is_finite() || clip.empty() || a.y == b.y) return;
  const int dir = b.y > a.y ? 1 : -1;
  const Point top = dir > 0 ? a : b;
  const Point bot = dir > 0 ? b : a;
  if (bot.y <= cy0 || top.y >= cy1) return;
  if (std::min(top.x, bot.x) >= cx1) return;  // entirely right of the box: invisible (see header)

  // Cut to the clip rows. The slope is taken from the original endpoints; interpolating from the
  // endpoint nearer to the cut keeps the error near 1 ulp of the cut coordinate even at ±1e9.
  const double dxdy = (bot.x - top.x) / (bot.y - top.y);
  double ya = top.y;
  double xa = top.x;
  double yb = bot.y;
  double xb = bot.x;
  if (ya < cy0) {
    ya = cy0;
    xa = (cy0 - top.y) < (bot.y - cy0) ? top.x + (cy0 - top.y) * dxdy : bot.x - (bot.y - cy0) * dxdy;
  }
  if (yb > cy1) {
    yb = cy1;
    xb = (cy1 - top.y) < (bot.y - cy1) ? top.x + (cy1 - top.y) * dxdy : bot.x - (bot.y - cy1) * dxdy;
  }
  if (!(yb > ya)) return;

  if (std::max(xa, xb) <= cx0) {  // entirely left: a vertical edge on the left side of the box
    push_piece(cx0, ya, cx0, yb, dir, out);
    return;
  }
  if (std::min(xa, xb) >= cx0 && std::max(xa, xb) <= cx1) {  // the common case: entirely inside
    push_piece(xa, ya, xb, yb, dir, out);
    return;
  }

  // The edge crosses x = cx0 and/or x = cx1: split it at those heights. The heights are computed from
  // the segment (xa, ya) -> (xb, yb) and clamped to it, so the pieces tile [ya, yb] exactly.
  const double dydx = (yb - ya) / (xb - xa);  // xb != xa here, or one of the cases above had applied
  const auto y_at_x = [&](double x) { return std::clamp(ya + (x - xa) * dydx, ya, yb); };
  double cuts[4] = {ya, 0.0, 0.0, 0.0};
  int count = 1;
  if ((xa - cx0) * (xb - cx0) < 0.0) cuts[count++] = y_at_x(cx0);
  if ((xa - cx1) * (xb - cx1) < 0.0) cuts[count++] = y_at_x(cx1);
  cuts[count++] = yb;
  std::sort(cuts, cuts + count);
  // Travel order: top to bottom for a downward edge, bottom to top for an upward one.
  for (int k = 0; k + 1 < count; ++k) {
    const int i = dir > 0 ? k : count - 2 - k;
    const double y0 = cuts[i];
    const double y1 = cuts[i + 1];
    if (!(y1 > y0)) continue;
    // x along the segment, pinned to its end values at its end heights.
    const auto x_at_y = [&](double y) {
      if (y <= ya) return xa;
      if (y >= yb) return xb;
      return xa + (y - ya) * (xb - xa) / (yb - ya);
    };
    const double mid_x = x_at_y(0.5 * (y0 + y1));
    if (mid_x >= cx1) continue;  // right of the box: dropped
    const double x0 = std::clamp(x_at_y(y0), cx0, cx1);
    const double x1 = std::clamp(x_at_y(y1), cx0, cx1);
    push_piece(x0, y0, x1, y1, dir, out);
  }
}

}  // namespace curvescan::detail
