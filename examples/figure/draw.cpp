#include "figure/draw.h"

#include <cmath>
#include <numbers>
#include <utility>

#include "curvescan/raster/path_builder.h"
#include "figure/palette.h"

namespace curvescan::figure {

namespace {

StrokeStyle round_style(double width, std::vector<double> dashes) {
  StrokeStyle style;
  style.width = width;
  style.join = LineJoin::kRound;
  style.cap = LineCap::kRound;
  style.dash_array = std::move(dashes);
  return style;
}

Bezier mapped(const Bezier& segment, const Affine& to_pixels) {
  std::vector<Point> points;
  points.reserve(segment.points().size());
  for (Point p : segment.points()) points.push_back(to_pixels.apply(p));
  return Bezier(std::move(points));
}

}  // namespace

void draw_beziers(Figure& figure, const Plot& plot, std::span<const Bezier> segments, Color color,
                  double width, std::vector<double> dashes) {
  if (segments.empty()) return;
  PathBuilder builder;
  const Affine to_pixels = plot.to_pixels();
  // Mapping the control points is the exact image of the curve (affine invariance, Ince); segments
  // that met exactly in data space meet exactly in pixels too, so append() keeps them one contour.
  for (const Bezier& segment : segments) builder.append(mapped(segment, to_pixels));
  figure.stroke(builder.build(), color, round_style(width, std::move(dashes)));
}

void draw_rational_beziers(Figure& figure, const Plot& plot, std::span<const RationalBezier> segments,
                           Color color, double width) {
  if (segments.empty()) return;
  PathBuilder builder;
  const Affine to_pixels = plot.to_pixels();
  for (const RationalBezier& segment : segments) {
    std::vector<Point> points;
    for (Point p : segment.points()) points.push_back(to_pixels.apply(p));
    const std::vector<double> weights(segment.weights().begin(), segment.weights().end());
    builder.append(RationalBezier(std::move(points), weights));
  }
  figure.stroke(builder.build(), color, round_style(width, {}));
}

void draw_polyline(Figure& figure, const Plot& plot, std::span<const Point> points, Color color, double width,
                   std::vector<double> dashes) {
  if (points.size() < 2) return;
  PathBuilder builder;
  builder.move_to(plot.map(points.front()));
  for (Point p : points.subspan(1)) builder.line_to(plot.map(p));
  figure.stroke(builder.build(), color, round_style(width, std::move(dashes)));
}

void draw_control_polygon(Figure& figure, const Plot& plot, std::span<const Point> points, Color color) {
  draw_polyline(figure, plot, points, color, 1.25, {5.0, 4.0});
  for (Point p : points) draw_marker(figure, plot, p, color, Marker::kRing, 3.5);
}

void draw_marker(Figure& figure, const Plot& plot, Point at, Color color, Marker marker, double radius) {
  const Point c = plot.map(at);
  constexpr double kTurn = 2.0 * std::numbers::pi;
  switch (marker) {
    case Marker::kDisc:
      figure.fill(PathBuilder().arc(c, radius, radius, 0.0, 0.0, kTurn).close().build(), color);
      break;
    case Marker::kRing:
      figure.fill(PathBuilder().arc(c, radius, radius, 0.0, 0.0, kTurn).close().build(), kPaper);
      figure.stroke(PathBuilder().arc(c, radius, radius, 0.0, 0.0, kTurn).close().build(), color,
                    round_style(1.5, {}));
      break;
    case Marker::kSquare:
      figure.fill(PathBuilder()
                      .move_to({c.x - radius, c.y - radius})
                      .line_to({c.x + radius, c.y - radius})
                      .line_to({c.x + radius, c.y + radius})
                      .line_to({c.x - radius, c.y + radius})
                      .close()
                      .build(),
                  color);
      break;
    case Marker::kDiamond:
      figure.fill(PathBuilder()
                      .move_to({c.x, c.y - radius * 1.3})
                      .line_to({c.x + radius * 1.3, c.y})
                      .line_to({c.x, c.y + radius * 1.3})
                      .line_to({c.x - radius * 1.3, c.y})
                      .close()
                      .build(),
                  color);
      break;
  }
}

void draw_arrow(Figure& figure, const Plot& plot, Point from, Point to, Color color, double width) {
  const Point a = plot.map(from);
  const Point b = plot.map(to);
  const Vec2 direction = (b - a).normalized();
  if (!direction.is_finite()) return;
  const double head = 4.0 + 2.5 * width;
  const Point base = b - direction * head;
  StrokeStyle style = round_style(width, {});
  style.cap = LineCap::kButt;
  figure.stroke(PathBuilder().move_to(a).line_to(base + direction * 1.0).build(), color, style);
  const Vec2 side = direction.perp() * (0.5 * head);
  figure.fill(PathBuilder().move_to(b).line_to(base + side).line_to(base - side).close().build(), color);
}

void draw_label(Figure& figure, const Plot& plot, std::string_view text, Point at, Vec2 offset, Color color,
                double size, TextAnchor anchor) {
  figure.text(text, plot.map(at) + offset, size, color, anchor);
}

void draw_legend(Figure& figure, Point top_left, std::span<const LegendEntry> entries, double size) {
  const double row = size * 1.6;
  Point baseline = top_left;
  for (const LegendEntry& entry : entries) {
    const double mid = baseline.y - 0.35 * size;
    StrokeStyle style = round_style(kCurveWidth, {});
    if (entry.dashed) style.dash_array = {5.0, 4.0};
    figure.stroke(PathBuilder().move_to({baseline.x, mid}).line_to({baseline.x + 24.0, mid}).build(),
                  entry.color, style);
    figure.text(entry.label, {baseline.x + 32.0, baseline.y}, size, kInk);
    baseline.y += row;
  }
}

}  // namespace curvescan::figure
