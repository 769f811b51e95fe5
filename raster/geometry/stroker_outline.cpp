// The outline of one flattened contour: a sum of same-sign convex pieces, filled nonzero.
//
// Why a sum (Nehab, "Converting stroked primitives to filled primitives", SIGGRAPH 2020, §3–4): the stroke
// of a C1 curve is the area swept by its normal segment (length w, centred on the curve), plus a round
// cap at every cusp, plus a wedge per join between the two offset corners on the outer side (round: a
// circular sector; miter: the kite up to the miter tip; bevel: a triangle), plus one cap per open end.
// flatten_for_stroke gives the true tangent at every polyline vertex; the swept area between two
// consecutive vertices is approximated by the quadrilateral between their two normal segments (within
// tolerance: stroker_flatten.cpp bounds the tangent's turn along a chord). Walking "left side forward, end
// cap, right side backward, start cap" traces exactly the edges of all pieces added together: quad_i
// ends with the normal segment (left_{i+1} -> right_{i+1}), quad_{i+1} starts with the reverse, and the
// shared edges cancel, so a run where the offsets are well behaved is just its two offset polylines —
// the thin outline. All pieces are wound the same way (clockwise in a y-up frame), so the winding number
// is -(number of pieces covering a point): non-zero exactly on their union, however they overlap. Where
// the half-width exceeds the radius of curvature, two consecutive normal segments cross at a point x_k
// and their quadrilateral is a bowtie with one lobe wound backwards. The normal, rotating about x_k,
// sweeps the two lobes: (F_k, F_k+1, x_k) on the fold side F (the side of the centre of curvature,
// where the offset folds back) and (O_k, O_k+1, x_k) on the other. Both have the orientation of the
// tangent's turn, so the bowtie (as the thin outline traces it) is O-lobe − F-lobe, and the swept area
// is the bowtie plus twice the F-lobe. Over a *fold run* — consecutive chords whose normals cross,
// turning the same way — the F-lobes share their edges along the normal segments (x_k and x_k+1 both
// lie on normal k+1), so their sum is one polygon: the fold side's offset chain F_i..F_j closed back
// through the crossings x_j-1..x_i (for a circle of radius < h: a disc sector of radius h − radius).
// Adding it twice: once folded into the traced outline, whose F side then runs F_i, x_i..x_j-1, F_j
// (the offset's swallowtail replaced by the crossings, close to the evolute), once as one extra
// polygon per run. Per-chord lobes made every normal segment of a tight bend an edge, and those all
// cross near the centre of curvature: quadratically many crossings for the rasterizer to resolve.
// A chord along which the tangent turns by more than the cuts allow (cut down to a tiny piece: a cusp, or a
// line drawn as a curve) gets the two opposite sectors its normal sweeps about the chord's middle — at a
// cusp they make a disc, Nehab's round cap — or a disc where the turn is not the short one (chord_piece).
// Loops, 179.9° turns and inner joins need no special case (strong correctness).
//
// At a join, the inner side goes through the pivot (the vertex itself): the edge quad_i ends with
// (left end -> pivot -> right end) and the wedge and quad_{i+1} continue from there. Where safe, an inner
// corner skips the pivot and joins the two inner offset corners directly (fewer edges): each inner corner
// lies inside the other chord's piece when w/2·sin θ <= that chord's length and θ < 90°, and then the
// small triangle it adds lies in two pieces at once (winding -2 ± 1 stays non-zero). We ask for half the
// chord's length for margin.
//
// Round joins and caps are polygons whose end vertices are on the circle and whose interior vertices are
// just outside it, at the radius that gives the polygon the sector's exact area (area_exact_radius); the
// inscribed polygon lies within arc_tolerance of the sector when the step angle α obeys
// w/2·(1 - cos(α/2)) <= arc_tolerance, and the area-exact one, with the same steps, closer still. When the
// whole turn obeys it, the straight connection (no arc vertex) is already within tolerance.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "stroke_outline.h"
#include "vector_length.h"

namespace curvescan::detail {
namespace {

Vec2 rotate(Vec2 v, double cs, double sn) noexcept { return {v.x * cs - v.y * sn, v.x * sn + v.y * cs}; }

class OutlineBuilder {
 public:
  OutlineBuilder(const OutlineParams& params, Polygons& out) : p_(params), out_(out) {
    const double h = p_.half_width;
    const double ratio = p_.arc_tolerance / h;
    max_arc_step_ = ratio >= 2.0 ? 2.0 * std::numbers::pi : 2.0 * std::acos(1.0 - ratio);
    const double merge_distance = p_.arc_tolerance * kFoldCrossingMergeFraction;
    merge_distance_squared_ = merge_distance * merge_distance;
  }

  // True once the points emitted and pending (sides, extra pieces) pass the budget: stroke() stops there
  // and exceeded() stays true.
  bool over_budget() noexcept {
    if (out_.points.size() + left_.size() + right_.size() + extra_.points.size() + fold_side_.size() +
            fold_crossings_.size() >
        p_.max_points) {
      exceeded_ = true;
    }
    return exceeded_;
  }
  [[nodiscard]] bool exceeded() const noexcept { return exceeded_ || out_.points.size() > p_.max_points; }

  /// Strokes one contour, or a dash train: consecutive open contours, each continuing the previous one
  /// (continues_train), traced as one polygon whose sides bridge the gaps (bridge_gap).
  void stroke(std::span<const FlatContour> train) {
    const FlatContour& first = train.front();
    const std::vector<FlatVertex>& v = first.vertices;
    if (v.empty()) return;
    if (v.size() == 1) {
      degenerate(v[0].point, first.degenerate_direction);
      return;
    }
    left_.clear();
    right_.clear();
    extra_.points.clear();
    extra_.ends.clear();
    fold_active_ = false;
    if (first.closed) {
      const std::size_t n = v.size();
      measure_chords(first);
      start_sides(v[0].point, or_chord(v[0].tangent_out, directions_[0]));
      for (std::size_t i = 0; i < n; ++i) {
        chord_piece(v, i);
        vertex_join(v[(i + 1) % n], i, (i + 1) % n);
        if (over_budget()) return;
      }
      end_fold_run();
      emit_side(left_, false);
      emit_side(right_, true);
    } else {
      for (std::size_t k = 0; k < train.size(); ++k) {
        const std::vector<FlatVertex>& cv = train[k].vertices;
        const std::size_t n = cv.size();
        measure_chords(train[k]);
        const Vec2 start_tangent = or_chord(cv[0].tangent_out, directions_[0]);
        if (k == 0) {
          if (cv[0].corner && cv[0].tangent_in != Vec2{} && cv[0].tangent_in != start_tangent) {
            lone_join(cv[0].point, cv[0].tangent_in, start_tangent);
          }
          start_sides(cv[0].point, start_tangent);
        } else {
          bridge_gap(train[k - 1].vertices.back().point, end_tangent(train[k - 1]), cv[0].point, start_tangent);
        }
        for (std::size_t i = 0; i + 1 < n; ++i) {
          chord_piece(cv, i);
          if (i + 2 < n) vertex_join(cv[i + 1], i, i + 1);
          if (over_budget()) return;
        }
        end_fold_run();
      }
      // One polygon: left side, end cap, right side backwards, start cap.
      const double h = p_.half_width;
      const std::vector<FlatVertex>& last = train.back().vertices;
      Polygons& o = out_;
      o.points.insert(o.points.end(), left_.begin(), left_.end());
      cap(last.back().point, end_tangent(train.back()) * h);
      o.points.insert(o.points.end(), right_.rbegin(), right_.rend());
      cap(v[0].point, start_tangent(first) * -h);
      o.ends.push_back(o.points.size());
    }
    const std::size_t base = out_.points.size();
    out_.points.insert(out_.points.end(), extra_.points.begin(), extra_.points.end());
    for (const std::size_t end : extra_.ends) out_.ends.push_back(base + end);
  }

  /// Whether open contour `next` may continue the polygon of open contour `previous` (a dash train):
  /// round or square caps, `next` starting where `previous` ends plus a gap g along the same tangent t,
  /// with g < 2h (round) or <= 2h (square), i.e. the two facing caps A (of `previous`, at x in [0, h]
  /// along t from its end) and B (of `next`, x in [g - h, g]) overlap. Tracing both dashes as one polygon
  /// whose sides run along the caps' envelope over [0, g] (bridge_gap, enclosing Q ⊂ A ∪ B) instead of
  /// along the two caps sums to the two dash polygons plus Q − A − B: with every piece clockwise
  /// (winding −1 per piece) the winding becomes w_a + w_b − [Q] + [A] + [B], still <= −1 on Q (which
  /// A ∪ B covers) and unchanged outside A ∪ B. What Q misses of A ∪ B is where A pokes past x = g or B
  /// before x = 0: nothing when g >= h; otherwise that part must lie in the other dash's body, so both
  /// chords next to the gap must run straight along t for at least h − g (their pieces are then the
  /// rectangles that cover it). Then the nonzero union is the same, and the rasterizer gets no crossing
  /// edges between the two caps. Misalignment (tangents, chords or positions off the common line)
  /// moves the pieces by at most h·|Δt| + |gap × t|, held below arc_tolerance / 16.
  [[nodiscard]] bool continues_train(const FlatContour& previous, const FlatContour& next) const noexcept {
    if (p_.cap == LineCap::kButt || previous.closed || next.closed || previous.vertices.size() < 2 ||
        next.vertices.size() < 2) {
      return false;
    }
    const std::vector<FlatVertex>& a = previous.vertices;
    const std::vector<FlatVertex>& b = next.vertices;
    const FlatVertex& start = b.front();
    const Vec2 t = end_tangent(previous), u = start_tangent(next);
    if (start.corner && start.tangent_in != Vec2{} && start.tangent_in != u) return false;  // a lone join
    const Vec2 gap = start.point - a.back().point;
    const double h = p_.half_width, g = gap.dot(t), slack = p_.arc_tolerance / 16.0;
    const double misalignment = h * vector_length(t - u) + std::abs(gap.cross(t));
    if (!(misalignment <= slack) || !(g >= 0.0)) {
      return p_.cap == LineCap::kRound && continues_curved_train(a, b);
    }
    if (!(p_.cap == LineCap::kRound ? g < 2.0 * h : g <= 2.0 * h)) return false;
    if (g >= h) return true;
    const auto straight_along_t = [&](const FlatVertex& from, const FlatVertex& to) {
      const Vec2 chord = to.point - from.point;
      const double length = vector_length(chord);
      return length >= h - g && h * vector_length(chord / length - t) <= slack &&
             h * vector_length(or_chord(from.tangent_out, t) - t) <= slack &&
             h * vector_length(or_chord(to.tangent_in, t) - t) <= slack;
    };
    return straight_along_t(a[a.size() - 2], a.back()) && straight_along_t(b[0], b[1]);
  }

 private:
  static Vec2 chord_direction(const FlatVertex& a, const FlatVertex& b) noexcept {
    return unit_vector(b.point - a.point);
  }
  static Vec2 start_tangent(const FlatContour& c) noexcept {
    return or_chord(c.vertices[0].tangent_out, chord_direction(c.vertices[0], c.vertices[1]));
  }
  static Vec2 end_tangent(const FlatContour& c) noexcept {
    const std::size_t n = c.vertices.size();
    return or_chord(c.vertices[n - 1].tangent_in, chord_direction(c.vertices[n - 2], c.vertices[n - 1]));
  }

  void measure_chords(const FlatContour& contour) {
    const std::vector<FlatVertex>& v = contour.vertices;
    const std::size_t n = v.size();
    const std::size_t segment_count = contour.closed ? n : n - 1;
    directions_.resize(segment_count);
    lengths_.resize(segment_count);
    for (std::size_t i = 0; i < segment_count; ++i) {
      const Vec2 chord = v[(i + 1) % n].point - v[i].point;
      lengths_[i] = vector_length(chord);
      directions_[i] = chord / lengths_[i];
    }
  }

  // The sides across the gap between a dash ending at `end` (unit tangent t) and the next starting at
  // `start` (unit tangent u), as continues_train allows: the envelope of the two facing caps. Round: the
  // end cap's arc from its side to where the two circles cross (on the gap's perpendicular bisector, at
  // sqrt(h² - d²/4) from its middle), then the start cap's arc on to its side. Square (t = u only): the
  // sides run straight on.
  void bridge_gap(Point end, Vec2 t, Point start, Vec2 u) {
    const double h = p_.half_width;
    const Vec2 nt = t.perp() * h, nu = u.perp() * h;
    if (p_.cap == LineCap::kRound && start != end) {  // dashes that touch need no bridge
      const auto [cross_left, cross_right] = circle_crossings(end, start);
      const auto turn = [](Vec2 from, Vec2 to) { return std::atan2(from.cross(to), from.dot(to)); };
      arc(left_, end, nt, turn(nt, cross_left - end));
      push_unique(left_, cross_left);
      arc(left_, start, cross_left - start, turn(cross_left - start, nu));
      arc(right_, end, -nt, turn(-nt, cross_right - end));
      push_unique(right_, cross_right);
      arc(right_, start, cross_right - start, turn(cross_right - start, -nu));
    }
    push_unique(left_, start + nu);
    push_unique(right_, start - nu);
  }

  // Where the circles of radius h about `end` and `start` cross (0 < |start - end| < 2h): the left one
  // (towards +perp of start - end) first.
  [[nodiscard]] std::pair<Point, Point> circle_crossings(Point end, Point start) const noexcept {
    const double h = p_.half_width;
    const Vec2 gap = start - end;
    const double d = vector_length(gap);
    const Vec2 across = gap.perp() / d * std::sqrt(std::max(0.0, h * h - 0.25 * d * d));
    const Point middle = end + gap * 0.5;
    return {middle + across, middle - across};
  }

  // The largest value of nu·p over W = {|p - c| <= h, (p - line_point)·m >= 0} (m a unit vector); -inf
  // when W is empty. A linear function on a disc cut by a line peaks at the disc's extreme point in
  // direction nu if that point is in W, else at an end of the cut.
  [[nodiscard]] double cut_disc_max(Vec2 nu, Point c, Point line_point, Vec2 m) const noexcept {
    const double h = p_.half_width;
    const double length = vector_length(nu);
    const Point extreme = length > 0.0 ? c + nu * (h / length) : c;
    if ((extreme - line_point).dot(m) >= 0.0) return nu.dot(extreme.to_vec());
    const double depth = (c - line_point).dot(m);  // > -h when the line cuts the disc
    if (!(depth > -h)) return -std::numeric_limits<double>::infinity();
    const Point foot = c - m * depth;
    const Vec2 half_chord = m.perp() * std::sqrt(std::max(0.0, h * h - depth * depth));
    return std::max(nu.dot((foot + half_chord).to_vec()), nu.dot((foot - half_chord).to_vec()));
  }

  // Whether W (as in cut_disc_max) lies inside the piece of the chord from `from` to `to` (the
  // quadrilateral between their normal segments), checked on its edges other than the normal segment
  // at `skip_end` (W's own cut). False where the normals cross (the piece is not a quadrilateral).
  [[nodiscard]] bool cut_disc_in_piece(Point c, Point line_point, Vec2 m, const FlatVertex& from,
                                       const FlatVertex& to, Vec2 chord, bool skip_from) const noexcept {
    const double h = p_.half_width;
    const Vec2 nf = or_chord(from.tangent_out, chord).perp() * h, nt = or_chord(to.tangent_in, chord).perp() * h;
    const Point corners[4] = {from.point + nf, to.point + nt, to.point - nt, from.point - nf};
    if (segments_cross(corners[0], corners[3], corners[1], corners[2])) return false;
    double area = 0.0;
    for (int i = 0; i < 4; ++i) area += corners[i].to_vec().cross(corners[(i + 1) % 4].to_vec());
    const double sign = area > 0.0 ? 1.0 : -1.0;
    for (int i = 0; i < 4; ++i) {
      if (i == (skip_from ? 3 : 1)) continue;  // edge 3 is the normal segment at `from`, edge 1 at `to`
      const Point x = corners[i], y = corners[(i + 1) % 4];
      // Inside: sign·cross(y - x, p - x) >= 0, i.e. nu·p <= nu·x with nu = -sign·perp(y - x).
      const Vec2 nu = (y - x).perp() * -sign;
      if (!(cut_disc_max(nu, c, line_point, m) <= nu.dot(x.to_vec()))) return false;
    }
    return true;
  }

  // continues_train on curves (round caps): the tangents t at the end E and u at the start S differ.
  // With A, B the facing half discs and the crossings of their circles on the front arc of A and the
  // back arc of B, the bridge region Q is A and B each cut by the gap's bisector, so Q ⊂ A ∪ B; what Q
  // misses is the part of A in front of S's normal (and of B behind E's), which must then lie in the
  // other dash's first (last) chord piece: checked exactly on the disc cut by that normal.
  [[nodiscard]] bool continues_curved_train(const std::vector<FlatVertex>& a,
                                            const std::vector<FlatVertex>& b) const noexcept {
    const double h = p_.half_width;
    const Point e = a.back().point, s = b.front().point;
    const Vec2 chord_a = chord_direction(a[a.size() - 2], a.back()), chord_b = chord_direction(b[0], b[1]);
    const Vec2 t = or_chord(a.back().tangent_in, chord_a), u = or_chord(b.front().tangent_out, chord_b);
    const double d = vector_length(s - e);
    if (!(d > 0.0 && d < 2.0 * h && t.dot(u) > 0.0)) return false;
    const auto [cross_left, cross_right] = circle_crossings(e, s);
    const Vec2 nt = t.perp(), nu = u.perp();
    const Vec2 le = cross_left - e, re = cross_right - e, ls = cross_left - s, rs = cross_right - s;
    if (!(le.dot(t) >= 0.0 && le.dot(nt) >= 0.0 && re.dot(t) >= 0.0 && re.dot(nt) <= 0.0)) return false;
    if (!(ls.dot(u) <= 0.0 && ls.dot(nu) >= 0.0 && rs.dot(u) <= 0.0 && rs.dot(nu) <= 0.0)) return false;
    return cut_disc_in_piece(e, s, u, b[0], b[1], chord_b, true) &&
           cut_disc_in_piece(s, e, t * -1.0, a[a.size() - 2], a.back(), chord_a, false);
  }

  static Vec2 or_chord(Vec2 tangent, Vec2 chord) noexcept { return tangent == Vec2{} ? chord : tangent; }

  void start_sides(Point p, Vec2 direction) {
    const Vec2 normal = direction.perp() * p_.half_width;
    left_.push_back(p + normal);
    right_.push_back(p - normal);
  }

  // The piece of chord i: the quadrilateral between the true normal segments at its two ends (the sides
  // hold its start already). Consecutive pieces share their normal segment, so in the traced outline
  // those edges cancel and only the two offset polylines remain. Two cases need more (see the essay):
  // the normal segments cross (half-width beyond the radius of curvature: the quadrilateral would be a
  // bowtie with one lobe wound backwards; the chord joins a fold run), and a tangent turning too far
  // along the chord (a cusp).
  void chord_piece(const std::vector<FlatVertex>& v, std::size_t i) {
    const std::size_t n = v.size();
    const FlatVertex& a = v[i];
    const FlatVertex& b = v[(i + 1) % n];
    const double h = p_.half_width;
    const Vec2 ta = or_chord(a.tangent_out, directions_[i]), tb = or_chord(b.tangent_in, directions_[i]);
    const Vec2 na = ta.perp() * h, nb = tb.perp() * h;
    const Point la = a.point + na, ra = a.point - na, lb = b.point + nb, rb = b.point - nb;
    const double turn = ta.cross(tb);
    if (turn != 0.0 && segments_cross(la, ra, lb, rb)) {
      // The normal rotates about the crossing x; the centre of curvature, hence the fold, is on the left
      // when the tangent turns counterclockwise (towards +perp).
      const Vec2 sa = ra - la, sb = rb - lb;
      const Point x = la + sa * ((lb - la).cross(sb) / sa.cross(sb));
      const bool fold_left = turn > 0.0;
      if (fold_active_ && fold_left != fold_left_) end_fold_run();
      std::vector<Point>& fold = fold_left ? left_ : right_;
      if (!fold_active_) {
        fold_active_ = true;
        fold_left_ = fold_left;
        fold_side_.assign(1, fold.back());
        fold_crossings_.clear();
      }
      fold_side_.push_back(fold_left ? lb : rb);
      // A crossing as near the run's last one as the merge distance adds no area worth a vertex, and it
      // is dropped from both places (the outline's fold side and the run's lobe polygon: the same points,
      // so the two still add up). Along a circle of radius < h every crossing is the centre in exact
      // arithmetic; computed, they scatter by rounding (1e-11 px about a centre at 10 px) into thousands
      // of tiny edges that all cross one another, quadratically many crossings for the rasterizer
      // (fuzz/regressions/raster_stroke/circle_fold_crossings_at_centre_slow).
      if (fold_crossings_.empty() ||
          (x - fold_crossings_.back()).length_squared() > merge_distance_squared_) {
        fold_crossings_.push_back(x);
        push_unique(fold, x);
      }
      push_unique(fold_left ? right_ : left_, fold_left ? rb : lb);
    } else {
      end_fold_run();
      push_unique(left_, lb);
      push_unique(right_, rb);
    }
    if (ta == tb) return;
    // The offset chords fall short of the swept area by h·(1 - cos(Δ/2)) where the normal turns by Δ;
    // flatten_for_stroke keeps that within tolerance except on chords shorter than its piece floor (a
    // cusp, or a direction that turns sharply within a fraction of the tolerance: a line drawn as a
    // curve). Threshold: arc_tolerance = tolerance/2 (stroker.cpp), what is left beside the flattening
    // error. The chord is that short, so the normal segment turns about (practically) one point, its
    // middle, and sweeps the two opposite sectors of radius h between na and nb (at a cusp, Δ = π, they
    // make Nehab's round cap: a disc). By the mean value theorem the chord's direction is one of the
    // tangents along it, so when it lies outside the short turn from ta to tb the direction did not turn
    // that way (a loop, or a turn of π or more): then the disc, which holds every normal about the point.
    const double cos_half = std::sqrt(std::max(0.0, 0.5 * (1.0 + ta.dot(tb))));
    if (h * (1.0 - cos_half) > p_.arc_tolerance) {
      const Point middle = a.point + (b.point - a.point) * 0.5;
      const Vec2 d = directions_[i];
      const double angle = std::atan2(turn, ta.dot(tb));
      const double side = angle >= 0.0 ? 1.0 : -1.0;
      if (side * ta.cross(d) >= 0.0 && side * d.cross(tb) >= 0.0) {
        swept_sector(middle, na, angle);
        swept_sector(middle, na * -1.0, angle);
      } else {
        extra_.points.push_back(middle + Vec2{0.0, h});
        arc(extra_.points, middle, Vec2{0.0, h}, -2.0 * std::numbers::pi, 4.0);
        extra_.ends.push_back(extra_.points.size());
      }
    }
  }

  // The sector of radius |from| about `center` that the vector `from` sweeps turning by `sweep` radians
  // (|sweep| <= π), as one extra piece wound like every other (clockwise in a y-up frame, as the disc's
  // negative sweep: a sector turning the other way is traced from its far side).
  void swept_sector(Point center, Vec2 from, double sweep) {
    if (sweep > 0.0) {
      from = rotate(from, std::cos(sweep), std::sin(sweep));
      sweep = -sweep;
    }
    std::vector<Point>& pts = extra_.points;
    pts.push_back(center);
    pts.push_back(center + from);
    arc(pts, center, from, sweep);
    pts.push_back(center + rotate(from, std::cos(sweep), std::sin(sweep)));
    extra_.ends.push_back(pts.size());
  }

  // Closes the fold run in progress (see the essay): the fold side reaches F_j, and the sum of the run's
  // F-lobes — F_i..F_j, then the crossings back x_j-1..x_i — is added once more as one polygon, wound
  // clockwise (y-up) like every piece: that order turns with the tangent, counterclockwise on a left fold.
  void end_fold_run() {
    if (!fold_active_) return;
    fold_active_ = false;
    push_unique(fold_left_ ? left_ : right_, fold_side_.back());
    std::vector<Point>& pts = extra_.points;
    const std::size_t begin = pts.size();
    pts.insert(pts.end(), fold_side_.begin(), fold_side_.end());
    pts.insert(pts.end(), fold_crossings_.rbegin(), fold_crossings_.rend());
    if (fold_left_) std::reverse(pts.begin() + static_cast<std::ptrdiff_t>(begin), pts.end());
    extra_.ends.push_back(pts.size());
  }

  static bool segments_cross(Point a0, Point a1, Point b0, Point b1) noexcept {
    const double s0 = (a1 - a0).cross(b0 - a0), s1 = (a1 - a0).cross(b1 - a0);
    const double s2 = (b1 - b0).cross(a0 - b0), s3 = (b1 - b0).cross(a1 - b0);
    return ((s0 < 0.0 && s1 > 0.0) || (s0 > 0.0 && s1 < 0.0)) && ((s2 < 0.0 && s3 > 0.0) || (s2 > 0.0 && s3 < 0.0));
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

  // The join at one vertex between the true tangents arriving and leaving: the user's join at a corner,
  // round elsewhere (a dash vertex, a tangent-continuous junction seen through rounding).
  void vertex_join(const FlatVertex& vertex, std::size_t in, std::size_t out) {
    const Vec2 t_in = or_chord(vertex.tangent_in, directions_[in]), t_out = or_chord(vertex.tangent_out, directions_[out]);
    if (t_in == t_out) return;
    end_fold_run();  // the join's points go on the sides after F_j
    join(vertex.point, t_in, t_out, vertex.corner ? p_.join : LineJoin::kRound, lengths_[in], lengths_[out]);
  }

  // The join at the first vertex of a dash that starts exactly on a corner (the dasher keeps the corner
  // there, as Cairo draws it): traced alone from degenerate sides, "left forward, right backward" is the
  // wedge plus two zero-area spikes through the pivot, which cancel.
  void lone_join(Point p, Vec2 u, Vec2 v) {
    std::swap(left_, lone_left_);
    std::swap(right_, lone_right_);
    left_.clear();
    right_.clear();
    start_sides(p, u);
    join(p, u, v, p_.join, 0.0, 0.0);
    extra_.points.insert(extra_.points.end(), left_.begin(), left_.end());
    extra_.points.insert(extra_.points.end(), right_.rbegin(), right_.rend());
    extra_.ends.push_back(extra_.points.size());
    std::swap(left_, lone_left_);
    std::swap(right_, lone_right_);
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

    const double shorter = std::min(length_in, length_out);
    const bool direct = d > 0.0 && h * std::abs(c) <= 0.5 * shorter;
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
          const Vec2 bisector = unit_vector(u - v);
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

  // Appends the interior vertices of the arc around `center` starting at center + from (on the circle),
  // turning by `sweep` radians (positive from +x towards +y), spaced so that the polygon stays within
  // tolerance, at the radius that gives the polygon the sector's area (area_exact_radius).
  // The steps of the latest arc are kept (ArcSteps): every round cap sweeps the same half turn, so a dashed
  // stroke's caps compute their cosine, sine and radius once (two libm sine calls per cap before).
  void arc(std::vector<Point>& side, Point center, Vec2 from, double sweep, double min_steps = 1.0) {
    if (!(sweep == arc_steps_.sweep && min_steps == arc_steps_.min_steps)) {
      const double steps = std::max(min_steps, std::ceil(std::abs(sweep) / max_arc_step_));
      const int count = static_cast<int>(std::clamp(steps, 1.0, static_cast<double>(kMaxArcSegments)));
      const double step = sweep / count;
      const double radius = area_exact_radius(count, std::abs(step));
      arc_steps_ = {sweep, min_steps, count, std::cos(step), std::sin(step), radius};
    }
    const ArcSteps& a = arc_steps_;
    Vec2 offset = from * a.radius;
    for (int i = 1; i < a.count; ++i) {
      offset = rotate(offset, a.cos_step, a.sin_step);
      side.push_back(center + offset);
    }
  }

  // The radius ρ (relative to the circle's) of the interior vertices of an arc polygon of `count` steps of
  // `step` radians whose two end vertices are on the circle, such that the polygon (fanned from the
  // centre) has the sector's area: ½h²·sin(step)·(2ρ + (count − 2)ρ²) = ½h²·count·step. Inscribed
  // vertices (ρ = 1) leave a round cap or dot short by ~step²/6 of its area (2.5 % for a 1 px dot at
  // tolerance 0.02, the worst total of the stroke oracle). With ρ ≈ 1 + step²/12 the polygon's vertices are
  // outside the circle by ~h·step²/12 and its edges' middles inside by ~h·step²/24, both below the
  // inscribed polygon's h·step²/8 <= arc_tolerance (the step count is unchanged); ρ is capped at
  // 1 + arc_tolerance/h for arcs forced to a few steps (min_steps) on a stroke far thinner than tolerance.
  [[nodiscard]] double area_exact_radius(int count, double step) const noexcept {
    if (count < 2 || !(step > 0.0 && step <= std::numbers::pi / 2)) return 1.0;
    const double target = count * step / std::sin(step);  // 2ρ + (count − 2)ρ²
    const double rho = count == 2 ? target / 2.0 : (std::sqrt(1.0 + (count - 2) * target) - 1.0) / (count - 2);
    return std::min(rho, 1.0 + p_.arc_tolerance / p_.half_width);
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
      case LineCap::kRound:
        // The half circle's interior points only: its ends p ± normal are the sides' ends.
        arc(out_.points, p, normal, -std::numbers::pi);
        break;
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
  // arc()'s plan for a sweep (and min_steps): its step count, the cosine and sine of one step, and the
  // area-exact radius relative to h. A NaN sweep matches no arc.
  struct ArcSteps {
    double sweep = std::numeric_limits<double>::quiet_NaN();
    double min_steps = 0.0;
    int count = 1;
    double cos_step = 1.0, sin_step = 0.0, radius = 1.0;
  };
  ArcSteps arc_steps_;
  bool exceeded_ = false;
  std::vector<Point> left_, right_, lone_left_, lone_right_;
  Polygons extra_;  // fold runs' lobes, cusp discs: emitted after the contour's outline
  // The fold run in progress (chord_piece, end_fold_run): its side, F_i..F_k and x_i..x_k-1 so far.
  // Crossings of a fold run closer than this to the run's previous kept crossing are merged into it
  // (chord_piece): the traced boundary moves by at most the distance, 2^-10 of the arc tolerance, a
  // thousandth of the error the outline is already allowed (stroker.cpp's budget), while the rounding that
  // scatters coincident crossings is ~1e-12 of the coordinates (merged whenever coordinates stay below
  // about 10^9 tolerances).
  static constexpr double kFoldCrossingMergeFraction = 1.0 / 1024.0;
  double merge_distance_squared_ = 0.0;
  bool fold_active_ = false;
  bool fold_left_ = false;
  std::vector<Point> fold_side_, fold_crossings_;
  std::vector<Vec2> directions_;
  std::vector<double> lengths_;
};

}  // namespace

bool append_outlines(std::span<const FlatContour> contours, const OutlineParams& params, Polygons& out) {
  OutlineBuilder builder(params, out);
  for (std::size_t i = 0; i < contours.size();) {
    std::size_t count = 1;
    while (i + count < contours.size() && builder.continues_train(contours[i + count - 1], contours[i + count])) {
      ++count;
    }
    builder.stroke(contours.subspan(i, count));
    if (builder.exceeded()) return false;
    i += count;
  }
  return true;
}

}  // namespace curvescan::detail
