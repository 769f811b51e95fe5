// Figures after Umetani, "Parametric Curve": B-spline basis functions (Fig. 1), the Cox–de Boor
// step (Fig. 2), knot insertion (section 3.3) and the NURBS circle (section 4.1).
#include <cmath>
#include <string>
#include <vector>

#include "curvescan/curves/bspline.h"
#include "curvescan/curves/knot_vector.h"
#include "curvescan/curves/nurbs.h"
#include "figure/draw.h"
#include "figure/figure.h"
#include "figure/figures.h"
#include "figure/graphs.h"
#include "figure/palette.h"
#include "figure/plot.h"

namespace curvescan::figure {

namespace {

std::string subscript(int value) {
  // U+2080 SUBSCRIPT ZERO onwards: three UTF-8 bytes E2 82 80+d. DejaVu Sans has them.
  std::string digits = std::to_string(value);
  std::string out;
  for (char d : digits) out += std::string("\xE2\x82") + static_cast<char>(0x80 + (d - '0'));
  return out;
}

}  // namespace

Result<Image> render_bspline_basis() {
  // Umetani Fig. 1: one row per degree p = 0..3 on the uniform knots 0, 1, ..., 8. Each N_{i,p} is drawn
  // exactly (graphs.h): it is a B-spline curve itself.
  constexpr int kRows = 4;
  constexpr double kRowHeight = 150.0;
  Result<Figure> made = Figure::create(760, 60 + static_cast<int>(kRows * kRowHeight));
  if (!made) return made.error();
  Figure& figure = *made;
  figure.text(
      "B-spline basis functions N\xE2\x82\x8D\xE1\xB5\xA2,\xE2\x82\x9A\xE2\x82\x8E(u) on uniform knots "
      "u\xE1\xB5\xA2 = i (Umetani, Fig. 1)",
      {380.0, 30.0}, 16.0, kInk, TextAnchor::kMiddle);
  Result<std::vector<double>> knots = uniform_knots(5, 3);  // 9 knots 0..8
  if (!knots) return knots.error();
  for (int p = 0; p < kRows; ++p) {
    const double top = 55.0 + kRowHeight * p;
    const Plot plot{pixel_box(80.0, top, 640.0, kRowHeight - 50.0), Rect{0.0, 0.0, 8.0, 1.05}};
    Axes axes;
    axes.x_ticks = ticks(0.0, 8.0, 1.0);
    axes.y_ticks = {0.0, 0.5, 1.0};
    axes.y_decimals = 1;
    axes.x_label = p == kRows - 1 ? "u" : "";
    draw_axes(figure, plot, axes);
    figure.text("p = " + std::to_string(p), {12.0, top + 0.5 * (kRowHeight - 50.0) + 5.0}, 14.0, kInk);
    const std::size_t count = knots->size() - static_cast<std::size_t>(p) - 1;
    for (std::size_t i = 0; i < count; ++i) {
      const std::vector<Bezier> graph = basis_function_graph(*knots, p, i);
      draw_beziers(figure, plot, graph, series(i));
      if (p == 0) {
        // Degree 0 is a step: dotted risers show where it jumps (the value at the knot is the right one).
        const double u0 = (*knots)[i];
        draw_polyline(figure, plot, std::vector<Point>{{u0, 0.0}, {u0, 1.0}}, series(i), 1.0, {2.0, 3.0});
        draw_marker(figure, plot, {u0, 1.0}, series(i), Marker::kDisc, 3.5);
      }
      // Label each function at its peak: the middle of its support.
      const double mid = 0.5 * ((*knots)[i] + (*knots)[i + static_cast<std::size_t>(p) + 1]);
      const double peak = basis_function(*knots, p, i, mid);
      draw_label(figure, plot, "N" + subscript(static_cast<int>(i)) + "," + subscript(p), {mid, peak},
                 {0.0, -6.0}, series(i), 11.0, TextAnchor::kMiddle);
    }
  }
  return std::move(figure).finish();
}

Result<Image> render_cox_de_boor() {
  // Umetani Fig. 2 and eq. 7 on the knots 0, 1, 2, 3: N_{0,2}(u) = (u - u_0)/(u_2 - u_0) N_{0,1}(u)
  //                                                          + (u_3 - u)/(u_3 - u_1) N_{1,1}(u).
  // Each product is a quadratic on each unit span, drawn exactly through three of its values
  // (quadratic_graph); the values come from basis_function (graphs.h), the library's Cox–de Boor
  // reference evaluated where the whole support is inside the domain.
  const std::vector<double> knots{0.0, 1.0, 2.0, 3.0, 4.0};
  Result<Figure> made = Figure::create(960, 340);
  if (!made) return made.error();
  Figure& figure = *made;
  const auto left_ramp = [](double u) { return (u - 0.0) / (2.0 - 0.0); };
  const auto right_ramp = [](double u) { return (3.0 - u) / (3.0 - 1.0); };
  const auto left = [&](double u) { return left_ramp(u) * basis_function(knots, 1, 0, u); };
  const auto right = [&](double u) { return right_ramp(u) * basis_function(knots, 1, 1, u); };
  const auto product_graph = [](auto f, double a, double b) {
    std::vector<Bezier> pieces;
    for (double u = a; u < b; u += 1.0)
      pieces.push_back(quadratic_graph(u, u + 1.0, f(u), f(u + 0.5), f(u + 1.0)));
    return pieces;
  };
  Axes axes;
  axes.x_ticks = ticks(0.0, 3.0, 1.0);
  axes.y_ticks = {0.0, 0.5, 1.0};
  axes.y_decimals = 1;
  axes.x_label = "u";
  const Rect data{-0.1, 0.0, 3.1, 1.08};

  // Left: N_{0,1} and the ramp rising from 0 to 1 over its support [u_0, u_2].
  const Plot a{pixel_box(60.0, 70.0, 230.0, 200.0), data};
  draw_title(figure, a,
             "left: N\xE2\x82\x80,\xE2\x82\x81 \xC3\x97 (u \xE2\x88\x92 u\xE2\x82\x80)/(u\xE2\x82\x82 "
             "\xE2\x88\x92 u\xE2\x82\x80)");
  draw_axes(figure, a, axes);
  draw_beziers(figure, a, basis_function_graph(knots, 1, 0), with_alpha(kBlue, 110), 2.0);
  draw_polyline(figure, a, std::vector<Point>{{0.0, 0.0}, {2.0, 1.0}}, kBlue, 1.25, {5.0, 4.0});
  draw_beziers(figure, a, product_graph(left, 0.0, 2.0), kBlue);

  // Middle: N_{1,1} and the ramp falling from 1 to 0 over [u_1, u_3].
  const Plot b{pixel_box(385.0, 70.0, 230.0, 200.0), data};
  draw_title(figure, b,
             "right: N\xE2\x82\x81,\xE2\x82\x81 \xC3\x97 (u\xE2\x82\x83 \xE2\x88\x92 u)/(u\xE2\x82\x83 "
             "\xE2\x88\x92 u\xE2\x82\x81)");
  draw_axes(figure, b, axes);
  draw_beziers(figure, b, basis_function_graph(knots, 1, 1), with_alpha(kVermillion, 110), 2.0);
  draw_polyline(figure, b, std::vector<Point>{{1.0, 1.0}, {3.0, 0.0}}, kVermillion, 1.25, {5.0, 4.0});
  draw_beziers(figure, b, product_graph(right, 1.0, 3.0), kVermillion);

  // Right: their sum is N_{0,2}, one span wider than either (Umetani section 3.2).
  const Plot c{pixel_box(710.0, 70.0, 230.0, 200.0), data};
  draw_title(figure, c, "sum: N\xE2\x82\x80,\xE2\x82\x82 (one span wider)");
  draw_axes(figure, c, axes);
  draw_beziers(figure, c, product_graph(left, 0.0, 2.0), kBlue, 1.5, {5.0, 4.0});
  draw_beziers(figure, c, product_graph(right, 1.0, 3.0), kVermillion, 1.5, {5.0, 4.0});
  draw_beziers(figure, c, basis_function_graph(knots, 2, 0), kGreen, 3.0);
  figure.text("+", {322.0, 178.0}, 26.0, kInk, TextAnchor::kMiddle);
  figure.text("=", {647.0, 178.0}, 26.0, kInk, TextAnchor::kMiddle);
  figure.text(
      "Cox\xE2\x80\x93"
      "de Boor, Umetani eq. 7: solid = product, dashed = the linear ramp, faint = the p = 1 function",
      {480.0, 326.0}, 12.0, kMutedInk, TextAnchor::kMiddle);
  return std::move(figure).finish();
}

Result<Image> render_knot_insertion() {
  // Umetani section 3.3: inserting a knot keeps the curve and moves p control points onto the old
  // polygon (Boehm's rule, BSpline::insert_knot, which also documents the notes' eq. 8 index slip).
  Result<BSpline> curve =
      BSpline::clamped({{0.0, 0.0}, {1.0, 2.2}, {3.0, 2.6}, {4.2, 0.6}, {6.0, 0.2}, {7.0, 2.4}}, 3);
  if (!curve) return curve.error();
  constexpr double kInserted = 0.45;
  const BSpline refined = curve->insert_knot(kInserted);
  Result<Figure> made = Figure::create(960, 400);
  if (!made) return made.error();
  Figure& figure = *made;
  const Rect data{-0.4, -0.5, 7.4, 3.0};
  const auto knot_markers = [&](const Plot& plot, const BSpline& spline) {
    for (double u : spline.bezier_breakpoints())
      draw_marker(figure, plot, spline.eval(u), kInk, Marker::kSquare, 3.5);
  };

  const Plot before = Plot::fit(pixel_box(30.0, 60.0, 430.0, 280.0), data);
  draw_title(figure, before, "before: knots 0,0,0,0, \xE2\x85\x93, \xE2\x85\x94, 1,1,1,1");
  draw_control_polygon(figure, before, curve->points(), kControl);
  draw_beziers(figure, before, curve->to_beziers(), kBlue);
  knot_markers(before, *curve);
  for (std::size_t i = 0; i < curve->points().size(); ++i) {
    draw_label(figure, before, "P" + subscript(static_cast<int>(i)), curve->points()[i], {6.0, -6.0},
               kMutedInk);
  }

  const Plot after = Plot::fit(pixel_box(500.0, 60.0, 430.0, 280.0), data);
  draw_title(figure, after, "after inserting u = 0.45: one more control point");
  draw_polyline(figure, after, curve->points(), with_alpha(kControl, 150), 1.25, {5.0, 4.0});
  draw_control_polygon(figure, after, refined.points(), kVermillion);
  draw_beziers(figure, after, refined.to_beziers(), kBlue);
  knot_markers(after, refined);
  draw_marker(figure, after, refined.eval(kInserted), kGreen, Marker::kDiamond, 5.0);
  for (std::size_t i = 0; i < refined.points().size(); ++i) {
    draw_label(figure, after, "Q" + subscript(static_cast<int>(i)), refined.points()[i], {6.0, 14.0},
               kVermillion);
  }
  const std::vector<LegendEntry> legend{{"the curve (unchanged)", kBlue},
                                        {"old control polygon P", kControl, true},
                                        {"new control polygon Q", kVermillion, true}};
  draw_legend(figure, {40.0, 362.0}, std::span(legend).first(1));
  draw_legend(figure, {330.0, 362.0}, std::span(legend).subspan(1, 1));
  draw_legend(figure, {620.0, 362.0}, std::span(legend).subspan(2, 1));
  figure.text("\xE2\x96\xA0 knots on the curve   \xE2\x97\x86 the inserted knot", {480.0, 392.0}, 12.0,
              kMutedInk, TextAnchor::kMiddle);
  return std::move(figure).finish();
}

Result<Image> render_nurbs_circle() {
  // Umetani section 4.1: the 9-point quadratic NURBS circle (Nurbs::circle), drawn exactly as its four
  // rational quadratic pieces (Nurbs::to_rational_beziers), with the weights at the control points.
  Result<Nurbs> circle = Nurbs::circle({0.0, 0.0}, 1.0);
  if (!circle) return circle.error();
  Result<Figure> made = Figure::create(560, 560);
  if (!made) return made.error();
  Figure& figure = *made;
  figure.text(
      "The exact circle as a quadratic NURBS (Umetani \xC2\xA7"
      "4.1)",
      {280.0, 30.0}, 16.0, kInk, TextAnchor::kMiddle);
  const Plot plot = Plot::fit(pixel_box(60.0, 60.0, 440.0, 420.0), Rect{-1.35, -1.35, 1.35, 1.35});
  const std::vector<Point> points = circle->points();
  const std::vector<double> weights = circle->weights();
  draw_control_polygon(figure, plot, points, kControl);
  const std::vector<RationalBezier> quarters = circle->to_rational_beziers();
  for (std::size_t q = 0; q < quarters.size(); ++q) {
    draw_rational_beziers(figure, plot, std::span(quarters).subspan(q, 1), series(q), 3.0);
  }
  for (double u : circle->bezier_breakpoints())
    draw_marker(figure, plot, circle->eval(u), kInk, Marker::kSquare, 3.5);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {  // the last point repeats the first
    const bool corner = weights[i] < 0.99;
    const Vec2 outward = points[i].to_vec() * (1.0 / points[i].to_vec().length());
    // Side labels need more room than top and bottom ones: text is wider than tall.
    const Point at = points[i] + outward * (std::abs(outward.x) > 0.9 ? 0.25 : 0.13);
    draw_label(figure, plot,
               corner ? "w = \xE2\x88\x9A"
                        "2/2"
                      : "w = 1",
               at, {0.0, 4.0}, corner ? kVermillion : kMutedInk, 12.0, TextAnchor::kMiddle);
  }
  figure.text(
      "knots {0,0,0, \xC2\xBC,\xC2\xBC, \xC2\xBD,\xC2\xBD, \xC2\xBE,\xC2\xBE, 1,1,1} "
      "(\xE2\x96\xA0 on the curve)",
      {280.0, 510.0}, 12.0, kMutedInk, TextAnchor::kMiddle);
  figure.text("each quarter is one rational quadratic whose middle weight is cos 45\xC2\xB0", {280.0, 530.0},
              12.0, kMutedInk, TextAnchor::kMiddle);
  return std::move(figure).finish();
}

}  // namespace curvescan::figure
