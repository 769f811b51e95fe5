// Figures after "Parametric Curves" (U. of Toronto course notes): the cubic of "A First Example", piecewise Hermite and
// Bézier continuity, and B-spline knots of multiplicity 1, 2 and 3.
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "curvescan/curves/basis_matrix.h"
#include "curvescan/curves/bspline.h"
#include "curvescan/curves/continuity.h"
#include "curvescan/curves/hermite.h"
#include "curvescan/curves/interpolate_points.h"
#include "figure/draw.h"
#include "figure/figure.h"
#include "figure/figures.h"
#include "figure/graphs.h"
#include "figure/palette.h"
#include "figure/plot.h"

namespace curvescan::figure {

namespace {

/// The cubic T·M·G as a Bézier: the power-form coefficients are the rows of M times G (U. of Toronto
/// "A = B_inv G"), converted exactly.
Bezier cubic_from_basis(const BasisMatrix& m, const std::array<Vec2, 4>& geometry) {
  std::array<Vec2, 4> rows{};
  for (std::size_t r = 0; r < 4; ++r) {
    for (std::size_t c = 0; c < 4; ++c) rows[r] += geometry[c] * m[r][c];
  }
  return CubicPowerForm{rows[0], rows[1], rows[2], Point::from_vec(rows[3])}.to_bezier();
}

}  // namespace

Result<Image> render_first_example() {
  // U. of Toronto "A First Example": the user gives P(0), P(0.5), P(1) and the tangent T(0.5); the cubic is
  // T·M·G with G = [P0 P0.5 T0.5 P1] and M = kMidpointTangentBasis. Left: one set of points with several
  // tangents ("The following figure illustrates some sample curves"); right: the blending functions.
  Result<Figure> made = Figure::create(960, 420);
  if (!made) return made.error();
  Figure& figure = *made;
  const Point p0{0.0, 0.0}, mid{2.0, 1.6}, p1{4.0, 0.0};
  const Plot left = Plot::fit(pixel_box(20.0, 60.0, 500.0, 300.0), Rect{-0.4, -1.2, 4.4, 3.0});
  draw_title(figure, left, "P(0), P(\xC2\xBD), P(1) fixed; tangent T(\xC2\xBD) varied");
  const std::array<Vec2, 4> tangents{Vec2{4.0, 0.0}, Vec2{8.0, 0.0}, Vec2{4.0, 3.0}, Vec2{4.0, -4.0}};
  std::vector<LegendEntry> legend;
  for (std::size_t k = 0; k < tangents.size(); ++k) {
    const Bezier curve =
        cubic_from_basis(kMidpointTangentBasis, {p0.to_vec(), mid.to_vec(), tangents[k], p1.to_vec()});
    draw_beziers(figure, left, std::array{curve}, series(k), 2.5);
    // Arrows a quarter of the tangent long: T is dP/dt, and a quarter of the parameter range fits the plot.
    draw_arrow(figure, left, mid, mid + tangents[k] * 0.25, series(k), 2.0);
    legend.push_back(
        {"T = (" + format_number(tangents[k].x, 0) + ", " + format_number(tangents[k].y, 0) + ")",
         series(k)});
  }
  for (Point p : {p0, mid, p1}) draw_marker(figure, left, p, kInk, Marker::kDisc, 4.5);
  draw_legend(figure, {40.0, 385.0}, std::span(legend).first(2));
  draw_legend(figure, {220.0, 385.0}, std::span(legend).subspan(2));

  const Plot right{pixel_box(620.0, 70.0, 300.0, 260.0), Rect{0.0, -0.3, 1.0, 1.1}};
  draw_title(figure, right, "its blending functions (T\xC2\xB7M)");
  Axes axes;
  axes.x_ticks = ticks(0.0, 1.0, 0.25);
  axes.y_ticks = ticks(-0.25, 1.0, 0.25);
  axes.x_decimals = 2;
  axes.y_decimals = 2;
  axes.x_label = "t";
  draw_axes(figure, right, axes);
  const std::array<const char*, 4> names{"P(0)", "P(\xC2\xBD)", "T(\xC2\xBD)", "P(1)"};
  std::vector<LegendEntry> blending;
  for (int j = 0; j < 4; ++j) {
    const auto index = static_cast<std::size_t>(j);
    draw_beziers(figure, right, std::array{blending_graph(kMidpointTangentBasis, j)}, series(index + 1), 2.5);
    blending.push_back({names[index], series(index + 1)});
  }
  draw_legend(figure, {640.0, 375.0}, std::span(blending).first(2), 11.0);
  draw_legend(figure, {790.0, 375.0}, std::span(blending).subspan(2), 11.0);
  return std::move(figure).finish();
}

Result<Image> render_piecewise_continuity() {
  // U. of Toronto "Hermite Curves" and "Geometric and Parametric Continuity": a piecewise Hermite curve shares
  // the point and the tangent at each join (C1 here: same tangent vector); as Béziers (P1 + R1/3, P4 - R4/3)
  // the control points around every join are collinear, the Bézier form of the same condition.
  const std::vector<Point> points{{0.0, 0.0}, {2.0, 2.0}, {4.5, 0.8}, {6.5, 2.4}};
  const std::vector<Vec2> tangents{{3.0, 4.0}, {3.0, 0.0}, {2.0, -1.5}, {3.0, 3.0}};
  Result<std::vector<Bezier>> pieces = hermite_spline(points, tangents);
  if (!pieces) return pieces.error();
  Result<Figure> made = Figure::create(960, 400);
  if (!made) return made.error();
  Figure& figure = *made;
  const Rect data{-0.4, -0.8, 7.2, 3.4};

  const Plot left = Plot::fit(pixel_box(20.0, 60.0, 440.0, 280.0), data);
  draw_title(figure, left, "Hermite: points and tangents (arrows: R/3)");
  for (std::size_t k = 0; k < pieces->size(); ++k) {
    draw_beziers(figure, left, std::span(*pieces).subspan(k, 1), series(k), 3.0);
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    draw_arrow(figure, left, points[i], points[i] + tangents[i] * (1.0 / 3.0), kInk, 1.75);
    draw_marker(figure, left, points[i], kInk, Marker::kDisc, 4.5);
  }

  const Plot right = Plot::fit(pixel_box(500.0, 60.0, 440.0, 280.0), data);
  draw_title(figure, right, "the same pieces as B\xC3\xA9ziers: joins collinear");
  for (std::size_t k = 0; k < pieces->size(); ++k) {
    draw_control_polygon(figure, right, (*pieces)[k].points(), series(k));
    draw_beziers(figure, right, std::span(*pieces).subspan(k, 1), series(k), 3.0);
  }
  for (std::size_t k = 0; k + 1 < pieces->size(); ++k) {
    const JoinContinuity join = classify_join((*pieces)[k], (*pieces)[k + 1]);
    draw_label(figure, right, "C" + std::to_string(join.parametric) + "/G" + std::to_string(join.geometric),
               (*pieces)[k].end(), {6.0, 22.0}, kInk, 12.0);
  }
  figure.text(
      "labels: continuity of each join as classify_join measures it (parametric C\xE1\xB5\x8F / geometric "
      "G\xE1\xB5\x8F)",
      {480.0, 380.0}, 12.0, kMutedInk, TextAnchor::kMiddle);
  return std::move(figure).finish();
}

Result<Image> render_knot_multiplicity() {
  // U. of Toronto "Splines" / Gallivan "knots can be simple or have multiplicity k ... manipulating multiplicity
  // affects shape": the same seven control points, the knot u = ½ with multiplicity 1, 2, 3. A cubic is
  // C^(3-k) at a knot of multiplicity k; at k = 3 the curve runs through a control point with a corner
  // allowed. Below each curve, its basis functions (drawn exactly, graphs.h).
  const std::vector<Point> control{{0.0, 0.0}, {0.6, 2.2}, {1.8, 2.6}, {2.6, 0.6},
                                   {3.4, 2.6}, {4.6, 2.2}, {5.2, 0.0}};
  const std::array<std::vector<double>, 3> knot_vectors{
      std::vector<double>{0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1},
      std::vector<double>{0, 0, 0, 0, 0.25, 0.5, 0.5, 1, 1, 1, 1},
      std::vector<double>{0, 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1, 1}};
  const std::array<const char*, 3> titles{"u = \xC2\xBD simple: C\xC2\xB2", "u = \xC2\xBD double: C\xC2\xB9",
                                          "u = \xC2\xBD triple: C\xE2\x81\xB0, through P\xE2\x82\x83"};
  Result<Figure> made = Figure::create(960, 470);
  if (!made) return made.error();
  Figure& figure = *made;
  Axes axes;
  axes.x_ticks = ticks(0.0, 1.0, 0.25);
  axes.y_ticks = {0.0, 1.0};
  axes.x_decimals = 2;
  axes.x_label = "u";
  for (std::size_t k = 0; k < knot_vectors.size(); ++k) {
    Result<BSpline> spline = BSpline::create(control, knot_vectors[k], 3);
    if (!spline) return spline.error();
    const double x = 20.0 + 315.0 * static_cast<double>(k);
    const Plot curve = Plot::fit(pixel_box(x, 50.0, 295.0, 200.0), Rect{-0.3, -0.3, 5.5, 3.0});
    draw_title(figure, curve, titles[k]);
    draw_control_polygon(figure, curve, control, kControl);
    const std::vector<Bezier> segments = spline->to_beziers();
    for (std::size_t s = 0; s < segments.size(); ++s) {
      draw_beziers(figure, curve, std::span(segments).subspan(s, 1), series(s), 3.0);
    }
    for (double u : spline->bezier_breakpoints())
      draw_marker(figure, curve, spline->eval(u), kInk, Marker::kSquare, 3.5);

    const Plot basis{pixel_box(x + 40.0, 300.0, 240.0, 110.0), Rect{0.0, 0.0, 1.0, 1.05}};
    draw_axes(figure, basis, axes);
    for (std::size_t i = 0; i < control.size(); ++i) {
      draw_beziers(figure, basis, basis_function_graph(knot_vectors[k], 3, i), series(i), 2.0);
    }
  }
  figure.text(
      "top: curve segments in colour, \xE2\x96\xA0 knots; bottom: the cubic basis functions "
      "N\xE1\xB5\xA2,\xE2\x82\x83(u) "
      "on knots 0,0,0,0, \xE2\x80\xA6, 1,1,1,1",
      {480.0, 458.0}, 12.0, kMutedInk, TextAnchor::kMiddle);
  return std::move(figure).finish();
}

}  // namespace curvescan::figure
