// The outline of one flattened contour: a sum of same-sign convex pieces, filled nonzero.
//
// Why a sum (Nehab, "Converting stroked primitives to filled primitives", SIGGRAPH 2020, §3–4): the stroke
// of a polyline with joins and caps is the union of (a) one rectangle per segment, sides at ±w/2, (b) one
// wedge per join between the two offset corners on the outer side (round: a circular sector; miter: the
// kite up to the miter tip; bevel: a triangle), (c) one cap per open end. Each piece is convex. Walking
// "left side forward, end cap, right side backward, start cap" and routing every inner corner through the
// pivot (the vertex itself) traces exactly the edges of all pieces added together: the edge rect_i ends
// with (left end -> pivot -> right end), rect_{i+1} starts with the reverse, and the shared halves cancel.
// All pieces are wound the same way (clockwise in a y-up frame), so the winding number is -(number of
// pieces covering a point): non-zero exactly on their union, however they overlap. Cusps, loops, 179.9°
// turns and half-widths beyond the radius of curvature therefore need no special case: the union of
// capsules along the polyline is the swept area (strong correctness).
//
// Where safe, an inner corner skips the pivot and joins the two inner offset corners directly (fewer
// edges): each inner corner lies inside the other segment's rectangle when w/2·sin θ <= that segment's
// length and θ < 90°, and then the small triangle it adds lies in two pieces at once (winding -2 ± 1 stays
// non-zero). We ask for half the segment's length for margin. The sub-joins between a chord and a nearly
// equal true tangent (one side of zero length) also connect directly when that moves the outline by at
// most `inner_slack`: an isolated sliver of that width, at most two per corner.
//
// Joins inside a curve are round: their polygon has its vertices on the circle, so it lies within
// arc_tolerance of the sector when the step angle α obeys w/2·(1 - cos(α/2)) <= arc_tolerance; when the
// whole turn obeys it, the straight connection (no arc vertex) is already within tolerance.
#include "stroke_outline.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace curvescan::detail {
namespace {

Vec2 rotate(Vec2 v, double cs, double sn) noexcept { return {v.x * cs - v.y * sn, v.x * sn + v.y * cs}; }

class OutlineBuilder {
 public:
  OutlineBuilder(const OutlineParams& params, Polygons& out) : p_(params), out_(out) {
    const double h = p_.half_width;
    const double ratio = p_.arc_tolerance / h;
    max_arc_step_ = ratio >= 2.0 ? 2.0 * std::numbers::pi : 2.0 * std::acos(1.0 - ratio);
  }

  void stroke(const FlatContour& contour) {
    const std::vector<FlatVertex>& v = contour.vertices;
    if (v.empty()) return;
    if (v.size() == 1) {
      degenerate(v[0].point, contour.degenerate_direction);
      return;
    }
    const std::size_t n = v.size();
    const std::size_t segment_count = contour.closed ? n : n - 1;
    directions_.resize(segment_count);
    lengths_.resize(segment_count);
    for (std::size_t i = 0; i < segment_count; ++i) {
      const Vec2 chord = v[(i + 1) % n].point - v[i].point;
      lengths_[i] = chord.length();
      directions_[i] = chord / lengths_[i];
    }
    left_.clear();
    right_.clear();
    const double h = p_.half_width;
    if (contour.closed) {
      start_sides(v[0].point, directions_[0]);
      for (std::size_t i = 1; i < n; ++i) vertex_join(v[i], i - 1, i);
      vertex_join(v[0], n - 1, 0);
      emit_side(left_, false);
      emit_side(right_, true);
      return;
    }
    const Vec2 start_tangent = or_chord(v[0].tangent_out, directions_[0]);
    const Vec2 end_tangent = or_chord(v[n - 1].tangent_in, directions_[n - 2]);
    start_sides(v[0].point, start_tangent);
    join(v[0].point, start_tangent, directions_[0], LineJoin::kRound, 0.0, lengths_[0]);
    for (std::size_t i = 1; i + 1 < n; ++i) vertex_join(v[i], i - 1, i);
    join(v[n - 1].point, directions_[n - 2], end_tangent, LineJoin::kRound, lengths_[n - 2], 0.0);
    const Vec2 end_normal = end_tangent.perp() * h;
    push_unique(left_, v[n - 1].point + end_normal);
    push_unique(right_, v[n - 1].point - end_normal);

    // One polygon: left side, end cap, right side backwards, start cap.
    Polygons& o = out_;
    o.points.insert(o.points.end(), left_.begin(), left_.end());
    cap(v[n - 1].point, end_tangent * h);
    o.points.insert(o.points.end(), right_.rbegin(), right_.rend());
    cap(v[0].point, start_tangent * -h);
    o.ends.push_back(o.points.size());
  }

 private:
  static Vec2 or_chord(Vec2 tangent, Vec2 chord) noexcept { return tangent == Vec2{} ? chord : tangent; }

  void start_sides(Point p, Vec2 direction) {
    const Vec2 normal = direction.perp() * p_.half_width;
    left_.push_back(p + normal);
    right_.push_back(p - normal);
  }

  static void push_unique(std::vector<Point>& side, Point p) {
    if (side.empty() || side.back() != p) side.push_back(p);
  }

  void emit_side(const std::vector<Point>& side, bool reversed) {
    std::size_t count = side.size();
    if (count > 1 && side.back() == side.front()) --count;  // the loop came back to its first point
    if (reversed) {
      out_.points.insert(out_.points.end(), side.rend() - static_cast<std::ptrdiff_t>(count), side.rend());
    } else {
      out_.points.insert(out_.points.end(), side.begin(), side.begin() + static_cast<std::ptrdiff_t>(count));
    }
    out_.ends.push_back(out_.points.size());
  }

  // The joins at one vertex: chord -> true tangent (round), the user's join between the true tangents at a
  // corner (round inside a curve), true tangent -> chord (round).
  void vertex_join(const FlatVertex& vertex, std::size_t in, std::size_t out) {
    const Vec2 d_in = directions_[in], d_out = directions_[out];
    if (!vertex.corner) {
      join(vertex.point, d_in, d_out, LineJoin::kRound, lengths_[in], lengths_[out]);
      return;
    }
    const Vec2 t_in = or_chord(vertex.tangent_in, d_in), t_out = or_chord(vertex.tangent_out, d_out);
    join(vertex.point, d_in, t_in, LineJoin::kRound, lengths_[in], 0.0);
    join(vertex.point, t_in, t_out, p_.join, t_in == d_in ? lengths_[in] : 0.0,
         t_out == d_out ? lengths_[out] : 0.0);
    join(vertex.point, t_out, d_out, LineJoin::kRound, 0.0, lengths_[out]);
  }

  // Turning at `p` from unit direction u to unit direction v: the outer side gets the join's corners and
  // ends at p ± h·perp(v); the inner side goes through the pivot p unless that is safe to skip.
  void join(Point p, Vec2 u, Vec2 v, LineJoin kind, double length_in, double length_out) {
    const double c = u.cross(v), d = u.dot(v);
    if (c == 0.0 && d > 0.0) return;
    const double h = p_.half_width;
    // c > 0 turns towards +perp, so +perp (left) is inside; a reversal (c == 0) puts the outer side left.
    const bool outer_left = c <= 0.0;
    const double sign = outer_left ? 1.0 : -1.0;
    const Vec2 nu = u.perp() * (sign * h), nv = v.perp() * (sign * h);
    std::vector<Point>& outer = outer_left ? left_ : right_;
    std::vector<Point>& inner = outer_left ? right_ : left_;
    push_unique(outer, p + nu);  // where the incoming segment's sides end
    push_unique(inner, p - nu);

    // The slack only serves the sub-joins between a chord and a true tangent (a zero-length side): their
    // slivers are isolated, two per corner at most. Between chords, slivers would pile up along a curve.
    const double shorter = std::min(length_in, length_out);
    const bool direct = d > 0.0 && (h * std::abs(c) <= 0.5 * shorter ||
                                    (shorter == 0.0 && h * std::abs(c) <= p_.inner_slack));
    if (!direct) inner.push_back(p);
    inner.push_back(p - nv);

    const double cos_half = std::sqrt(std::max(0.0, 0.5 * (1.0 + d)));
    switch (kind) {
      case LineJoin::kRound:
        arc(outer, p, nu, (outer_left ? -1.0 : 1.0) * std::atan2(std::abs(c), d));
        break;
      case LineJoin::kMiter:
      case LineJoin::kMiterClip:
        // SVG 2 §13.5.4: miter length / width = 1 / sin(φ/2) with φ = π - θ the angle between the
        // segments, i.e. 1 / cos(θ/2) for the turning angle θ.
        if (1.0 <= p_.miter_limit * cos_half) {
          outer.push_back(p + (nu + nv) / (1.0 + d));
        } else if (kind == LineJoin::kMiterClip) {
          // Cut the miter by the line perpendicular to the outward bisector at miter_limit·h from p.
          const Vec2 bisector = (u - v).normalized();
          const double reach = p_.miter_limit * h;
          outer.push_back(p + nu + u * ((reach - nu.dot(bisector)) / u.dot(bisector)));
          outer.push_back(p + nv + v * ((reach - nv.dot(bisector)) / v.dot(bisector)));
        }
        break;
      case LineJoin::kBevel:
        break;
    }
    outer.push_back(p + nv);
  }

  // Appends the interior vertices of the arc around `center` starting at center + from, turning by
  // `sweep` radians (positive from +x towards +y), spaced so that the polygon stays within tolerance.
  void arc(std::vector<Point>& side, Point center, Vec2 from, double sweep, double min_steps = 1.0) {
    const double steps = std::max(min_steps, std::ceil(std::abs(sweep) / max_arc_step_));
    const int count = static_cast<int>(std::clamp(steps, 1.0, static_cast<double>(kMaxArcSegments)));
    const double step = sweep / count;
    const double cs = std::cos(step), sn = std::sin(step);
    Vec2 offset = from;
    for (int i = 1; i < count; ++i) {
      offset = rotate(offset, cs, sn);
      side.push_back(center + offset);
    }
  }

  // A cap at `p` beyond which the stroke ends, `ahead` = h·(unit direction out of the stroke). The
  // polygon arrives at p + h·perp(ahead) and leaves from p - h·perp(ahead).
  void cap(Point p, Vec2 ahead) {
    const Vec2 normal = ahead.perp();
    switch (p_.cap) {
      case LineCap::kButt:
        break;
      case LineCap::kSquare:
        out_.points.push_back(p + normal + ahead);
        out_.points.push_back(p - normal + ahead);
        break;
      case LineCap::kRound: {
        std::vector<Point>& pts = out_.points;
        const std::size_t before = pts.size();
        pts.push_back(p + normal);  // arc() appends interior points only; drop this anchor after
        arc(pts, p, normal, -std::numbers::pi);
        pts.erase(pts.begin() + static_cast<std::ptrdiff_t>(before));
        break;
      }
    }
  }

  // A zero-length subpath (SVG 2 §13.5.5 'stroke-linecap'): a disc, a square along `direction`, or
  // nothing. Wound clockwise (y-up) like every other piece, so that overlaps add up.
  void degenerate(Point p, Vec2 direction) {
    const double h = p_.half_width;
    const Vec2 ahead = direction * h, normal = direction.perp() * h;
    switch (p_.cap) {
      case LineCap::kButt:
        return;
      case LineCap::kSquare:
        out_.points.insert(out_.points.end(),
                           {p + normal + ahead, p - normal + ahead, p - normal - ahead, p + normal - ahead});
        break;
      case LineCap::kRound:
        out_.points.push_back(p + normal);
        arc(out_.points, p, normal, -2.0 * std::numbers::pi, 4.0);  // at least a square, never empty
        break;
    }
    out_.ends.push_back(out_.points.size());
  }

  const OutlineParams& p_;
  Polygons& out_;
  double max_arc_step_;
  std::vector<Point> left_, right_;
  std::vector<Vec2> directions_;
  std::vector<double> lengths_;
};

}  // namespace

void append_outlines(std::span<const FlatContour> contours, const OutlineParams& params, Polygons& out) {
  OutlineBuilder builder(params, out);
  for (const FlatContour& contour : contours) builder.stroke(contour);
}

}  // namespace curvescan::detail
