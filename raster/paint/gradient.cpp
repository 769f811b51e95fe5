// Gradients: stop normalization (SVG 1.1 section 13.2.4), the SVG degenerate cases, the parameter t of a
// point (linear projection; radial two-circle solve), and the colour at t (fast walker and reference).
//
// The radial parameter. SVG 2 (section 14.4.3, after the canvas createRadialGradient model) and pixman
// (pixman-radial-gradient.c) both define the radial gradient as a family of circles
//   c(t) = f + t·(c − f),  r(t) = fr + t·(r − fr),
// and paint each point with the colour of the largest t whose circle passes through it with r(t) >= 0.
// Writing p − f = d, c − f = e, r − fr = dr, the condition |d − t·e| = fr + t·dr squares to
//   A·t² − 2·B·t + C = 0,  A = e·e − dr²,  B = d·e + fr·dr,  C = d·d − fr²,
// whose roots are (B ± sqrt(B² − A·C)) / A (one root C / 2B when A = 0, the focal circle touching the
// end circle from inside). With the focal point clamped inside the end circle and fr = 0, A < 0 and C >= 0,
// so there is always a root with r(t) >= 0: every pixel is painted.
#include "curvescan/raster/gradient.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "gradient_walker.h"

namespace curvescan {
namespace {

// [0, 1], NaN -> 0: the same total clamp as Paint::solid.
double unit_interval(double v) noexcept {
  return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;
}

// Cairo's _cairo_color_double_to_short: d·65535 + 0.5, truncated (d in [0, 1]).
std::uint16_t to_short(double unit) noexcept {
  return static_cast<std::uint16_t>(unit * 65535.0 + 0.5);
}

// Cairo's _cairo_fixed_16_16_from_double rounds to nearest with ties to even (a magic-number add).
std::int64_t offset_to_fixed(double offset) noexcept {
  return static_cast<std::int64_t>(std::nearbyint(offset * 65536.0));
}

Paint solid_of(const GradientStop& stop) noexcept {
  return Paint::solid(stop.color);
}

bool all_finite(const Affine& m, std::initializer_list<double> values) noexcept {
  return m.is_finite() &&
         std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

bool invertible(const Affine& m) noexcept {
  return m.inverse().has_value();
}

std::vector<GradientShader::WalkerStop> walker_stops_for(const std::vector<GradientStop>& stops,
                                                         SpreadMethod spread) {
  std::vector<GradientShader::WalkerStop> walker;
  walker.reserve(stops.size() + 2);
  walker.emplace_back();
  for (const GradientStop& stop : stops) {
    walker.push_back({offset_to_fixed(stop.offset), to_short(stop.color.r), to_short(stop.color.g),
                      to_short(stop.color.b), to_short(stop.color.a)});
  }
  walker.emplace_back();
  // The sentinels pixman's gradient_property_changed (pixman-image.c) places around the stops.
  GradientShader::WalkerStop& before = walker.front();
  GradientShader::WalkerStop& after = walker.back();
  const GradientShader::WalkerStop first = walker[1];
  const GradientShader::WalkerStop last = walker[walker.size() - 2];
  switch (spread) {
    case SpreadMethod::kPad:
      before = first;
      before.x = detail::kPadSentinelLow;
      after = last;
      after.x = detail::kPadSentinelHigh;
      break;
    case SpreadMethod::kRepeat:
      before = last;
      before.x = last.x - detail::kFixedOne;
      after = first;
      after.x = first.x + detail::kFixedOne;
      break;
    case SpreadMethod::kReflect:
      before = first;
      before.x = -first.x;
      after = last;
      after.x = 2 * detail::kFixedOne - last.x;
      break;
  }
  return walker;
}

// Spread applied to t: the position in [0, 1] whose colour t shows.
double spread_parameter(double t, SpreadMethod spread) noexcept {
  switch (spread) {
    case SpreadMethod::kPad:
      return std::clamp(t, 0.0, 1.0);
    case SpreadMethod::kRepeat:
      return t - std::floor(t);
    case SpreadMethod::kReflect: {
      const double u = t - 2.0 * std::floor(t / 2.0);  // in [0, 2)
      return u > 1.0 ? 2.0 - u : u;
    }
  }
  return t;
}

std::uint8_t round_byte(double v) noexcept {
  return static_cast<std::uint8_t>(std::clamp(std::floor(v * 255.0 + 0.5), 0.0, 255.0));
}

}  // namespace

std::vector<GradientStop> normalize_gradient_stops(std::span<const GradientStop> stops) {
  std::vector<GradientStop> out;
  out.reserve(stops.size() + 2);
  double largest = 0.0;
  for (const GradientStop& stop : stops) {
    // SVG 1.1 13.2.4: an offset below a previous one is taken as the largest previous offset.
    largest = std::max(largest, unit_interval(stop.offset));
    out.push_back({largest,
                   {unit_interval(stop.color.r), unit_interval(stop.color.g), unit_interval(stop.color.b),
                    unit_interval(stop.color.a)}});
  }
  if (out.empty()) return out;
  if (out.front().offset > 0.0) {
    GradientStop start = out.front();
    start.offset = 0.0;
    out.insert(out.begin(), start);
  }
  if (out.back().offset < 1.0) {
    GradientStop end = out.back();
    end.offset = 1.0;
    out.push_back(end);
  }
  return out;
}

Point clamped_focal_point(const RadialGradient& radial) noexcept {
  const Vec2 from_center = radial.focal - radial.center;
  const double distance = from_center.length();
  const double limit = kFocalClampRatio * radial.radius;
  if (!(distance > limit)) return radial.focal;  // inside, or NaN (which the comparison lets through)
  return radial.center + from_center * (limit / distance);
}

Paint linear_gradient_paint(const LinearGradient& geometry, std::span<const GradientStop> stops,
                            SpreadMethod spread, const Affine& gradient_to_user) {
  if (stops.empty()) return Paint::none();
  if (!all_finite(gradient_to_user, {geometry.start.x, geometry.start.y, geometry.end.x, geometry.end.y}) ||
      !invertible(gradient_to_user)) {
    return Paint::none();
  }
  std::vector<GradientStop> normalized = normalize_gradient_stops(stops);
  if (stops.size() == 1 || geometry.start == geometry.end) return solid_of(normalized.back());
  Paint paint = Paint::none();
  paint.gradient =
      std::make_shared<const GradientShader>(GradientShader::Shape::kLinear, std::move(normalized), spread,
                                             geometry, RadialGradient{}, gradient_to_user);
  return paint;
}

Paint radial_gradient_paint(const RadialGradient& geometry, std::span<const GradientStop> stops,
                            SpreadMethod spread, const Affine& gradient_to_user) {
  if (stops.empty()) return Paint::none();
  if (!all_finite(gradient_to_user, {geometry.center.x, geometry.center.y, geometry.radius, geometry.focal.x,
                                     geometry.focal.y, geometry.focal_radius}) ||
      !invertible(gradient_to_user) || geometry.radius < 0.0 || geometry.focal_radius < 0.0) {
    return Paint::none();
  }
  std::vector<GradientStop> normalized = normalize_gradient_stops(stops);
  if (stops.size() == 1 || geometry.radius == 0.0) return solid_of(normalized.back());
  RadialGradient clamped = geometry;
  clamped.focal = clamped_focal_point(geometry);
  if (clamped.focal == clamped.center && clamped.focal_radius == clamped.radius) return Paint::none();
  Paint paint = Paint::none();
  paint.gradient =
      std::make_shared<const GradientShader>(GradientShader::Shape::kRadial, std::move(normalized), spread,
                                             LinearGradient{}, clamped, gradient_to_user);
  return paint;
}

PaintKind Paint::kind() const noexcept {
  if (pattern != nullptr) return PaintKind::kImagePattern;
  if (gradient == nullptr) return PaintKind::kSolid;
  return gradient->shape() == GradientShader::Shape::kLinear ? PaintKind::kLinearGradient
                                                             : PaintKind::kRadialGradient;
}

GradientShader::GradientShader(Shape shape, std::vector<GradientStop> stops, SpreadMethod spread,
                               const LinearGradient& linear, const RadialGradient& radial,
                               const Affine& gradient_to_user)
    : shape_(shape),
      spread_(spread),
      stops_(std::move(stops)),
      walker_stops_(walker_stops_for(stops_, spread)),
      linear_(linear),
      radial_(radial),
      gradient_to_user_(gradient_to_user) {}

double GradientShader::parameter_at(Point p) const noexcept {
  if (shape_ == Shape::kLinear) {
    const Vec2 axis = linear_.end - linear_.start;
    return (p - linear_.start).dot(axis) / axis.length_squared();
  }
  const Vec2 d = p - radial_.focal;
  const Vec2 e = radial_.center - radial_.focal;
  const double fr = radial_.focal_radius;
  const double dr = radial_.radius - fr;
  const double a = e.dot(e) - dr * dr;
  const double b = d.dot(e) + fr * dr;
  const double c = d.dot(d) - fr * fr;
  const auto on_circle = [&](double t) { return fr + t * dr >= 0.0; };
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  if (a == 0.0) {
    if (b == 0.0) return kNone;
    const double t = c / (2.0 * b);
    return on_circle(t) ? t : kNone;
  }
  const double discriminant = b * b - a * c;
  if (!(discriminant >= 0.0)) return kNone;  // no real root, or NaN input
  const double root = std::sqrt(discriminant);
  const double t1 = (b + root) / a, t2 = (b - root) / a;
  const double high = std::max(t1, t2), low = std::min(t1, t2);
  if (on_circle(high)) return high;
  if (on_circle(low)) return low;
  return kNone;
}

Rgba8 GradientShader::color_at(double t) const noexcept {
  detail::GradientWalker walker(*this);
  return walker.color_at(t);
}

Rgba8 GradientShader::color_at_reference(double t) const noexcept {
  if (std::isnan(t)) return {};
  const double u = spread_parameter(t, spread_);
  // The segment: the last stop at or before u and the one after it (so of two stops at the same offset
  // the later one governs from that offset on, as SVG 1.1 13.2.4 says).
  std::size_t right = 1;
  while (right + 1 < stops_.size() && !(u < stops_[right].offset)) ++right;
  const double lo_offset = stops_[right - 1].offset;
  const double width = stops_[right].offset - lo_offset;
  const Color& lo = stops_[right - 1].color;
  const Color& hi = stops_[right].color;
  const double f = width > 0.0 ? std::clamp((u - lo_offset) / width, 0.0, 1.0) : 1.0;
  const auto lerp = [f](double x, double y) { return x + (y - x) * f; };
  const double alpha = lerp(lo.a, hi.a);
  return {round_byte(alpha * lerp(lo.r, hi.r)), round_byte(alpha * lerp(lo.g, hi.g)),
          round_byte(alpha * lerp(lo.b, hi.b)), round_byte(alpha)};
}

}  // namespace curvescan
