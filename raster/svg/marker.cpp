// Marker vertices and placement (marker.h).
#include "marker.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include "curvescan/svg/length.h"
#include "curvescan/svg/number.h"
#include "curvescan/svg/viewport.h"

namespace curvescan::svg::detail {
namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

// The direction at one end of a segment (from_back: its last point), SVG 2 "Path directionality": from
// the end point towards the first control point farther than `coincident` from it, in control polygon
// order (a Bézier's tangent there; the chord when all coincide). `coincident` is the stroker's rule
// (StrokeCurveCuts::coincident_length): a control point that close to the end only sets the curve's
// direction over a length of that order, so the cap and the marker both take the next one. When every
// control point is that close, the first that differs at all; zero for a degenerate segment.
Vec2 end_direction(const PathElement& element, bool from_back, double coincident) {
  const std::span<const Point> points = element.points;
  const std::size_t n = points.size();
  const auto edge = [&](std::size_t k) {
    return from_back ? points[n - 1] - points[n - 2 - k] : points[k + 1] - points[0];
  };
  if (coincident > 0.0) {
    for (std::size_t k = 0; k + 1 < n; ++k) {
      if (edge(k).length() > coincident) return edge(k);
    }
  }
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (edge(k) != Vec2{0.0, 0.0}) return edge(k);
  }
  return Vec2{0.0, 0.0};
}

Vec2 start_direction(const PathElement& element, double coincident) {
  return end_direction(element, false, coincident);
}

Vec2 end_direction(const PathElement& element, double coincident) {
  return end_direction(element, true, coincident);
}

bool is_zero(Vec2 v) {
  return v.x == 0.0 && v.y == 0.0;
}

double angle_of(Vec2 v) {
  return std::atan2(v.y, v.x) * kDegreesPerRadian;
}

// The bisector of an incoming and an outgoing direction, in degrees; one alone when the other is zero.
double bisector(Vec2 in, Vec2 out) {
  if (is_zero(in)) return is_zero(out) ? 0.0 : angle_of(out);
  if (is_zero(out)) return angle_of(in);
  const double a = angle_of(in), b = angle_of(out);
  double difference = b - a;
  if (difference > 180.0) difference -= 360.0;
  if (difference < -180.0) difference += 360.0;
  return a + difference / 2.0;
}

struct Pending {
  Point position;
  Vec2 in{0.0, 0.0}, out{0.0, 0.0};
};

// Whether the join between two pieces lies inside one elliptical arc (see marker.h).
bool inside_arc(const PathElement& previous, const PathElement& next) {
  if (!previous.is_rational() || !next.is_rational()) return false;
  const Vec2 a = end_direction(previous, 0.0), b = start_direction(next, 0.0);
  const double cross = a.x * b.y - a.y * b.x, dot = a.x * b.x + a.y * b.y;
  return dot > 0.0 && std::abs(cross) <= 1e-9 * std::hypot(a.x, a.y) * std::hypot(b.x, b.y);
}

// Angle with an optional unit (SVG 2 <angle>: deg, grad, rad, turn); nullopt when malformed.
std::optional<double> parse_angle(std::string_view text) {
  std::string_view rest = trim_whitespace(text);
  const std::optional<double> value = consume_number(rest);
  if (!value) return std::nullopt;
  if (rest.empty() || rest == "deg") return *value;
  if (rest == "grad") return *value * 0.9;
  if (rest == "rad") return *value * kDegreesPerRadian;
  if (rest == "turn") return *value * 360.0;
  return std::nullopt;
}

}  // namespace

std::vector<MarkerVertex> marker_vertices(const Path& path, bool merge_arc_pieces, double coincident_length) {
  std::vector<Pending> pending;
  // A copy: iterating a Path yields elements by value (their spans point into the path, which lives on).
  std::optional<PathElement> previous;
  for (const PathElement& element : path) {
    switch (element.verb) {
      case PathVerb::kMove:
        pending.push_back({element.start});
        previous.reset();
        break;
      case PathVerb::kClose: {
        if (pending.empty()) break;
        const Vec2 closing = element.end - element.start;
        const Vec2 direction = is_zero(closing) ? pending.back().in : closing;
        if (!is_zero(closing)) pending.back().out = closing;
        pending.push_back({element.end, direction});
        previous.reset();
        break;
      }
      default:
        if (pending.empty()) break;
        if (merge_arc_pieces && previous && inside_arc(*previous, element)) {
          pending.back().position = element.end;  // the arc continues: move its end vertex along
          pending.back().in = end_direction(element, coincident_length);
        } else {
          pending.back().out = start_direction(element, coincident_length);
          pending.push_back({element.end, end_direction(element, coincident_length)});
        }
        previous = element;
    }
  }
  std::vector<MarkerVertex> vertices;
  vertices.reserve(pending.size());
  for (const Pending& vertex : pending)
    vertices.push_back({vertex.position, bisector(vertex.in, vertex.out)});
  return vertices;
}

ResolvedMarker resolve_marker(const pugi::xml_node& marker, ComputedStyle style,
                              const ResolveContext& context, Diagnostics& diagnostics) {
  ResolvedMarker resolved;
  resolved.element = marker;
  const auto length = [&](const char* name, double fallback, LengthAxis axis) {
    const pugi::xml_attribute attribute = marker.attribute(name);
    if (!attribute) return fallback;
    const Result<Length> parsed = parse_length(attribute.value());
    if (!parsed) {
      diagnostics.warnings.push_back("<marker> " + std::string(name) + ": " + parsed.error().message);
      return fallback;
    }
    return length_to_pixels(*parsed, LengthContext{axis.dpi, style.font_size, axis.percent_reference});
  };
  resolved.width = length("markerWidth", 3.0, context.horizontal());
  resolved.height = length("markerHeight", 3.0, context.vertical());
  resolved.clips = style.painting.overflow != PaintingProperties::Overflow::kVisible;
  resolved.style = std::move(style);
  if (!(resolved.width > 0.0) || !(resolved.height > 0.0) ||
      !std::isfinite(resolved.width + resolved.height)) {
    resolved.draws = false;
    return resolved;
  }
  const double ref_x = length("refX", 0.0, context.horizontal());
  const double ref_y = length("refY", 0.0, context.vertical());

  const std::string_view orient = trim_whitespace(marker.attribute("orient").value());
  if (orient == "auto") {
    resolved.fixed_angle = std::nullopt;
  } else if (orient == "auto-start-reverse") {
    resolved.auto_start_reverse = true;
  } else {
    resolved.fixed_angle = parse_angle(orient).value_or(0.0);  // absent or invalid: 0 (SVG 1.1 11.6.2)
  }

  // markerUnits: anything but userSpaceOnUse is the default, strokeWidth.
  resolved.stroke_width_units = std::string_view(marker.attribute("markerUnits").value()) != "userSpaceOnUse";
  if (const pugi::xml_attribute attribute = marker.attribute("viewBox")) {
    const Result<ViewBox> box = parse_view_box(attribute.value());
    if (box) {
      if (!(box->width > 0.0) || !(box->height > 0.0)) {
        resolved.draws = false;
        return resolved;
      }
      PreserveAspectRatio aspect;
      if (const pugi::xml_attribute par = marker.attribute("preserveAspectRatio")) {
        if (const Result<PreserveAspectRatio> parsed = parse_preserve_aspect_ratio(par.value()))
          aspect = *parsed;
      }
      resolved.view = view_box_transform(*box, aspect, 0.0, 0.0, resolved.width, resolved.height);
    } else {
      diagnostics.warnings.push_back("<marker> " + box.error().message);
    }
  }
  // The reference point, mapped into the viewport, goes to the vertex.
  resolved.ref = resolved.view.apply(Point{ref_x, ref_y});
  return resolved;
}

std::optional<MarkerSetup> place_marker(const ResolvedMarker& marker, double stroke_width) {
  if (!marker.draws) return std::nullopt;
  const Affine units = marker.stroke_width_units ? Affine::scale(stroke_width) : Affine::identity();
  MarkerSetup setup;
  setup.content_to_frame = units * Affine::translate(-marker.ref.x, -marker.ref.y) * marker.view;
  if (marker.clips) {
    // The viewport (0, 0, width, height) shifted by the reference point, in the scaled frame.
    const Affine to_frame = units * Affine::translate(-marker.ref.x, -marker.ref.y);
    const Point a = to_frame.apply(Point{0.0, 0.0}), b = to_frame.apply(Point{marker.width, marker.height});
    setup.clip = Rect{std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
  }
  return setup;
}

}  // namespace curvescan::svg::detail
