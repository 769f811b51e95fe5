// Path: an immutable, validated sequence of contours made of lines and (rational) Bézier segments of any
// degree. Built only by PathBuilder (path_builder.h), which checks every coordinate.
//
// Guarantees of every Path (after tiny-skia's Path, which documents the same kind of invariant):
//  - every point and every weight is finite, and every weight is > 0;
//  - every contour starts with kMove, and a kMove is always followed by at least one drawing verb (no
//    empty contours, no trailing move);
//  - kClose only ever ends a contour: it is followed by kMove or by the end of the path;
//  - kBezier and kRationalBezier segments have degree 1..kMaxPathCurveDegree (limits.h);
//  - bounds() is the finite box of all control points (a path with no verbs has the zero box).
// So the flattener and the rasterizer downstream never see NaN, infinity or a segment without a start.
//
// Storage is three flat arrays as in tiny-skia and Skia: verbs, points (each drawing verb appends the
// points after its start, its start being the previous point), weights (rational verbs only, one per
// control point including the start, so a conic stores (1, w, 1)). Iterating yields PathElements whose
// `points` span includes the segment's start point, ready for flatten_bezier / flatten_rational.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <span>
#include <vector>

#include "curvescan/curves/affine.h"
#include "curvescan/curves/point.h"
#include "curvescan/curves/rect.h"
#include "curvescan/status.h"

namespace curvescan {

// FillRule and Antialias: how the rasterizer turns winding numbers into coverage.
/// SVG fill-rule / Cairo fill rule.
enum class FillRule {
  kNonZero,  ///< inside where the winding number is not zero
  kEvenOdd,  ///< inside where the winding number is odd
};

enum class Antialias {
  kExact,  ///< coverage = exact area of the (rule-resolved) shape inside the pixel square
  kNone,   ///< aliased: a pixel is fully covered iff its centre is inside
};

enum class PathVerb : std::uint8_t {
  kMove,            ///< starts a contour at one point
  kLine,            ///< straight segment to one point
  kQuad,            ///< quadratic Bézier: control point, end point
  kCubic,           ///< cubic Bézier: two control points, end point
  kConic,           ///< rational quadratic with weights (1, w, 1): control point, end point
  kBezier,          ///< polynomial Bézier of any degree n: n points after the start
  kRationalBezier,  ///< rational Bézier of any degree n: n points after the start, n + 1 weights
  kClose,           ///< straight segment back to the contour's start; ends the contour
};

/// One verb of a Path with the geometry it needs, as iteration yields it.
struct PathElement {
  PathVerb verb = PathVerb::kMove;
  /// kMove: {the point}. Drawing verbs: the control points *including the start*, degree + 1 of them
  /// (kLine: {start, end}; kCubic: {start, c1, c2, end}). kClose: empty (use start/end below).
  std::span<const Point> points;
  /// Rational verbs (kConic, kRationalBezier): one weight per entry of `points`. Otherwise empty.
  std::span<const double> weights;
  /// The element's first and last point: for kMove both the point, for kClose the current point and the
  /// contour's start (the implicit closing line), for drawing verbs points.front() and points.back().
  Point start;
  Point end;

  /// Degree of the segment (kLine and kClose 1, kQuad/kConic 2, ...); 0 for kMove.
  [[nodiscard]] int degree() const noexcept {
    return verb == PathVerb::kClose ? 1 : static_cast<int>(points.size()) - 1;
  }
  [[nodiscard]] bool is_rational() const noexcept { return !weights.empty(); }
};

class PathBuilder;

class Path {
 public:
  /// The empty path (no contours).
  Path() = default;

  [[nodiscard]] std::span<const PathVerb> verbs() const noexcept { return verbs_; }
  [[nodiscard]] std::span<const Point> points() const noexcept { return points_; }
  [[nodiscard]] std::span<const double> weights() const noexcept { return weights_; }
  [[nodiscard]] bool empty() const noexcept { return verbs_.empty(); }

  /// The box of all control points (every curve lies inside it: the convex hull property for positive
  /// weights; Ince, *Curves*, "Convex hull property"). Rect{} for the empty path.
  [[nodiscard]] Rect bounds() const noexcept { return bounds_; }
  /// The tight box of the curves themselves: exact extrema for lines, polynomial segments
  /// (Bezier::bounding_box) and rational ones (RationalBezier::bounding_box: an SVG arc's box is its
  /// ellipse's extent over the arc, not its conics' control points). Rect{} for the empty path. Costs a
  /// pass over the segments.
  [[nodiscard]] Rect tight_bounds() const;

  /// The path with every point mapped by `transform`; weights unchanged. Exact for every verb: Bézier and
  /// rational Bézier curves are affine invariant, so transforming control points transforms the curve (Ince,
  /// *Curves*, "Affine invariance property"). Fails (kInvalidArgument) when `transform` is not finite or maps
  /// a point to a non-finite position (overflow), which would break the Guarantees.
  [[nodiscard]] Result<Path> transformed(const Affine& transform) const;

  /// Forward iteration over the elements, in order.
  class Iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = PathElement;
    using difference_type = std::ptrdiff_t;
    using pointer = const PathElement*;
    using reference = const PathElement&;

    Iterator() = default;
    reference operator*() const noexcept { return element_; }
    pointer operator->() const noexcept { return &element_; }
    Iterator& operator++() noexcept;
    Iterator operator++(int) noexcept {
      Iterator before = *this;
      ++*this;
      return before;
    }
    bool operator==(const Iterator& other) const noexcept { return verb_index_ == other.verb_index_; }

   private:
    friend class Path;
    Iterator(const Path* path, std::size_t verb_index) noexcept;
    void load() noexcept;  // fills element_ for verb_index_ (when not at the end)

    const Path* path_ = nullptr;
    std::size_t verb_index_ = 0;
    std::size_t point_index_ = 0;    // first point not yet consumed by an earlier verb
    std::size_t weight_index_ = 0;   // first weight not yet consumed
    std::size_t degree_index_ = 0;   // next entry of degrees_ (kBezier / kRationalBezier)
    std::size_t contour_start_ = 0;  // index of the current contour's kMove point
    PathElement element_;
  };
  [[nodiscard]] Iterator begin() const noexcept { return {this, 0}; }
  [[nodiscard]] Iterator end() const noexcept { return {this, verbs_.size()}; }

  bool operator==(const Path&) const = default;

 private:
  friend class PathBuilder;

  std::vector<PathVerb> verbs_;
  std::vector<Point> points_;
  std::vector<double> weights_;
  std::vector<std::uint16_t> degrees_;  // one per kBezier / kRationalBezier verb, in order
  Rect bounds_;
};

}  // namespace curvescan
