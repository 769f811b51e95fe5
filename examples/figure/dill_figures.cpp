// Figures after Dill, "Introduction to Parametric Curves": Hermite and Bézier blending functions, joining
// Béziers with C0, C1 and C2 continuity, and degree raising.
#include <array>
#include <string>
#include <vector>

#include "curvescan/curves/basis_matrix.h"
#include "curvescan/curves/bezier.h"
#include "curvescan/curves/continuity.h"
#include "figure/draw.h"
#include "figure/figure.h"
#include "figure/figures.h"
#include "figure/graphs.h"
#include "figure/palette.h"
#include "figure/plot.h"

namespace curvescan::figure {

Result<Image> render_hermite_blending() {
  // Dill "Blending Functions" (the plot under "The Hermite blending functions are plotted in the
  // figure below"), from the Hermite matrix M_h of basis_matrix.h; each is one cubic, drawn exactly.
  Result<Figure> made = Figure::create(760, 460);
  if (!made) return made.error();
  Figure& figure = *made;
  const Plot plot{pixel_box(80.0, 60.0, 420.0, 330.0), Rect{0.0, -0.25, 1.0, 1.05}};
  draw_title(figure, plot, "Hermite blending functions (Dill, U. of Toronto)");
  Axes axes;
  axes.x_ticks = ticks(0.0, 1.0, 0.25);
  axes.y_ticks = ticks(-0.25, 1.0, 0.25);
  axes.x_decimals = 2;
  axes.y_decimals = 2;
  axes.x_label = "t";
  draw_axes(figure, plot, axes);
  const std::array<std::string, 4> labels{
      "F\xE2\x82\x81 = 2t\xC2\xB3 \xE2\x88\x92 3t\xC2\xB2 + 1  (weights P\xE2\x82\x81)",
      "F\xE2\x82\x82 = \xE2\x88\x92"
      "2t\xC2\xB3 + 3t\xC2\xB2  (weights P\xE2\x82\x82)",
      "F\xE2\x82\x83 = t\xC2\xB3 \xE2\x88\x92 2t\xC2\xB2 + t  (weights R\xE2\x82\x81)",
      "F\xE2\x82\x84 = t\xC2\xB3 \xE2\x88\x92 t\xC2\xB2  (weights R\xE2\x82\x82)"};
  std::vector<LegendEntry> legend;
  for (int j = 0; j < 4; ++j) {
    const auto index = static_cast<std::size_t>(j);
    draw_beziers(figure, plot, std::array{blending_graph(kHermiteBasis, j)}, series(index), 3.0);
    legend.push_back({labels[index], series(index)});
  }
  draw_legend(figure, {520.0, 120.0}, legend, 12.0);
  figure.text(
      "P(t) = F\xE2\x82\x81P\xE2\x82\x81 + F\xE2\x82\x82P\xE2\x82\x82 + F\xE2\x82\x83R\xE2\x82\x81 + "
      "F\xE2\x82\x84R\xE2\x82\x82",
      {520.0, 260.0}, 13.0, kInk);
  figure.text("(Dill prints F\xE2\x82\x83 as t\xC2\xB3 \xE2\x88\x92 2t\xC2\xB2 + 1, a typo:",
              {520.0, 290.0}, 11.0, kMutedInk);
  figure.text("it must vanish at t = 0 with slope 1)", {520.0, 306.0}, 11.0, kMutedInk);
  return std::move(figure).finish();
}

Result<Image> render_bezier_blending() {
  // Dill "Bezier Blending Functions of degree 2, 3, and 5": B_{n,i}(t) = C(n,i) t^i (1-t)^(n-i), each
  // the Bézier graph with control points (k/n, δ_ik) (graphs.h), peaking at t = i/n.
  Result<Figure> made = Figure::create(960, 340);
  if (!made) return made.error();
  Figure& figure = *made;
  const std::array<int, 3> degrees{2, 3, 5};
  Axes axes;
  axes.x_ticks = ticks(0.0, 1.0, 0.25);
  axes.y_ticks = ticks(0.0, 1.0, 0.25);
  axes.x_decimals = 2;
  axes.y_decimals = 2;
  axes.x_label = "t";
  for (std::size_t k = 0; k < degrees.size(); ++k) {
    const int n = degrees[k];
    const Plot plot{pixel_box(60.0 + 310.0 * static_cast<double>(k), 55.0, 240.0, 230.0),
                    Rect{0.0, 0.0, 1.0, 1.1}};
    draw_title(figure, plot, "degree " + std::to_string(n));
    draw_axes(figure, plot, axes);
    for (int i = 0; i <= n; ++i) {
      const auto index = static_cast<std::size_t>(i);
      draw_beziers(figure, plot, std::array{bernstein_graph(n, i)}, series(index), 2.5);
      const double t = static_cast<double>(i) / n;
      const double y = bernstein(n, i, t);
      draw_label(figure, plot, std::to_string(i), {t, y}, {0.0, -6.0}, series(index), 11.0,
                 TextAnchor::kMiddle);
    }
  }
  figure.text(
      "Bernstein polynomials B(n,i), labelled by i: non-negative, summing to one (convex hull property)",
      {480.0, 328.0}, 12.0, kMutedInk, TextAnchor::kMiddle);
  return std::move(figure).finish();
}

namespace {

std::string describe(JoinContinuity join) {
  return "classify_join: C" + std::to_string(join.parametric) + ", G" + std::to_string(join.geometric);
}

}  // namespace

Result<Image> render_bezier_joins() {
  // Dill "Joining Bezier Curves": C0 needs Q0 = P3; C1 also P'(1) = 3(P3 - P2) = Q'(0) = 3(Q1 - Q0),
  // i.e. Q1 = 2 P3 - P2; C2 also P''(1) = Q''(0), i.e. Q2 = P1 - 4 P2 + 4 P3 (the "A-frame": Q2 is fixed
  // by P1, P2, P3). Each panel states what classify_join (continuity.h) measures.
  Result<Figure> made = Figure::create(960, 360);
  if (!made) return made.error();
  Figure& figure = *made;
  const Point p0{0.0, 0.0}, p1{0.4, 1.6}, p2{1.4, 2.0}, p3{2.0, 1.2};
  const Bezier first({p0, p1, p2, p3});
  const Point free_q1{2.9, 2.2}, q3{4.0, 0.2};
  const Point c1_q1 = p3 + (p3 - p2);
  const Point c2_q2 = p1 + (p3 - p2) * 4.0;  // P1 - 4 P2 + 4 P3 written affinely
  const std::array<Bezier, 3> seconds{Bezier({p3, free_q1, {3.6, 0.6}, q3}),
                                      Bezier({p3, c1_q1, {3.4, 0.3}, q3}), Bezier({p3, c1_q1, c2_q2, q3})};
  const std::array<const char*, 3> titles{
      "C\xE2\x81\xB0: Q\xE2\x82\x80 = P\xE2\x82\x83",
      "C\xC2\xB9: P\xE2\x82\x82, P\xE2\x82\x83 = Q\xE2\x82\x80, Q\xE2\x82\x81 "
      "collinear, equal steps",
      "C\xC2\xB2: Q\xE2\x82\x82 fixed by P\xE2\x82\x81, P\xE2\x82\x82, P\xE2\x82\x83"};
  for (std::size_t k = 0; k < seconds.size(); ++k) {
    const Rect data{-0.3, -1.9, 4.3, 2.7};
    const Plot plot = Plot::fit(pixel_box(20.0 + 310.0 * static_cast<double>(k), 60.0, 300.0, 230.0), data);
    draw_title(figure, plot, titles[k]);
    draw_control_polygon(figure, plot, first.points(), kBlue);
    draw_control_polygon(figure, plot, seconds[k].points(), kVermillion);
    if (k == 2) {
      // The A-frame: D = 2 P2 - P1 (P1 -> P2 extended by its own length); Q1 is the midpoint of D and Q2.
      const Point apex = p2 + (p2 - p1);
      draw_polyline(figure, plot, std::vector<Point>{p2, apex, c2_q2}, kGreen, 1.25, {2.0, 3.0});
      draw_marker(figure, plot, apex, kGreen, Marker::kDisc, 3.0);
    }
    draw_beziers(figure, plot, std::array{first}, kBlue, 3.0);
    draw_beziers(figure, plot, std::array{seconds[k]}, kVermillion, 3.0);
    const JoinContinuity join = classify_join(first, seconds[k]);
    figure.text(describe(join), {plot.pixels.x0 + 0.5 * plot.pixels.width(), 320.0}, 13.0, kInk,
                TextAnchor::kMiddle);
  }
  figure.text(
      "P (blue) ends where Q (vermillion) starts; dotted green: the A-frame that places Q\xE2\x82\x82",
      {480.0, 348.0}, 12.0, kMutedInk, TextAnchor::kMiddle);
  return std::move(figure).finish();
}

Result<Image> render_degree_raising() {
  // Dill "Degree Raising": Q_i = (i P_{i-1} + (n + 1 - i) P_i) / (n + 1) (Bezier::elevate). The curve
  // is unchanged; repeated raising makes the polygon converge to it.
  Result<Figure> made = Figure::create(960, 380);
  if (!made) return made.error();
  Figure& figure = *made;
  const Bezier cubic({{0.0, 0.0}, {0.6, 3.0}, {3.4, 3.0}, {4.0, 0.4}});
  const Rect data{-0.3, -0.3, 4.3, 3.3};

  const Plot left = Plot::fit(pixel_box(20.0, 60.0, 440.0, 260.0), data);
  draw_title(figure, left, "a cubic raised to degree 4");
  const Bezier quartic = cubic.elevate();
  draw_control_polygon(figure, left, cubic.points(), kControl);
  draw_control_polygon(figure, left, quartic.points(), kVermillion);
  draw_beziers(figure, left, std::array{cubic}, kBlue, 3.0);
  for (std::size_t i = 0; i < cubic.points().size(); ++i) {
    draw_label(figure, left, "P" + std::to_string(i), cubic.points()[i], {-6.0, -9.0}, kMutedInk, 12.0);
  }
  for (std::size_t i = 0; i < quartic.points().size(); ++i) {
    draw_label(figure, left, "Q" + std::to_string(i), quartic.points()[i], {4.0, 16.0}, kVermillion, 12.0);
  }

  const Plot right = Plot::fit(pixel_box(500.0, 60.0, 440.0, 260.0), data);
  draw_title(figure, right, "raised again and again: degree 3, 5, 10, 30");
  Bezier raised = cubic;
  std::size_t colour = 0;
  std::vector<LegendEntry> legend;
  for (int degree = 3; degree <= 30; ++degree) {
    if (degree == 3 || degree == 5 || degree == 10 || degree == 30) {
      draw_polyline(figure, right, raised.points(), series(colour + 1), 1.5);
      legend.push_back({"degree " + std::to_string(degree), series(colour + 1)});
      ++colour;
    }
    raised = raised.elevate();
  }
  draw_beziers(figure, right, std::array{cubic}, kBlue, 3.0);
  draw_legend(figure, {40.0, 352.0}, std::span(legend).first(2));
  draw_legend(figure, {300.0, 352.0}, std::span(legend).subspan(2));
  figure.text(
      "Q\xE1\xB5\xA2 = (i P\xE1\xB5\xA2\xE2\x82\x8B\xE2\x82\x81 + (n + 1 \xE2\x88\x92 i) P\xE1\xB5\xA2) / (n "
      "+ 1)",
      {600.0, 352.0}, 13.0, kInk);
  return std::move(figure).finish();
}

}  // namespace curvescan::figure
