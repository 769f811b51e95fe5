// Explicit and implicit curves (Ince after Elias, *Lecture 11: Curves*, "Representations of curves":
// explicit y = f(x), implicit f(x, y) = 0), drawn from the certified polylines of curves/
// (explicit_curve.h, implicit_curve.h): a graph split at its poles, a figure eight through its singular
// point, and a cubic whose zero set has two components.
#include <array>
#include <string>
#include <vector>

#include "curvescan/curves/explicit_curve.h"
#include "curvescan/curves/expression.h"
#include "curvescan/curves/implicit_curve.h"
#include "figure/draw.h"
#include "figure/figure.h"
#include "figure/figures.h"
#include "figure/palette.h"
#include "figure/plot.h"

namespace curvescan::figure {
namespace {

// Polylines are within this distance of the curves (data units); the panels show about 5 units across
// 290 pixels, so 0.002 units is 0.1 px.
constexpr double kTolerance = 0.002;

Result<Expression> formula(const char* text, bool two_variables) {
  constexpr ExpressionVariable kX[] = {ExpressionVariable::kX};
  constexpr ExpressionVariable kXY[] = {ExpressionVariable::kX, ExpressionVariable::kY};
  return two_variables ? Expression::parse(text, kXY) : Expression::parse(text, kX);
}

void draw_polylines(Figure& figure, const Plot& plot, const std::vector<std::vector<Point>>& polylines,
                    Color color) {
  for (const std::vector<Point>& line : polylines) draw_polyline(figure, plot, line, color, kCurveWidth);
}

Axes unit_axes(double x0, double x1, double y0, double y1) {
  Axes axes;
  axes.x_ticks = ticks(x0, x1, 1.0);
  axes.y_ticks = ticks(y0, y1, 1.0);
  return axes;
}

}  // namespace

Result<Image> render_curve_representations() {
  Result<Figure> made = Figure::create(960, 400);
  if (!made) return made.error();
  Figure& figure = *made;

  // Explicit: tan x on [−3, 3], split at ±π/2 where no bound can be proven (no vertical line).
  const Plot left = Plot::fit(pixel_box(30.0, 60.0, 280.0, 280.0), Rect{-3.0, -3.0, 3.0, 3.0});
  draw_axes(figure, left, unit_axes(-3.0, 3.0, -3.0, 3.0));
  draw_title(figure, left, "explicit: y = tan x");
  Result<Expression> tangent = formula("tan(x)", false);
  if (!tangent) return tangent.error();
  ExplicitCurveOptions explicit_options;
  explicit_options.tolerance = kTolerance;
  explicit_options.y_min = -3.0;
  explicit_options.y_max = 3.0;
  Result<ExplicitCurve> graph = flatten_explicit_curve(*tangent, -3.0, 3.0, explicit_options);
  if (!graph) return graph.error();
  draw_polylines(figure, left, graph->polylines, kBlue);

  // Implicit: Bernoulli's lemniscate, one component through its node (the singular point, marked).
  const Plot middle = Plot::fit(pixel_box(340.0, 60.0, 280.0, 280.0), Rect{-2.0, -2.0, 2.0, 2.0});
  draw_axes(figure, middle, unit_axes(-2.0, 2.0, -2.0, 2.0));
  draw_title(figure, middle, "implicit: (x\u00b2 + y\u00b2)\u00b2 = 2(x\u00b2 \u2212 y\u00b2)");
  Result<Expression> lemniscate = formula("(x^2 + y^2)^2 - 2*(x^2 - y^2)", true);
  if (!lemniscate) return lemniscate.error();
  ImplicitCurveOptions implicit_options;
  implicit_options.tolerance = kTolerance;
  Result<ImplicitCurve> eight =
      contour_implicit_curve(*lemniscate, {-2.0, -1.9}, {2.1, 2.0}, implicit_options);
  if (!eight) return eight.error();
  draw_polylines(figure, middle, eight->polylines, kVermillion);
  for (const Point p : eight->singular_points) draw_marker(figure, middle, p, kInk, Marker::kRing, 5.0);

  // Implicit: y² = x³ − x, an oval and an unbounded branch: two components, one closed.
  const Plot right = Plot::fit(pixel_box(650.0, 60.0, 280.0, 280.0), Rect{-2.0, -2.5, 2.5, 2.5});
  draw_axes(figure, right, unit_axes(-2.0, 2.0, -2.0, 2.0));
  draw_title(figure, right, "implicit: y\u00b2 = x\u00b3 \u2212 x");
  Result<Expression> cubic = formula("y^2 - x^3 + x", true);
  if (!cubic) return cubic.error();
  Result<ImplicitCurve> components =
      contour_implicit_curve(*cubic, {-2.0, -2.5}, {2.5, 2.5}, implicit_options);
  if (!components) return components.error();
  for (std::size_t k = 0; k < components->polylines.size(); ++k) {
    draw_polyline(figure, right, components->polylines[k], series(k), kCurveWidth);
  }
  figure.text(std::to_string(graph->polylines.size()) + " polylines (split at the poles)", {170.0, 380.0},
              13.0, kMutedInk, TextAnchor::kMiddle);
  figure.text("1 polyline, singular point ringed", {480.0, 380.0}, 13.0, kMutedInk, TextAnchor::kMiddle);
  figure.text(std::to_string(components->polylines.size()) + " components: an oval and a branch",
              {790.0, 380.0}, 13.0, kMutedInk, TextAnchor::kMiddle);
  return std::move(figure).finish();
}

}  // namespace curvescan::figure
