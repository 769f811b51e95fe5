// "Dusk garden": an illustration of curvescan's own making (the repository ships no third-party art).
// Everything in it is built from the curve families of the notes and drawn exactly:
//  - sky: a rectangle under a three-stop linear gradient;
//  - sun: a NURBS circle (Umetani §4.1) under a radial gradient, with a translucent halo;
//  - hills: closed regions whose ridges are centripetal Catmull–Rom splines (Ince), the middle one in
//    a layer composited at 85 % opacity (group opacity);
//  - flowers: petals of single cubic Béziers rotated by affine maps (affine invariance, Ince), stems
//    of C2 cubic splines, leaves of conics (rational quadratics, Umetani §4.1);
//  - a firefly's flight: a closed cubic B-spline (Gallivan) stroked with a dash pattern and round caps;
//  - stars: small polygons at positions from a fixed linear congruential sequence (deterministic).
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "curvescan/curves/bspline.h"
#include "curvescan/curves/catmull_rom.h"
#include "curvescan/curves/cubic_spline.h"
#include "curvescan/curves/nurbs.h"
#include "curvescan/raster/gradient.h"
#include "curvescan/raster/path_builder.h"
#include "figure/figure.h"
#include "figure/figures.h"
#include "figure/palette.h"

namespace curvescan::figure {

namespace {

constexpr double kWidth = 960.0;
constexpr double kHeight = 560.0;
constexpr double kTurn = 2.0 * std::numbers::pi;

Result<Path> nurbs_circle_path(Point center, double radius) {
  Result<Nurbs> circle = Nurbs::circle(center, radius);
  if (!circle) return circle.error();
  PathBuilder builder;
  for (const RationalBezier& quarter : circle->to_rational_beziers()) builder.append(quarter);
  return builder.close().build();
}

/// The region under a ridge through `ridge` (a centripetal Catmull–Rom spline) down to the bottom edge.
Result<Path> hill(std::span<const Point> ridge) {
  Result<std::vector<Bezier>> spline = catmull_rom(ridge, kCatmullRomCentripetal);
  if (!spline) return spline.error();
  PathBuilder builder;
  for (const Bezier& piece : *spline) builder.append(piece);
  builder.line_to({ridge.back().x, kHeight}).line_to({ridge.front().x, kHeight}).close();
  return builder.build();
}

Paint gradient(Point from, Point to, std::span<const GradientStop> stops) {
  return linear_gradient_paint({from, to}, stops, SpreadMethod::kPad);
}

void flower(Figure& figure, Point base, Point head, double size, Color petal_color, int petals) {
  // Stem: a natural cubic spline through three points, leaning like a real stem.
  const std::array<Point, 3> stem_points{base, lerp(base, head, 0.5) + Vec2{size * 0.25, 0.0}, head};
  Result<std::vector<Bezier>> stem = cubic_spline(stem_points);
  if (!stem) return figure.record(stem.status());
  PathBuilder stem_path;
  for (const Bezier& piece : *stem) stem_path.append(piece);
  StrokeStyle stem_style;
  stem_style.width = size * 0.09;
  stem_style.cap = LineCap::kRound;
  figure.stroke(stem_path.build(), Color::from_rgba8(46, 110, 60), stem_style);
  // Leaf: two conics between the same end points, bulging to either side (weight 0.9: an ellipse arc).
  const Point leaf_start = lerp(base, head, 0.45) + Vec2{size * 0.12, 0.0};
  const Point leaf_tip = leaf_start + Vec2{size * 0.7, -size * 0.35};
  figure.fill(PathBuilder()
                  .move_to(leaf_start)
                  .conic_to(leaf_start + Vec2{size * 0.5, -size * 0.6}, leaf_tip, 0.9)
                  .conic_to(leaf_start + Vec2{size * 0.3, size * 0.05}, leaf_start, 0.9)
                  .close()
                  .build(),
              Color::from_rgba8(70, 140, 70));
  // Petals: one cubic loop from the centre and back, rotated around the centre.
  PathBuilder petal_builder;
  for (int k = 0; k < petals; ++k) {
    const Affine place = Affine::translate(head.x, head.y) * Affine::rotate(kTurn * k / petals);
    petal_builder.move_to(place.apply(Point{0.0, 0.0}))
        .cubic_to(place.apply(Point{size * 0.45, -size * 0.32}), place.apply(Point{size * 0.75, size * 0.22}),
                  place.apply(Point{0.0, 0.0}))
        .close();
  }
  figure.fill(petal_builder.build(), with_alpha(petal_color, 215));
  figure.fill(nurbs_circle_path(head, size * 0.14), Color::from_rgba8(250, 215, 90));
}

}  // namespace

Result<Image> render_illustration() {
  Result<Figure> made = Figure::create(static_cast<int>(kWidth), static_cast<int>(kHeight));
  if (!made) return made.error();
  Figure& figure = *made;
  const Result<Path> frame = PathBuilder()
                                 .move_to({0, 0})
                                 .line_to({kWidth, 0})
                                 .line_to({kWidth, kHeight})
                                 .line_to({0, kHeight})
                                 .close()
                                 .build();

  const std::array<GradientStop, 3> sky{GradientStop{0.0, {0.11, 0.17, 0.33, 1.0}},
                                        GradientStop{0.55, {0.49, 0.15, 0.33, 1.0}},
                                        GradientStop{1.0, {1.0, 0.62, 0.37, 1.0}}};
  figure.fill_paint(frame, gradient({0.0, 0.0}, {0.0, 360.0}, sky));

  // Stars: a fixed LCG (Numerical Recipes' constants) so the picture is the same on every run.
  std::uint32_t state = 2024;
  const auto next = [&state]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / static_cast<double>(1u << 24);
  };
  PathBuilder stars;
  for (int k = 0; k < 60; ++k) {
    const Point c{next() * kWidth, next() * 200.0};
    const double r = 0.8 + 1.6 * next();
    for (int v = 0; v < 10; ++v) {
      const double angle = kTurn * v / 10.0 - std::numbers::pi / 2.0;
      const double radius = (v % 2 == 0) ? r * 2.2 : r * 0.9;
      const Point p = c + Vec2{std::cos(angle), std::sin(angle)} * radius;
      if (v == 0)
        stars.move_to(p);
      else
        stars.line_to(p);
    }
    stars.close();
  }
  figure.fill(stars.build(), Color::from_rgba8(255, 250, 230, 200));

  // Sun and halo.
  const Point sun{650.0, 300.0};
  const std::array<GradientStop, 2> halo{GradientStop{0.0, {1.0, 0.85, 0.5, 0.55}},
                                         GradientStop{1.0, {1.0, 0.6, 0.4, 0.0}}};
  figure.fill_paint(nurbs_circle_path(sun, 170.0),
                    radial_gradient_paint({sun, 170.0, sun, 0.0}, halo, SpreadMethod::kPad));
  const std::array<GradientStop, 2> disc{GradientStop{0.0, {1.0, 0.96, 0.75, 1.0}},
                                         GradientStop{1.0, {1.0, 0.72, 0.3, 1.0}}};
  figure.fill_paint(
      nurbs_circle_path(sun, 70.0),
      radial_gradient_paint({sun, 70.0, sun + Vec2{-20.0, -20.0}, 0.0}, disc, SpreadMethod::kPad));

  // Hills, back to front.
  const std::vector<Point> far{{-20, 330}, {120, 290}, {260, 320}, {420, 270},
                               {600, 330}, {780, 285}, {980, 320}};
  const std::vector<Point> middle{{-20, 400}, {150, 350}, {330, 395}, {520, 345},
                                  {700, 400}, {860, 360}, {980, 390}};
  const std::vector<Point> near{{-20, 470}, {200, 430}, {420, 480}, {640, 440}, {800, 470}, {980, 445}};
  figure.fill(hill(far), Color::from_rgba8(88, 60, 110));
  figure.record(figure.canvas().push_layer());
  const std::array<GradientStop, 2> meadow{GradientStop{0.0, {0.22, 0.36, 0.33, 1.0}},
                                           GradientStop{1.0, {0.12, 0.22, 0.22, 1.0}}};
  figure.fill_paint(hill(middle), gradient({0.0, 340.0}, {0.0, 560.0}, meadow));
  figure.record(figure.canvas().pop_layer(0.85));
  figure.fill(hill(near), Color::from_rgba8(24, 44, 40));

  // Firefly flight: a closed cubic B-spline around loose control points, dashed.
  Result<BSpline> flight =
      BSpline::closed({{180, 250}, {300, 190}, {380, 260}, {300, 330}, {200, 300}, {120, 350}, {80, 260}}, 3);
  if (!flight) return flight.error();
  PathBuilder flight_path;
  for (const Bezier& piece : flight->to_beziers()) flight_path.append(piece);
  StrokeStyle dotted;
  dotted.width = 3.0;
  dotted.cap = LineCap::kRound;
  dotted.dash_array = {0.0, 11.0};
  figure.stroke(flight_path.close().build(), Color::from_rgba8(255, 240, 140, 230), dotted);
  figure.fill(nurbs_circle_path(flight->eval(flight->domain_start()), 5.0), Color::from_rgba8(255, 250, 190));

  flower(figure, {150, 560}, {170, 440}, 70.0, Color::from_rgba8(230, 120, 160), 7);
  flower(figure, {300, 560}, {330, 470}, 52.0, Color::from_rgba8(240, 170, 60), 6);
  flower(figure, {820, 560}, {790, 430}, 80.0, Color::from_rgba8(180, 140, 230), 8);
  flower(figure, {700, 560}, {690, 490}, 44.0, Color::from_rgba8(240, 110, 90), 5);

  figure.text("curvescan", {kWidth - 20.0, kHeight - 18.0}, 14.0, Color::from_rgba8(255, 255, 255, 200),
              TextAnchor::kEnd);
  return std::move(figure).finish();
}

}  // namespace curvescan::figure
