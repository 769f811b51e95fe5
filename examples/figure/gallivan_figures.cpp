// Figures after Gallivan, "Parametric Curves": interpolating points on a circle with uniform and
// with cumulative-length parameters, and a closed curve.
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "curvescan/curves/arc.h"
#include "curvescan/curves/bspline.h"
#include "curvescan/curves/cubic_spline.h"
#include "figure/draw.h"
#include "figure/figure.h"
#include "figure/figures.h"
#include "figure/palette.h"
#include "figure/plot.h"

namespace curvescan::figure {

Result<Image> render_circle_parametrization() {
  // Gallivan "Parameterization": points (x_i, y_i) on a circle, fitted by x(t) and y(t) separately with
  // t_i = i/n ("simple uniform scale") or t_i = cumulative chord length ("cumulative length scale").
  // Unevenly spaced points make the difference visible: uniform parameters pretend every step is equally
  // long, so the curve overshoots on the long steps.
  constexpr double kDegree = std::numbers::pi / 180.0;
  const std::array<double, 9> angles{0.0, 15.0, 35.0, 110.0, 130.0, 200.0, 215.0, 300.0, 320.0};
  std::vector<Point> points;
  for (double a : angles) points.push_back({std::cos(a * kDegree), std::sin(a * kDegree)});
  Result<Figure> made = Figure::create(960, 440);
  if (!made) return made.error();
  Figure& figure = *made;
  const std::vector<RationalBezier> circle =
      elliptical_arc_conics({0.0, 0.0}, 1.0, 1.0, 0.0, 0.0, 2.0 * std::numbers::pi);
  const Rect data{-1.45, -1.45, 1.45, 1.45};
  const std::array<SplineParameterization, 2> kinds{SplineParameterization::kUniform,
                                                    SplineParameterization::kChordLength};
  const std::array<const char*, 2> titles{
      "uniform: t\xE1\xB5\xA2 = i/n", "cumulative length: t\xE1\xB5\xA2 = \xCE\xA3 \xE2\x84\x93\xE2\x82\x96"};
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    CubicSplineOptions options;
    options.parameterization = kinds[k];
    Result<std::vector<Bezier>> spline = cubic_spline(points, options);
    if (!spline) return spline.error();
    const Plot plot = Plot::fit(pixel_box(40.0 + 460.0 * static_cast<double>(k), 60.0, 420.0, 320.0), data);
    draw_title(figure, plot, titles[k]);
    draw_rational_beziers(figure, plot, circle, kGrid, 6.0);
    draw_beziers(figure, plot, *spline, series(k), 3.0);
    for (std::size_t i = 0; i < points.size(); ++i) {
      draw_marker(figure, plot, points[i], kInk, Marker::kDisc, 4.0);
      draw_label(figure, plot, std::to_string(i), points[i],
                 {points[i].x * 14.0 - 4.0, -points[i].y * 14.0 + 4.0}, kMutedInk, 11.0);
    }
  }
  figure.text(
      "natural C\xC2\xB2 cubic splines through nine points on the unit circle (grey: the circle itself, "
      "an exact conic)",
      {480.0, 420.0}, 12.0, kMutedInk, TextAnchor::kMiddle);
  return std::move(figure).finish();
}

Result<Image> render_closed_curve() {
  // Gallivan "Closed Curve Data": "For a closed curve add (t_{n+1}, x_0), (t_{n+1}, y_0)" — a periodic
  // spline through the points; and "repeating knots and control points closes the curve" — a closed
  // B-spline with the same points as its control polygon. The first point is marked: the notes ask
  // "Where is (x_0, y_0)?", since a closed C2 curve shows no seam.
  const std::vector<Point> points{{0.0, 0.0}, {1.6, -0.5}, {3.0, 0.4}, {3.4, 2.0},
                                  {2.2, 2.4}, {1.6, 1.4},  {0.6, 2.6}, {-0.6, 1.6}};
  Result<Figure> made = Figure::create(960, 420);
  if (!made) return made.error();
  Figure& figure = *made;
  const Rect data{-1.0, -0.9, 3.8, 3.0};
  CubicSplineOptions options;
  options.ends = SplineEnds::kClosed;
  Result<std::vector<Bezier>> through = cubic_spline(points, options);
  if (!through) return through.error();
  Result<BSpline> around = BSpline::closed(points, 3);
  if (!around) return around.error();

  const Plot left = Plot::fit(pixel_box(30.0, 60.0, 430.0, 300.0), data);
  draw_title(figure, left, "closed cubic spline through the points");
  draw_beziers(figure, left, *through, kBlue, 3.0);
  for (Point p : points) draw_marker(figure, left, p, kInk, Marker::kDisc, 4.0);
  draw_marker(figure, left, points.front(), kVermillion, Marker::kDiamond, 5.5);
  draw_label(figure, left, "(x\xE2\x82\x80, y\xE2\x82\x80)", points.front(), {8.0, 16.0}, kVermillion, 12.0);

  const Plot right = Plot::fit(pixel_box(500.0, 60.0, 430.0, 300.0), data);
  draw_title(figure, right, "closed cubic B-spline around them");
  std::vector<Point> polygon = points;
  polygon.push_back(points.front());
  draw_control_polygon(figure, right, polygon, kControl);
  const std::vector<Bezier> segments = around->to_beziers();
  for (std::size_t k = 0; k < segments.size(); ++k) {
    draw_beziers(figure, right, std::span(segments).subspan(k, 1), series(k), 3.0);
  }
  for (double u : around->bezier_breakpoints())
    draw_marker(figure, right, around->eval(u), kInk, Marker::kSquare, 3.0);
  figure.text(
      "left: periodic end conditions, chord-length parameters; right: periodic knots, the first three "
      "points repeated at the end",
      {480.0, 400.0}, 12.0, kMutedInk, TextAnchor::kMiddle);
  return std::move(figure).finish();
}

}  // namespace curvescan::figure
