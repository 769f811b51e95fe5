// The dasher: flattened contours -> their dashes, by arc length along the curve (SVG 2 §13.5.6): each chord
// counts as the circle arc its end tangents define (see arc_over_chord), so dash ends sit where they do
// on the true curve up to fourth-order terms.
//
// The pattern restarts at every subpath (SVG 2 and Cairo). The walk keeps the dash state (entry index,
// length left in the entry, on/off) across the segments of a contour and toggles wherever the length
// runs out, so a dash running through a vertex keeps the vertex — with its corner flag and true tangents —
// and gets a join there, not two caps. A toggle that lands exactly on a vertex takes that vertex's true
// tangent for the cap. On a closed contour whose pattern is on both at the start and at the end, the last
// dash continues into the first one through the closing join (Cairo does the same).
//
// Given a cull box (the part of the plane a caller draws, grown by the stroke's reach: stroke_reach.h),
// the walk makes no dashes on the pieces of chords outside it: it moves the pattern across them by
// arithmetic — whole periods at once — and cuts a dash that runs out of the box where it leaves (its cap
// there is outside the box, farther than the reach from anything drawn). A fine pattern on a path that runs
// far off the canvas then costs, and counts against the dash limit, only what can be seen; the dashes
// inside are laid at the same arc lengths as without the box.
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "curvescan/raster/limits.h"
#include "curvescan/raster/stroke.h"
#include "dash_contours.h"
#include "segment_in_box.h"
#include "stroke_contour.h"
#include "stroke_curve_piece.h"
#include "vector_length.h"

namespace curvescan::detail {
namespace {

Error too_many_dashes() {
  return Error{ErrorKind::kLimitExceeded, "the dash pattern would cut the path into more than " +
                                              std::to_string(kMaxDashSegments) +
                                              " dashes; use a longer pattern"};
}

class Dasher {
 public:
  Dasher(std::span<const double> dash_array, double dash_offset, const std::optional<Rect>& cull)
      : cull_(cull) {
    lengths_.assign(dash_array.begin(), dash_array.end());
    if (lengths_.size() % 2 == 1) lengths_.insert(lengths_.end(), dash_array.begin(), dash_array.end());
    for (const double l : lengths_) period_ += l;
    // Offset modulo the period, negative offsets included (SVG 2: "a negative value is equivalent to
    // the positive value modulo the pattern length"); then skip the entries it covers.
    double offset = std::fmod(dash_offset, period_);
    if (offset < 0.0) offset += period_;
    std::size_t index = 0;
    for (std::size_t step = 0; step < 2 * lengths_.size() && offset > 0.0 && offset >= lengths_[index]; ++step) {
      offset -= lengths_[index];
      index = (index + 1) % lengths_.size();
    }
    start_index_ = index;
    start_remaining_ = lengths_[index] - std::max(0.0, offset);
  }

  [[nodiscard]] double period() const noexcept { return period_; }
  [[nodiscard]] const std::optional<Rect>& cull() const noexcept { return cull_; }
  [[nodiscard]] std::size_t entry_count() const noexcept { return lengths_.size(); }

  Status dash(const FlatContour& contour, std::vector<FlatContour>& out) {
    index_ = start_index_;
    remaining_ = start_remaining_;
    const std::vector<FlatVertex>& v = contour.vertices;
    const bool on_at_start = index_ % 2 == 0;
    if (v.size() == 1) {
      if (on_at_start) out.push_back(contour);
      return Status::ok();
    }
    const std::size_t first_output = out.size();
    bool on = on_at_start;
    bool toggled = false;
    // The dash being walked (its vertices; it is copied out at its end, one allocation of its final size).
    std::vector<FlatVertex>& dash = dash_;
    dash.clear();
    if (on) dash.push_back({v[0].point, {}, v[0].tangent_out, false});
    const std::size_t n = v.size();
    const std::size_t segment_count = contour.closed ? n : n - 1;
    // Whether the walk covered the start and the end of the contour (not culled there): a closed contour's
    // last dash joins its first only then.
    bool walked_from_start = true, walked_to_end = true;
    // Ends the dash being walked at its last vertex (a cut where the walk leaves the cull box); a dash with
    // no length yet is dropped (it is outside the box: nothing of it could be seen).
    const auto cut_dash = [&] {
      if (on && dash.size() > 1) {
        dash.back().corner = false;
        emit(dash, out);
      }
      dash.clear();
      toggled = true;  // the contour is no longer one piece
    };
    for (std::size_t i = 0; i < segment_count; ++i) {
      const FlatVertex& a = v[i];
      const FlatVertex& b = v[(i + 1) % n];
      const Vec2 chord = b.point - a.point;
      const double chord_length = vector_length(chord);
      const Vec2 direction = chord / chord_length;
      const double length = chord_length * arc_over_chord(or_chord(a.tangent_out, direction), or_chord(b.tangent_in, direction));
      // The part of the chord walked, [s, end] in arc length: all of it, or what lies in the cull box.
      double s = 0.0, end = length;
      if (cull_) {
        const std::optional<SegmentSpan> inside = segment_in_box(a.point, b.point, *cull_);
        s = inside ? inside->t0 * length : length;
        end = inside ? inside->t1 * length : length;
        if (i == 0 && s > 0.0) walked_from_start = false;
        if (i + 1 == segment_count && end < length) walked_to_end = false;
      }
      if (s > 0.0) {  // culled up to s: cut at a, move the pattern across, resume at the box
        cut_dash();
        on = advance(s);
        const Point resume = s >= length ? b.point : a.point + direction * (chord_length * s / length);
        if (on) dash.assign(1, FlatVertex{resume, {}, direction, false});
      }
      while (remaining_ <= end - s) {
        s += remaining_;
        const bool at_vertex = s >= length;
        Point x = at_vertex ? b.point : a.point + direction * (chord_length * s / length);
        // Inside a chord the cap is cut on the curve's normal: at the curve point of the chord's piece
        // that projects where the dash end does, with its exact tangent (stroke_curve_piece.h); without a
        // piece (a line, dash_path) the tangent interpolated between the chord ends' true tangents.
        Vec2 tangent =
            interpolate_tangent(or_chord(a.tangent_out, direction), or_chord(b.tangent_in, direction), s / length);
        if (!at_vertex && a.piece >= 0) {
          const std::optional<CurvePoint> on_curve = curve_point_along(contour.piece(a.piece), x, direction);
          if (on_curve && on_curve->tangent.dot(tangent) > 0.0) {
            x = on_curve->point;
            tangent = on_curve->tangent;
          }
        }
        if (on) {
          push(dash, {x, at_vertex ? b.tangent_in : tangent, {}, false});
          emit(dash, out).degenerate_direction = at_vertex ? or_chord(b.tangent_in, direction) : tangent;
        } else {
          // A dash starting exactly on a corner keeps the corner: its join is drawn (Cairo does).
          const bool on_corner = at_vertex && b.corner;
          dash.assign(1, FlatVertex{x, on_corner ? b.tangent_in : Vec2{}, at_vertex ? b.tangent_out : tangent,
                                    on_corner});
        }
        on = !on;
        toggled = true;
        if (++toggles_ > 2 * kMaxDashSegments) return too_many_dashes();
        index_ = (index_ + 1) % lengths_.size();
        remaining_ = lengths_[index_];
      }
      remaining_ -= end - s;
      if (end < length) {  // culled from end on: cut where the chord leaves the box, resume at b
        if (on) push(dash, {a.point + direction * (chord_length * end / length), direction, {}, false});
        cut_dash();
        on = advance(length - end);
        if (on) dash.assign(1, FlatVertex{b.point, {}, b.tangent_out, false});
        continue;
      }
      if (on) push(dash, b);
    }
    if (!toggled) {
      out.push_back(contour);  // the pattern never switched off: the subpath unchanged
      return Status::ok();
    }
    if (!on) return Status::ok();
    if (contour.closed && on_at_start && walked_from_start && walked_to_end) {
      // Continue the last dash into the first through vertex 0 (pushed above with its corner data).
      FlatContour& first = out[first_output];
      dash.insert(dash.end(), first.vertices.begin() + 1, first.vertices.end());
      first = FlatContour{};
      first.vertices.assign(dash.begin(), dash.end());
      return Status::ok();
    }
    // A dash of positive length that began exactly at the end has no length on the path: nothing to draw
    // (only a zero-length dash entry draws a dot, and that one was finished inside the walk).
    if (dash.size() == 1) return Status::ok();
    // Open contour: the dash ends at the last vertex, with its true tangent for the cap.
    dash.back().corner = false;
    emit(dash, out);
    return Status::ok();
  }

 private:
  static Vec2 or_chord(Vec2 tangent, Vec2 chord) noexcept { return tangent == Vec2{} ? chord : tangent; }

  // Moves the pattern `distance` along the path without making dashes (a culled piece), whole periods at
  // once: a period has an even number of entries, so it leaves the entry and the on/off state as they
  // were. Returns whether the pattern is on afterwards. Toggles here are not counted: no dash is made.
  bool advance(double distance) {
    if (distance < remaining_) {
      remaining_ -= distance;
    } else {
      distance = std::fmod(distance - remaining_, period_);
      index_ = (index_ + 1) % lengths_.size();
      // The entries sum to the period up to rounding: at most one pass over them is left.
      for (std::size_t step = 0; step < lengths_.size() && distance >= lengths_[index_]; ++step) {
        distance -= lengths_[index_];
        index_ = (index_ + 1) % lengths_.size();
      }
      remaining_ = std::max(0.0, lengths_[index_] - distance);
    }
    return index_ % 2 == 0;
  }

  // Arc length / chord length of the curve between two vertices whose true tangents turn by δ: the
  // circle arc through both with those tangents has length chord·(δ/2)/sin(δ/2) (= 1 + δ²/24 + ...).
  // The polyline alone is short by that factor, which on a tight curve moves a dash end along the curve
  // enough to turn its cap visibly (a square cap's corner sits h·√2 from the curve). Chords whose
  // tangents turn by more than π/4 (a cusp cut down to a tiny piece) are measured as chords.
  //
  // Computed without atan2 and sin (about 180 instructions per chord, 0.8 % of a 1 px dashed stroke of
  // cubics): with x = sin²(δ/2) = (1 − cos δ)/2 = sin²δ / (2·(1 + cos δ)) (the last form has no
  // cancellation for small δ; the tangents are unit vectors), (δ/2)/sin(δ/2) = asin(√x)/√x =
  // Σ c_n·xⁿ with c_n = (2n)! / (4ⁿ·(n!)²·(2n + 1)) (Abramowitz and Stegun 4.4.40). On the range used,
  // x <= sin²(π/8) = 0.1464, the terms past n = 18 are below 1e-17: the sum is the quotient to a few ulps.
  static double arc_over_chord(Vec2 ta, Vec2 tb) noexcept {
    const double cross = ta.cross(tb), dot = ta.dot(tb);
    if (!(dot > 0.0)) return 1.0;  // δ >= π/2 (or NaN)
    const double x = cross * cross / (2.0 * (1.0 + dot));
    // δ/2 in (1e-6, π/8]: sin²(1e-6) = 1e-12 to a relative 1e-12, sin²(π/8) = (2 − √2)/4.
    if (!(x > 1e-12 && x <= (2.0 - std::numbers::sqrt2) / 4.0)) return 1.0;
    double sum = kAsinSeries.back();
    for (std::size_t n = kAsinSeries.size() - 1; n-- > 0;) sum = sum * x + kAsinSeries[n];
    return sum;
  }

  // c_n of arc_over_chord's series, n = 0 .. 18: c_n = a_n / (2n + 1), a_0 = 1, a_n = a_{n−1}·(2n − 1)/(2n).
  static constexpr std::array<double, 19> kAsinSeries = [] {
    std::array<double, 19> c{};
    double a = 1.0;
    for (std::size_t n = 0; n < c.size(); ++n) {
      if (n > 0) a *= static_cast<double>(2 * n - 1) / static_cast<double>(2 * n);
      c[n] = a / static_cast<double>(2 * n + 1);
    }
    return c;
  }();

  // Dashes keep no curve pieces (the outline does not use them): the vertex's piece index is dropped.
  static void push(std::vector<FlatVertex>& dash, const FlatVertex& vertex) {
    if (!dash.empty() && dash.back().point == vertex.point) return;
    dash.push_back(vertex);
    dash.back().piece = -1;
  }

  // Appends the dash walked so far to `out` as a contour of its own, its vertices in one allocation (grown
  // vertex by vertex they took three or four per dash: about 3 % of a 1 px dashed stroke), and returns it.
  static FlatContour& emit(const std::vector<FlatVertex>& dash, std::vector<FlatContour>& out) {
    FlatContour& contour = out.emplace_back();
    contour.vertices.assign(dash.begin(), dash.end());
    return contour;
  }

  std::optional<Rect> cull_;  // no dashes are made outside this box (see the top of this file)
  std::vector<double> lengths_;
  double period_ = 0.0;
  std::size_t start_index_ = 0;
  double start_remaining_ = 0.0;
  std::size_t index_ = 0;
  double remaining_ = 0.0;
  std::int64_t toggles_ = 0;
  std::vector<FlatVertex> dash_;  // dash(): the vertices of the dash being walked (storage reused)
};

// Polyline length of the parts of a contour inside `box`.
double contour_length_in_box(const FlatContour& contour, const Rect& box) noexcept {
  double length = 0.0;
  const std::size_t n = contour.vertices.size();
  const std::size_t segment_count = contour.closed ? n : n - 1;
  for (std::size_t i = 0; n > 1 && i < segment_count; ++i) {
    const Point a = contour.vertices[i].point, b = contour.vertices[(i + 1) % n].point;
    if (const std::optional<SegmentSpan> inside = segment_in_box(a, b, box)) {
      length += (inside->t1 - inside->t0) * vector_length(b - a);
    }
  }
  return length;
}

}  // namespace

Status dash_contours(std::span<const FlatContour> contours, std::span<const double> dash_array,
                     double dash_offset, std::vector<FlatContour>& out, const std::optional<Rect>& cull) {
  Dasher dasher(dash_array, dash_offset, cull);
  // Refuse before dashing: each period of the pattern makes entry_count / 2 dashes, plus one per contour
  // (lengths within the cull box only).
  double expected = 0.0;
  for (const FlatContour& contour : contours) {
    const double length = cull ? contour_length_in_box(contour, *cull) : contour_length(contour);
    expected += std::floor(length / dasher.period()) * static_cast<double>(dasher.entry_count() / 2) + 1.0;
  }
  if (!(expected <= static_cast<double>(kMaxDashSegments))) return too_many_dashes();
  const std::size_t before = out.size();
  for (const FlatContour& contour : contours) {
    if (Status status = dasher.dash(contour, out); !status) {
      out.resize(before);
      return status;
    }
  }
  return Status::ok();
}

}  // namespace curvescan::detail
