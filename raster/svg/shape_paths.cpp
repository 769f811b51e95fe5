// Basic shapes as Paths (shape_paths.h).
#include "shape_paths.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "curvescan/raster/path_builder.h"

namespace curvescan::svg::detail {
namespace {

std::optional<Path> built(const PathBuilder& builder) {
  Result<Path> path = builder.build();
  if (!path || path->empty()) return std::nullopt;  // non-finite input: not rendered
  return std::move(path).value();
}

}  // namespace

std::optional<Path> rect_path(double x, double y, double width, double height, std::optional<double> rx,
                              std::optional<double> ry) {
  if (!(width > 0.0) || !(height > 0.0)) return std::nullopt;
  // SVG 1.1 9.2: negative radii are errors (treated as absent), a missing radius copies the other.
  if (rx && *rx < 0.0) rx.reset();
  if (ry && *ry < 0.0) ry.reset();
  double rx_used = rx.value_or(ry.value_or(0.0));
  double ry_used = ry.value_or(rx.value_or(0.0));
  rx_used = std::min(rx_used, width / 2.0);
  ry_used = std::min(ry_used, height / 2.0);
  PathBuilder builder;
  if (rx_used > 0.0 && ry_used > 0.0) {
    // SVG 2 10.2's equivalent path: M x+rx,y H x+w-rx A ... V ... A ... H ... A ... V ... A ... Z, the
    // quarter arcs as exact conics.
    constexpr double kQuarter = std::numbers::pi / 2.0;
    const double right = x + width, bottom = y + height;
    builder.move_to({x + rx_used, y}).line_to({right - rx_used, y});
    builder.arc({right - rx_used, y + ry_used}, rx_used, ry_used, 0.0, -kQuarter, kQuarter);
    builder.line_to({right, bottom - ry_used});
    builder.arc({right - rx_used, bottom - ry_used}, rx_used, ry_used, 0.0, 0.0, kQuarter);
    builder.line_to({x + rx_used, bottom});
    builder.arc({x + rx_used, bottom - ry_used}, rx_used, ry_used, 0.0, kQuarter, kQuarter);
    builder.line_to({x, y + ry_used});
    builder.arc({x + rx_used, y + ry_used}, rx_used, ry_used, 0.0, 2.0 * kQuarter, kQuarter);
    builder.close();
  } else {
    builder.move_to({x, y}).line_to({x + width, y}).line_to({x + width, y + height}).line_to({x, y + height});
    builder.close();
  }
  return built(builder);
}

std::optional<Path> ellipse_path(double cx, double cy, double rx, double ry) {
  if (!(rx > 0.0) || !(ry > 0.0)) return std::nullopt;
  PathBuilder builder;
  builder.arc({cx, cy}, rx, ry, 0.0, 0.0, 2.0 * std::numbers::pi).close();
  return built(builder);
}

std::optional<Path> line_path(Point from, Point to) {
  PathBuilder builder;
  builder.move_to(from).line_to(to);
  return built(builder);
}

std::optional<Path> polyline_path(std::span<const double> coordinates, bool closed) {
  if (coordinates.size() < 4) return std::nullopt;  // SVG: fewer than two points render nothing
  PathBuilder builder;
  builder.move_to({coordinates[0], coordinates[1]});
  for (std::size_t i = 2; i + 1 < coordinates.size(); i += 2)
    builder.line_to({coordinates[i], coordinates[i + 1]});
  if (closed) builder.close();
  return built(builder);
}

}  // namespace curvescan::svg::detail
