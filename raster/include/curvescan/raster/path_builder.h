// PathBuilder: the only way to make a Path, and the place where user coordinates are validated.
//
// Commands are recorded as given; the first invalid one (a NaN or infinite coordinate, a weight <= 0, a
// drawing command before any move_to, a segment above kMaxPathCurveDegree) is remembered with its
// command index (0-based count of builder calls) and build() returns it as an Error naming that index,
// e.g. "path command 3 (line_to): the coordinates are not finite (nan, 2)". Later commands are ignored.
//
// Contour rules (SVG 1.1 section 8.3 "path data"): move_to starts a new contour; consecutive move_to
// calls collapse to the last; a contour with only a move is dropped; after close() the current point is
// the closed contour's start and the next drawing command starts a new contour there.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/point.h"
#include "curvescan/curves/rational_bezier.h"
#include "curvescan/raster/path.h"
#include "curvescan/status.h"

namespace curvescan {

/// The centre parametrization of an SVG endpoint arc (SVG 1.1 appendix F.6.5), radii already corrected
/// (F.6.6). Angles in radians in the ellipse's frame, positive from +x towards +y.
struct SvgArcCenter {
  Point center;
  double rx = 0.0, ry = 0.0;  ///< the radii actually used: |rx|, |ry|, scaled up if too small
  double start_angle = 0.0;   ///< θ1
  double sweep_angle = 0.0;   ///< Δθ: > 0 when sweep is true, < 0 otherwise, |Δθ| > π iff large_arc
};

/// Converts the SVG arc from `from` to `to` (radii rx, ry, x axis rotated by `x_rotation` radians, flags
/// large_arc and sweep) to centre form, following SVG 1.1 F.6.5 step by step and F.6.6 for radii: negative
/// radii are taken as absolute values and radii too small to reach `to` are scaled up uniformly until the
/// ellipse just fits (then the centre is the chord's midpoint). nullopt when the arc is not an ellipse arc
/// (F.6.2): identical endpoints (the segment is omitted) or a zero radius (the segment is a line). NaN
/// input gives NaN in the result (callers validate first).
[[nodiscard]] std::optional<SvgArcCenter> svg_arc_center(Point from, Point to, double rx, double ry,
                                                         double x_rotation, bool large_arc,
                                                         bool sweep) noexcept;

class PathBuilder {
 public:
  PathBuilder() = default;

  /// Starts a new contour at p.
  PathBuilder& move_to(Point p);
  PathBuilder& line_to(Point p);
  /// Quadratic Bézier with control point c.
  PathBuilder& quad_to(Point c, Point p);
  PathBuilder& cubic_to(Point c1, Point c2, Point p);
  /// Conic (rational quadratic) with weights (1, weight, 1), weight finite and > 0: an ellipse arc for
  /// weight < 1, a parabola for 1, a hyperbola for > 1 (Umetani, *Parametric Curve*, section 4.1).
  PathBuilder& conic_to(Point c, Point p, double weight);
  /// Polynomial Bézier of degree points.size() from the current point through `points` (the last is the
  /// end point). Degree 1..kMaxPathCurveDegree.
  PathBuilder& bezier_to(std::span<const Point> points);
  /// Rational Bézier of degree n = points.size() from the current point; `weights` has n + 1 entries, the
  /// first for the current point. All finite and > 0. Weights are stored as given (not normalized), so
  /// the path holds exactly the curve it was given.
  PathBuilder& rational_bezier_to(std::span<const Point> points, std::span<const double> weights);

  /// Appends `curve` exactly. Continues the current contour when the current point equals curve.start()
  /// bit for bit, else starts a new contour at curve.start(). Degree 1..kMaxPathCurveDegree.
  PathBuilder& append(const Bezier& curve);
  PathBuilder& append(const RationalBezier& curve);

  /// Arc of the ellipse (center, rx, ry, x axis rotated by x_rotation radians) from start_angle through
  /// sweep_angle (radians, positive from +x towards +y, |sweep| clamped to one turn), as exact conics
  /// (curves arc.h). Like cairo_arc: a line joins the current point to the arc's start, or a new contour
  /// starts there when there is no current point. A zero sweep adds only that line or move.
  PathBuilder& arc(Point center, double rx, double ry, double x_rotation, double start_angle,
                   double sweep_angle);
  /// SVG endpoint arc to `to` (SVG 1.1 F.6.5 and F.6.6, see svg_arc_center): a line when a radius is zero,
  /// nothing when `to` is the current point. The arc ends exactly at `to`.
  PathBuilder& svg_arc_to(double rx, double ry, double x_rotation, bool large_arc, bool sweep, Point to);

  /// Closes the current contour with a straight segment to its start. No effect without a drawn contour.
  PathBuilder& close();

  /// A closed polygon through `points` as one command: the same path as move_to(points[0]), line_to of
  /// each point after it, then close() (a single point is a move only; no points, nothing), checked and
  /// stored in one pass instead of one call per point (a stroke's outline has thousands of points).
  PathBuilder& polygon(std::span<const Point> points);

  /// The current point, if any (after close(): the closed contour's start).
  [[nodiscard]] std::optional<Point> current_point() const noexcept;
  /// The path so far, or the first error recorded. The builder can keep building afterwards.
  [[nodiscard]] Result<Path> build() const&;
  /// The same from a builder that is done: the path is moved out, not copied.
  [[nodiscard]] Result<Path> build() &&;

 private:
  // Every public command goes through begin_command() (which counts it and refuses once an error is
  // recorded) and fail() (which records the first error with the command's index and name).
  [[nodiscard]] bool begin_command();
  void fail(const char* command, ErrorKind kind, const std::string& what);
  [[nodiscard]] bool check_points(const char* command, std::span<const Point> points);
  [[nodiscard]] bool check_weights(const char* command, std::span<const double> weights);
  [[nodiscard]] bool check_degree(const char* command, std::size_t degree);
  // Emits the pending move (if any) so a drawing verb can follow; false (with an error) if there is no
  // current point at all.
  [[nodiscard]] bool ensure_contour(const char* command);
  void push_segment(PathVerb verb, std::span<const Point> points, std::span<const double> weights);

  Path path_;
  std::optional<Point> pending_move_;  // a move_to not yet followed by a drawing verb
  std::optional<Point> current_;       // current point
  Point contour_start_;
  bool contour_drawn_ = false;  // the current contour has at least one drawing verb
  std::size_t command_count_ = 0;
  std::optional<Error> error_;
};

}  // namespace curvescan
