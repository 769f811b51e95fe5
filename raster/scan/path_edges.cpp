// Path -> edges. Each segment goes through the one flattener (flatten.h), whose polyline ends exactly at
// the segment's end point, so consecutive segments share their joints and each contour's edges form a
// closed loop: the winding number is then well defined everywhere (the rasterizer needs nothing else). A
// fill closes every contour; an explicit kClose adds the same closing edge.
//
// Cost (glyph_bench --profile, docs/text.md): a glyph is ~30 edges and ~25 elements, so what is paid per
// element and per edge, not the flattening arithmetic, decided the cost. Hence:
//  - the vertices of a contour are gathered in the scratch polyline (the flattener appends to it in
//    place) and given to the rasterizer in one add_polyline call, which builds the edges that lie inside
//    the clip box directly (edge_clip.h clip_polyline) instead of one add_line and one clip_edge call each;
//  - a path whose control-point box lies inside the clip box (every glyph in its own mask) skips the
//    curve cull, which would flatten such a curve whole anyway (curve_clip_cull.h: its hull meets the box
//    and is no larger than it), and its quadratics are tested against Wang's bound inline (one segment)
//    and otherwise go straight to flatten_quadratic_bezier_past_one_segment, which does not repeat that
//    test or the finiteness checks (the points are finite: Path's guarantees);
//  - paths made of the fixed-size verbs (all glyphs, most SVG) are walked on Path's flat arrays (path.h
//    "Storage") rather than through Path::Iterator.
// The edges, their order and the returned count are those of add_path_edges_reference (the plain loop:
// one element at a time through flatten_visible and add_line), which tests/unit/font holds equal.
#include "path_edges.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "curve_clip_cull.h"
#include "curvescan/curves/flatten.h"
#include "curvescan/curves/flatten_quadratic_uniform.h"
#include "path_verb_points.h"

namespace curvescan::detail {
namespace {

// Pending vertices are handed to the rasterizer once this many have gathered inside one contour, so the
// scratch stays small next to the edges themselves (one curve's polyline can still exceed it: it is
// flattened whole, as before).
constexpr std::size_t kFlushVertices = 4096;

Rect box_of(IntRect clip) noexcept {
  return {static_cast<double>(clip.x0), static_cast<double>(clip.y0), static_cast<double>(clip.x1),
          static_cast<double>(clip.y1)};
}

/// The max_segments of the next curve once `edges` of `max_edges` are used: one more than the edges left,
/// so that a curve cut at its cap takes the count past max_edges (the caller then refuses the fill), and a
/// curve that fits is flattened exactly as without a budget. Before, a curve got the flattener's own cap of
/// 2^22 segments whatever the budget: a fill under a 2^14-segment budget spent 30 s flattening one conic
/// (fuzz/regressions/raster_stroke/conic_weight_dbl_max_flattened_past_budget_*).
std::size_t curve_segment_cap(std::size_t edges, std::size_t max_edges) noexcept {
  const std::size_t left = edges < max_edges ? max_edges - edges : 0;
  return left < kMaxFlattenSegments ? left + 1 : kMaxFlattenSegments;
}

/// Whether `inner` lies in the closed box `outer` (false for NaN).
bool box_within(const Rect& inner, const Rect& outer) noexcept {
  return inner.x0 >= outer.x0 && inner.x1 <= outer.x1 && inner.y0 >= outer.y0 && inner.y1 <= outer.y1;
}

/// One element at a time to the contour being gathered; the contour goes to the rasterizer as a
/// polyline whose first vertex is the current point.
class ContourEdges {
 public:
  ContourEdges(const Path& path, double tolerance, Rasterizer& rasterizer, std::vector<Point>& polyline,
               std::size_t max_edges)
      : tolerance_(tolerance),
        max_edges_(max_edges),
        rasterizer_(rasterizer),
        polyline_(polyline),
        visible_box_(box_of(rasterizer.clip())) {
    // Only the rasterizer's clip box is ever covered: curves (or halves of huge curves) that miss it are
    // replaced by their chords, exactly (curve_clip_cull.h), unless the whole path lies inside the box.
    whole_path_visible_ = box_within(path.bounds(), visible_box_);
    tolerance_valid_ = std::isfinite(tolerance) && tolerance > 0.0;
    polyline_.clear();
    polyline_.push_back(contour_start_);  // the current point before the first kMove, as in the reference
  }

  [[nodiscard]] std::size_t edges() const noexcept { return edges_; }

  /// The element as the flat walk sees it: a verb, its control points (start included; empty for
  /// kClose) and weights.
  void add(PathVerb verb, std::span<const Point> points, std::span<const double> weights) {
    switch (verb) {
      case PathVerb::kMove:
        move_to(points[0]);
        break;
      case PathVerb::kLine:
        line_to(points[1]);
        break;
      case PathVerb::kClose:
        line_to(contour_start_);
        break;
      case PathVerb::kQuad:
      case PathVerb::kCubic:
      case PathVerb::kBezier:
      case PathVerb::kConic:
      case PathVerb::kRationalBezier:
        curve(verb, points, weights);
        break;
    }
    if (polyline_.size() >= kFlushVertices) flush();
  }

  /// Closes the last contour and hands everything pending to the rasterizer.
  void finish() {
    line_to(contour_start_);
    flush();
  }

  /// Hands the pending vertices to the rasterizer (the budget stop: what was counted was added).
  void flush() {
    rasterizer_.add_polyline(polyline_);
    const Point last = polyline_.back();
    polyline_.clear();
    polyline_.push_back(last);
  }

 private:
  void move_to(Point start) {
    line_to(contour_start_);  // the implicit close of the contour before
    flush();
    polyline_.back() = contour_start_ = start;
  }

  void line_to(Point end) {
    if (polyline_.back() != end) {
      polyline_.push_back(end);
      ++edges_;
    }
  }

  void curve(PathVerb verb, std::span<const Point> ctrl, std::span<const double> weights) {
    const std::size_t before = polyline_.size();
    const std::size_t cap = curve_segment_cap(edges_, max_edges_);
    FlattenOutcome outcome;
    if (!whole_path_visible_) {
      const PathElement element{verb, ctrl, weights, ctrl.front(), ctrl.back()};
      outcome = flatten_visible(element, tolerance_, visible_box_, polyline_, cap);
    } else if (verb == PathVerb::kQuad) {
      // flatten_bezier's first test, inline (about half the quadratics of a glyph at 12 px stop there, and
      // the call cost more than the test): Wang's bound, exact for a quadratic, |P0 - 2P1 + P2| / 4 within
      // the tolerance means one segment. The same expression as in flatten.cpp, so the same decision; the
      // checks it skips hold here (points inside the clip box, tolerance checked once, see the constructor).
      const Vec2 second = (ctrl[0] - ctrl[1]) + (ctrl[2] - ctrl[1]);
      if (tolerance_valid_ && 0.25 * std::sqrt(second.length_squared()) <= tolerance_) {
        polyline_.push_back(ctrl[2]);
        ++edges_;
        return;
      }
      outcome = tolerance_valid_
                    ? flatten_quadratic_bezier_past_one_segment(ctrl[0], ctrl[1], ctrl[2], tolerance_,
                                                                polyline_, cap)
                    : flatten_quadratic_bezier(ctrl[0], ctrl[1], ctrl[2], tolerance_, polyline_, cap);
    } else if (weights.empty()) {
      outcome = flatten_bezier(ctrl, tolerance_, polyline_, cap);
    } else {
      outcome = flatten_rational(ctrl, weights, tolerance_, polyline_, cap);
    }
    if (outcome == FlattenOutcome::kOk || outcome == FlattenOutcome::kSegmentLimit) {
      edges_ += polyline_.size() - before;
    } else {
      // Refused (which the Path Guarantees rule out, short of overflow inside the flattener): nothing was
      // appended, and the straight edge below keeps the contour closed.
      polyline_.resize(before);
    }
    line_to(ctrl.back());
  }

  double tolerance_;
  std::size_t max_edges_;
  Rasterizer& rasterizer_;
  std::vector<Point>& polyline_;
  Rect visible_box_;
  bool whole_path_visible_ = false;
  bool tolerance_valid_ = false;  // finite and > 0: flatten_bezier's checks on the tolerance pass
  Point contour_start_;
  std::size_t edges_ = 0;
};

/// ContourEdges specialised to the common case — every verb of fixed size, the whole path inside the clip
/// box, a finite positive tolerance: every glyph in its own mask — with its state in locals, one switch per
/// verb and the control points read in place (measured: a quarter of the walk's cost per element at
/// 12 px). Same steps as ContourEdges::add, so the same polyline and count (with kFewest).
///
/// kBudget false: max_edges is SIZE_MAX (no budget: MaskRenderer), so the budget test before each verb
/// never stops the walk and every curve's cap is kMaxFlattenSegments (curve_segment_cap of any edge count
/// below SIZE_MAX - 2^22, which memory bounds far below); both are left out of the loop.
template <QuadraticSteps kQuadratics, bool kBudget>
std::size_t add_visible_fixed_size_path(const Path& path, double tolerance, Rasterizer& rasterizer,
                                        std::vector<Point>& polyline, std::size_t max_edges) {
  const auto cap_now = [&](std::size_t edges_so_far) {
    if constexpr (kBudget) {
      return curve_segment_cap(edges_so_far, max_edges);
    } else {
      return kMaxFlattenSegments;
    }
  };
  const std::span<const Point> points = path.points();
  const std::span<const double> weights = path.weights();
  std::size_t next_point = 0;
  std::size_t next_weight = 0;
  std::size_t edges = 0;
  Point contour_start;
  Point current;  // always polyline.back()
  polyline.clear();
  polyline.push_back(current);
  const auto line_to = [&](Point end) {
    if (current != end) {
      polyline.push_back(end);
      current = end;
      ++edges;
    }
  };
  const auto flush = [&] {
    rasterizer.add_polyline(polyline);
    polyline.clear();
    polyline.push_back(current);
  };
  // A flattener's polyline, as ContourEdges::curve takes it.
  const auto take = [&](FlattenOutcome outcome, std::size_t before, Point end) {
    if (outcome == FlattenOutcome::kOk || outcome == FlattenOutcome::kSegmentLimit) {
      edges += polyline.size() - before;
    } else {
      polyline.resize(before);
    }
    current = polyline.back();
    line_to(end);
  };
  for (const PathVerb verb : path.verbs()) {
    if (kBudget && edges > max_edges) {
      flush();  // past the budget: the rest is neither flattened nor stored, the contour not closed
      return edges;
    }
    switch (verb) {
      case PathVerb::kMove:
        line_to(contour_start);
        flush();
        current = contour_start = points[next_point++];
        polyline.back() = current;
        break;
      case PathVerb::kLine:
        line_to(points[next_point++]);
        break;
      case PathVerb::kClose:
        line_to(contour_start);
        break;
      case PathVerb::kQuad: {
        const Point p0 = points[next_point - 1];
        const Point p1 = points[next_point];
        const Point p2 = points[next_point + 1];
        next_point += 2;
        // flatten_bezier's first test inline, as in ContourEdges::curve.
        const Vec2 second = (p0 - p1) + (p2 - p1);
        const double second_length = std::sqrt(second.length_squared());
        if (0.25 * second_length <= tolerance) {
          polyline.push_back(p2);
          current = p2;
          ++edges;
        } else {
          const std::size_t before = polyline.size();
          const std::size_t cap = cap_now(edges);
          if constexpr (kQuadratics == QuadraticSteps::kUniform) {
            // The same length as the uniform flattener's (flatten_quadratic_uniform.h): not taken twice.
            take(flatten_quadratic_bezier_uniform_with_length(p0, p1, p2, second_length, tolerance, polyline,
                                                              cap),
                 before, p2);
          } else {
            take(flatten_quadratic_bezier_past_one_segment(p0, p1, p2, tolerance, polyline, cap), before, p2);
          }
        }
        break;
      }
      case PathVerb::kCubic: {
        const std::span<const Point> ctrl = points.subspan(next_point - 1, 4);
        next_point += 3;
        const std::size_t before = polyline.size();
        take(flatten_bezier(ctrl, tolerance, polyline, cap_now(edges)), before, ctrl.back());
        break;
      }
      case PathVerb::kConic: {
        const std::span<const Point> ctrl = points.subspan(next_point - 1, 3);
        next_point += 2;
        const std::size_t before = polyline.size();
        take(flatten_rational(ctrl, weights.subspan(next_weight, 3), tolerance, polyline, cap_now(edges)),
             before, ctrl.back());
        next_weight += 3;
        break;
      }
      case PathVerb::kBezier:
      case PathVerb::kRationalBezier:
        break;  // not given to this walk (add_path_edges checks)
    }
    if (polyline.size() >= kFlushVertices) flush();
  }
  line_to(contour_start);
  flush();
  return edges;
}

// Walks the old way: the original add_polyline of the reference, one add_line per vertex.
std::size_t add_curve_reference(Point from, Point end, FlattenOutcome outcome,
                                const std::vector<Point>& polyline, Rasterizer& rasterizer) {
  Point current = from;
  std::size_t edges = 0;
  if (outcome == FlattenOutcome::kOk || outcome == FlattenOutcome::kSegmentLimit) {
    for (const Point p : polyline) {
      rasterizer.add_line(current, p);
      current = p;
    }
    edges = polyline.size();
  }
  if (current != end) {
    rasterizer.add_line(current, end);
    ++edges;
  }
  return edges;
}

}  // namespace

std::size_t add_path_edges(const Path& path, double tolerance, Rasterizer& rasterizer,
                           std::vector<Point>& polyline, std::size_t max_edges, QuadraticSteps quadratics) {
  const std::span<const PathVerb> verbs = path.verbs();
  const bool fixed_size = std::none_of(verbs.begin(), verbs.end(), [](PathVerb verb) {
    return verb == PathVerb::kBezier || verb == PathVerb::kRationalBezier;
  });
  if (fixed_size && std::isfinite(tolerance) && tolerance > 0.0 &&
      box_within(path.bounds(), box_of(rasterizer.clip()))) {
    const bool budget = max_edges != SIZE_MAX;
    if (quadratics == QuadraticSteps::kUniform) {
      return budget ? add_visible_fixed_size_path<QuadraticSteps::kUniform, true>(path, tolerance, rasterizer,
                                                                                  polyline, max_edges)
                    : add_visible_fixed_size_path<QuadraticSteps::kUniform, false>(
                          path, tolerance, rasterizer, polyline, max_edges);
    }
    return budget ? add_visible_fixed_size_path<QuadraticSteps::kFewest, true>(path, tolerance, rasterizer,
                                                                               polyline, max_edges)
                  : add_visible_fixed_size_path<QuadraticSteps::kFewest, false>(path, tolerance, rasterizer,
                                                                                polyline, max_edges);
  }
  ContourEdges contour(path, tolerance, rasterizer, polyline, max_edges);
  bool stopped = false;  // over the budget before the last element
  if (fixed_size) {
    // The Iterator's walk (path.cpp) for the fixed-size verbs: a drawing verb's points start at the
    // previous point; rational verbs take one weight per point, start included.
    const std::span<const Point> points = path.points();
    const std::span<const double> weights = path.weights();
    std::size_t next_point = 0;
    std::size_t next_weight = 0;
    for (const PathVerb verb : verbs) {
      if (contour.edges() > max_edges) {
        stopped = true;
        break;
      }
      if (verb == PathVerb::kMove) {
        contour.add(verb, points.subspan(next_point, 1), {});
        next_point += 1;
      } else if (verb == PathVerb::kClose) {
        contour.add(verb, {}, {});
      } else {
        const std::size_t count = fixed_point_count(verb);
        std::span<const double> verb_weights;
        if (verb == PathVerb::kConic) {
          verb_weights = weights.subspan(next_weight, count + 1);
          next_weight += count + 1;
        }
        contour.add(verb, points.subspan(next_point - 1, count + 1), verb_weights);
        next_point += count;
      }
    }
  } else {
    for (const PathElement& element : path) {
      if (contour.edges() > max_edges) {
        stopped = true;
        break;
      }
      contour.add(element.verb, element.points, element.weights);
    }
  }
  if (stopped) {
    contour.flush();  // past the budget: the rest is neither flattened nor stored, the contour not closed
  } else {
    contour.finish();
  }
  return contour.edges();
}

std::size_t add_path_edges_reference(const Path& path, double tolerance, Rasterizer& rasterizer,
                                     std::vector<Point>& polyline, std::size_t max_edges) {
  const Rect visible_box = box_of(rasterizer.clip());
  Point contour_start;
  Point current;
  std::size_t edges = 0;
  for (const PathElement& element : path) {
    if (edges > max_edges) return edges;
    switch (element.verb) {
      case PathVerb::kMove:
        if (current != contour_start) {
          rasterizer.add_line(current, contour_start);  // implicit close
          ++edges;
        }
        contour_start = current = element.start;
        break;
      case PathVerb::kLine:
      case PathVerb::kClose:
        if (element.start != element.end) {
          rasterizer.add_line(element.start, element.end);
          ++edges;
        }
        current = element.end;
        break;
      case PathVerb::kQuad:
      case PathVerb::kCubic:
      case PathVerb::kBezier:
      case PathVerb::kConic:
      case PathVerb::kRationalBezier: {
        polyline.clear();
        const FlattenOutcome outcome =
            flatten_visible(element, tolerance, visible_box, polyline, curve_segment_cap(edges, max_edges));
        edges += add_curve_reference(element.start, element.end, outcome, polyline, rasterizer);
        current = element.end;
        break;
      }
    }
  }
  if (current != contour_start) {
    rasterizer.add_line(current, contour_start);
    ++edges;
  }
  return edges;
}

}  // namespace curvescan::detail
