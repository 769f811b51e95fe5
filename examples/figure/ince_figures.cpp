// Figures after Ince (after Elias), "Lecture 11: Curves": de Casteljau's construction, quadratic and cubic
// B-spline segments with their knots, Béziers of growing degree, the three Catmull–Rom parametrizations,
// and interpolating against approximating curves.
#include <array>
#include <string>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/bspline.h"
#include "curvescan/curves/catmull_rom.h"
#include "curvescan/curves/cubic_spline.h"
#include "figure/draw.h"
#include "figure/figure.h"
#include "figure/figures.h"
#include "figure/palette.h"
#include "figure/plot.h"

namespace curvescan::figure {

namespace {

/// One panel of the de Casteljau figure: every level of the triangle at t, the curve split there.
void de_casteljau_panel(Figure& figure, const Plot& plot, const std::vector<Point>& control, double t,
                        std::string_view title) {
  draw_title(figure, plot, title);
  const Bezier curve(control);
  const auto [first, second] = curve.split(t);
  draw_beziers(figure, plot, std::array{second}, with_alpha(kBlue, 90));
  draw_beziers(figure, plot, std::array{first}, kBlue);
  draw_control_polygon(figure, plot, control, kControl);
  // Gallivan "DeCasteljau's Algorithm": p_{k,i} = (1 - t) p_{k-1,i} + t p_{k-1,i+1}; each level is drawn as
  // the polyline of its points, in its own colour, down to the single point on the curve.
  std::vector<Point> level = control;
  std::size_t depth = 0;
  while (level.size() > 1) {
    std::vector<Point> next;
    for (std::size_t i = 0; i + 1 < level.size(); ++i) next.push_back(lerp(level[i], level[i + 1], t));
    ++depth;
    const Color color = next.size() == 1 ? kVermillion : series(depth + 1);
    if (next.size() > 1) draw_polyline(figure, plot, next, color, 1.75);
    for (Point p : next) draw_marker(figure, plot, p, color, Marker::kDisc, next.size() == 1 ? 5.0 : 3.5);
    level = std::move(next);
  }
  for (std::size_t i = 0; i < control.size(); ++i) {
    draw_label(figure, plot, "P" + std::to_string(i), control[i], {-8.0, -9.0}, kMutedInk, 12.0);
  }
}

}  // namespace

Result<Image> render_de_casteljau() {
  constexpr double kT = 0.4;
  Result<Figure> made = Figure::create(960, 360);
  if (!made) return made.error();
  Figure& figure = *made;
  const Rect data{-0.3, -0.3, 4.3, 3.3};
  de_casteljau_panel(figure, Plot::fit(pixel_box(20.0, 60.0, 300.0, 240.0), data), {{0.2, 0.3}, {3.8, 2.8}},
                     kT, "linear");
  de_casteljau_panel(figure, Plot::fit(pixel_box(330.0, 60.0, 300.0, 240.0), data),
                     {{0.2, 0.3}, {1.6, 3.0}, {3.8, 0.6}}, kT, "quadratic");
  de_casteljau_panel(figure, Plot::fit(pixel_box(640.0, 60.0, 300.0, 240.0), data),
                     {{0.2, 0.3}, {0.9, 3.0}, {3.2, 3.1}, {3.8, 0.4}}, kT, "cubic");
  figure.text(
      "de Casteljau at t = 0.4: every level interpolates the one above at t; the last point is on the "
      "curve (solid: t \xE2\x89\xA4 0.4)",
      {480.0, 340.0}, 12.0, kMutedInk, TextAnchor::kMiddle);
  return std::move(figure).finish();
}

Result<Image> render_bspline_segments() {
  // Ince "Quadratic B-spline Curves" / "Cubic B-spline Curves": segment S_k uses p + 1 consecutive
  // control points and covers [t_k, t_{k+1}); knots are the joins. Uniform knots t_i = i (knot_vector.h).
  Result<Figure> made = Figure::create(960, 380);
  if (!made) return made.error();
  Figure& figure = *made;
  const std::vector<Point> control{{0.0, 0.5}, {1.0, 2.6}, {2.6, 2.9}, {3.4, 0.6},
                                   {5.0, 0.2}, {5.8, 2.4}, {7.0, 2.8}};
  const Rect data{-0.4, -0.2, 7.4, 3.4};
  for (int p = 2; p <= 3; ++p) {
    Result<BSpline> spline = BSpline::uniform(control, p);
    if (!spline) return spline.error();
    const Plot plot = Plot::fit(pixel_box(p == 2 ? 20.0 : 500.0, 60.0, 440.0, 250.0), data);
    draw_title(figure, plot,
               p == 2 ? "quadratic: S\xE2\x82\x82 \xE2\x80\xA6 S\xE2\x82\x86, 3 points each"
                      : "cubic: S\xE2\x82\x83 \xE2\x80\xA6 S\xE2\x82\x86, 4 points each");
    draw_control_polygon(figure, plot, control, kControl);
    const std::vector<Bezier> segments = spline->to_beziers();
    for (std::size_t k = 0; k < segments.size(); ++k) {
      draw_beziers(figure, plot, std::span(segments).subspan(k, 1), series(k), 3.0);
    }
    const std::vector<double> breaks = spline->bezier_breakpoints();
    for (std::size_t k = 0; k < breaks.size(); ++k) {
      const Point at = spline->eval(breaks[k]);
      draw_marker(figure, plot, at, kInk, Marker::kSquare, 3.5);
      draw_label(figure, plot, "t" + std::to_string(static_cast<int>(breaks[k])), at, {4.0, 16.0}, kInk,
                 11.0);
    }
    for (std::size_t i = 0; i < control.size(); ++i) {
      draw_label(figure, plot, "p" + std::to_string(i), control[i], {6.0, -6.0}, kMutedInk, 11.0);
    }
  }
  figure.text(
      "uniform knots t\xE1\xB5\xA2 = i; \xE2\x96\xA0 = knots (segment joins); each segment S\xE2\x82\x96 in "
      "its own colour",
      {480.0, 360.0}, 12.0, kMutedInk, TextAnchor::kMiddle);
  return std::move(figure).finish();
}

Result<Image> render_bezier_degrees() {
  // Ince "Bezier Curves" (quadratic, cubic, quartic examples) and degree 10: the curve follows the
  // polygon less tightly as the degree grows (every point pulls on the whole curve).
  Result<Figure> made = Figure::create(960, 340);
  if (!made) return made.error();
  Figure& figure = *made;
  const Rect data{-0.3, -0.3, 4.3, 3.3};
  const std::vector<std::vector<Point>> curves{{{0.2, 0.4}, {0.8, 3.0}, {3.2, 3.0}, {3.8, 0.4}},
                                               {{0.2, 0.4}, {0.4, 2.9}, {2.0, 0.2}, {3.6, 2.9}, {3.8, 0.4}},
                                               {{0.2, 0.2},
                                                {0.5, 3.0},
                                                {0.9, 0.3},
                                                {1.3, 3.0},
                                                {1.7, 0.3},
                                                {2.0, 3.0},
                                                {2.3, 0.3},
                                                {2.7, 3.0},
                                                {3.1, 0.3},
                                                {3.5, 3.0},
                                                {3.8, 0.2}}};
  const std::array<const char*, 3> titles{"degree 3", "degree 4", "degree 10"};
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const Plot plot = Plot::fit(pixel_box(20.0 + 310.0 * static_cast<double>(k), 60.0, 300.0, 240.0), data);
    draw_title(figure, plot, titles[k]);
    draw_control_polygon(figure, plot, curves[k], kControl);
    draw_beziers(figure, plot, std::array{Bezier(curves[k])}, series(k), 3.0);
  }
  figure.text("B\xC3\xA9zier curves with their control polygons (the curve stays in their convex hull)",
              {480.0, 325.0}, 12.0, kMutedInk, TextAnchor::kMiddle);
  return std::move(figure).finish();
}

Result<Image> render_catmull_rom() {
  // Ince "Spline Parametrization": knot intervals |P_k - P_{k-1}|^α, α = 0 uniform, 1 chordal, 0.5
  // centripetal. Points with one short and several long steps show the uniform loop and the chordal bulge.
  const std::vector<Point> points{{0.0, 0.0}, {1.0, 2.6}, {1.5, 2.7}, {1.3, 2.3},
                                  {4.0, 0.3}, {6.0, 2.6}, {6.3, 0.0}};
  Result<Figure> made = Figure::create(760, 460);
  if (!made) return made.error();
  Figure& figure = *made;
  figure.text("Catmull\xE2\x80\x93Rom through the same points (Ince, \"Spline Parametrization\")",
              {380.0, 30.0}, 16.0, kInk, TextAnchor::kMiddle);
  const Plot plot = Plot::fit(pixel_box(30.0, 50.0, 700.0, 320.0), Rect{-0.4, -0.6, 6.8, 3.3});
  struct Variant {
    double alpha;
    const char* label;
    Color color;
  };
  const std::array<Variant, 3> variants{
      Variant{kCatmullRomUniform, "uniform (\xCE\xB1 = 0)", kVermillion},
      Variant{kCatmullRomChordal, "chordal (\xCE\xB1 = 1)", kGreen},
      Variant{kCatmullRomCentripetal, "centripetal (\xCE\xB1 = 0.5)", kBlue}};
  std::vector<LegendEntry> legend;
  for (const Variant& variant : variants) {
    Result<std::vector<Bezier>> spline = catmull_rom(points, variant.alpha);
    if (!spline) return spline.error();
    draw_beziers(figure, plot, *spline, variant.color, 2.5);
    legend.push_back({variant.label, variant.color});
  }
  for (Point p : points) draw_marker(figure, plot, p, kInk, Marker::kDisc, 4.5);
  draw_legend(figure, {60.0, 400.0}, legend, 13.0);
  figure.text("uniform overshoots and loops at the short step,", {420.0, 400.0}, 12.0, kMutedInk);
  figure.text("chordal bulges on the long ones,", {420.0, 420.0}, 12.0, kMutedInk);
  figure.text("centripetal stays tight, without loops or cusps", {420.0, 440.0}, 12.0, kMutedInk);
  return std::move(figure).finish();
}

Result<Image> render_interpolating_vs_approximating() {
  // Ince "Bezier Curves": "So far our splines pass through the control points: interpolation / Now
  // they will pass close to the control points: approximation". Same points, a C2 cubic spline through them
  // and a clamped cubic B-spline that they control.
  const std::vector<Point> points{{0.0, 0.3}, {1.0, 2.4}, {2.4, 2.8}, {3.2, 0.8}, {4.6, 0.4}, {5.4, 2.6}};
  Result<Figure> made = Figure::create(960, 360);
  if (!made) return made.error();
  Figure& figure = *made;
  const Rect data{-0.3, -0.3, 5.7, 3.3};
  Result<std::vector<Bezier>> through = cubic_spline(points);
  if (!through) return through.error();
  Result<BSpline> controlled = BSpline::clamped(points, 3);
  if (!controlled) return controlled.error();

  const Plot left = Plot::fit(pixel_box(20.0, 60.0, 440.0, 250.0), data);
  draw_title(figure, left, "interpolated: a C\xC2\xB2 cubic spline through the points");
  draw_polyline(figure, left, points, with_alpha(kControl, 120), 1.0, {5.0, 4.0});
  draw_beziers(figure, left, *through, kBlue, 3.0);
  for (Point p : points) draw_marker(figure, left, p, kVermillion, Marker::kDisc, 4.5);

  const Plot right = Plot::fit(pixel_box(500.0, 60.0, 440.0, 250.0), data);
  draw_title(figure, right, "approximated: a cubic B-spline they control");
  draw_control_polygon(figure, right, points, kControl);
  draw_beziers(figure, right, controlled->to_beziers(), kGreen, 3.0);
  for (Point p : points) draw_marker(figure, right, p, kVermillion, Marker::kDisc, 4.5);
  figure.text("the same six points: chord-length natural spline (left), clamped uniform B-spline (right)",
              {480.0, 345.0}, 12.0, kMutedInk, TextAnchor::kMiddle);
  return std::move(figure).finish();
}

}  // namespace curvescan::figure
