// Drawing the elements of a curve figure in a Plot: curves (exact Bézier and rational Bézier segments,
// never sampled), control polygons, points, knot markers, tangent arrows and legends.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/point.h"
#include "curvescan/curves/rational_bezier.h"
#include "curvescan/raster/pixel_format.h"
#include "figure/figure.h"
#include "figure/palette.h"
#include "figure/plot.h"

namespace curvescan::figure {

/// Width of curves, in pixels.
inline constexpr double kCurveWidth = 2.5;

/// Strokes the segments (data space) as one path, consecutive segments that meet exactly as one contour
/// (PathBuilder::append), with round joins and caps. `dashes` in pixels (empty: solid).
void draw_beziers(Figure& figure, const Plot& plot, std::span<const Bezier> segments, Color color,
                  double width = kCurveWidth, std::vector<double> dashes = {});
void draw_rational_beziers(Figure& figure, const Plot& plot, std::span<const RationalBezier> segments,
                           Color color, double width = kCurveWidth);

/// Strokes the polyline through `points` (data space).
void draw_polyline(Figure& figure, const Plot& plot, std::span<const Point> points, Color color, double width,
                   std::vector<double> dashes = {});

/// A control polygon: a thin dashed polyline and a hollow circle at every control point.
void draw_control_polygon(Figure& figure, const Plot& plot, std::span<const Point> points,
                          Color color = kControl);

enum class Marker { kDisc, kRing, kSquare, kDiamond };
/// A marker of `radius` pixels centred on `at` (data space).
void draw_marker(Figure& figure, const Plot& plot, Point at, Color color, Marker marker = Marker::kDisc,
                 double radius = 4.0);

/// An arrow from `from` to `to` (data space), head size in pixels.
void draw_arrow(Figure& figure, const Plot& plot, Point from, Point to, Color color, double width = 2.0);

/// A label at `at` (data space) shifted by `offset` pixels.
void draw_label(Figure& figure, const Plot& plot, std::string_view text, Point at, Vec2 offset, Color color,
                double size = 12.0, TextAnchor anchor = TextAnchor::kStart);

struct LegendEntry {
  std::string label;
  Color color;
  bool dashed = false;
};
/// A legend whose first row's baseline starts at `top_left` (pixels): a short line sample, then the label.
void draw_legend(Figure& figure, Point top_left, std::span<const LegendEntry> entries, double size = 12.0);

}  // namespace curvescan::figure
