#include "light_source.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string_view>

#include "primitive_numbers.h"
#include "xml_names.h"

namespace curvescan::svg::detail::filter {

namespace {

double number_or(const pugi::xml_node& element, const char* name, double lacuna) {
  return primitive_number(element, name).value_or(lacuna);
}

double radians(double degrees) noexcept {
  return degrees * std::numbers::pi / 180.0;
}

/// v / |v|, scaled by its largest component first so that lights at 1e300 do not overflow. The zero vector
/// (a light exactly on the surface point) and a vector with an infinite component (a light beyond the range
/// of doubles once in filter pixels) give zero, which lights nothing.
std::array<double, 3> normalized(const std::array<double, 3>& v) noexcept {
  const double largest = std::max({std::fabs(v[0]), std::fabs(v[1]), std::fabs(v[2])});
  if (!(largest > 0.0) || !std::isfinite(largest)) return {0.0, 0.0, 0.0};
  const double x = v[0] / largest, y = v[1] / largest, z = v[2] / largest;
  const double length = std::sqrt(x * x + y * y + z * z);
  return {x / length, y / length, z / length};
}

std::array<double, 3> point_in_pixels(const FilterSpace& space, double x, double y, double z) noexcept {
  const Point p = space.to_pixels({space.user_x(x), space.user_y(y)});
  return {p.x, p.y, space.length_to_pixels(space.user_length(z))};
}

}  // namespace

std::optional<LightSource> read_light_source(const pugi::xml_node& primitive, std::string& error) {
  for (const pugi::xml_node child : primitive.children()) {
    if (child.type() != pugi::node_element) continue;
    const std::string_view name = local_name(child);
    LightSource light;
    if (name == "feDistantLight") {
      light.kind = LightKind::kDistant;
      light.azimuth = number_or(child, "azimuth", 0.0);
      light.elevation = number_or(child, "elevation", 0.0);
      return light;
    }
    if (name == "fePointLight" || name == "feSpotLight") {
      light.kind = name == "fePointLight" ? LightKind::kPoint : LightKind::kSpot;
      light.x = number_or(child, "x", 0.0);
      light.y = number_or(child, "y", 0.0);
      light.z = number_or(child, "z", 0.0);
      if (light.kind == LightKind::kSpot) {
        light.points_at_x = number_or(child, "pointsAtX", 0.0);
        light.points_at_y = number_or(child, "pointsAtY", 0.0);
        light.points_at_z = number_or(child, "pointsAtZ", 0.0);
        // An exponent <= 0 does not focus the light at all (the factor no longer falls off away from the
        // axis): treated as not specified, its initial value 1, as Chrome and resvg render it.
        light.spot_exponent = number_or(child, "specularExponent", 1.0);
        if (!(light.spot_exponent > 0.0)) light.spot_exponent = 1.0;
        light.limiting_cone_angle = primitive_number(child, "limitingConeAngle");
      }
      return light;
    }
  }
  error =
      std::string(local_name(primitive)) + ": no light source (feDistantLight, fePointLight or feSpotLight)";
  return std::nullopt;
}

PlacedLight::PlacedLight(const LightSource& light, const FilterSpace& space) noexcept : kind_(light.kind) {
  switch (light.kind) {
    case LightKind::kDistant: {
      const double azimuth = radians(light.azimuth), elevation = radians(light.elevation);
      distant_direction_ = {std::cos(azimuth) * std::cos(elevation), std::sin(azimuth) * std::cos(elevation),
                            std::sin(elevation)};
      break;
    }
    case LightKind::kPoint:
    case LightKind::kSpot: {
      position_ = point_in_pixels(space, light.x, light.y, light.z);
      if (light.kind == LightKind::kSpot) {
        const auto target = point_in_pixels(space, light.points_at_x, light.points_at_y, light.points_at_z);
        spot_axis_ =
            normalized({target[0] - position_[0], target[1] - position_[1], target[2] - position_[2]});
        spot_exponent_ = light.spot_exponent;
        // The cone is symmetric: the sign of the angle does not matter (Filter Effects 1, 15.17).
        if (light.limiting_cone_angle) cos_cone_ = std::cos(radians(std::fabs(*light.limiting_cone_angle)));
      }
      break;
    }
  }
}

std::array<double, 3> PlacedLight::direction_to_light(double x, double y, double z) const noexcept {
  if (kind_ == LightKind::kDistant) return distant_direction_;
  return normalized({position_[0] - x, position_[1] - y, position_[2] - z});
}

std::array<double, 3> PlacedLight::color_along(const std::array<double, 3>& to_light,
                                               const std::array<float, 3>& color) const noexcept {
  if (kind_ != LightKind::kSpot) return {color[0], color[1], color[2]};
  // -L.S: the cosine between the spot's axis and the ray from the light to the surface point.
  const double minus_l_dot_s =
      -(to_light[0] * spot_axis_[0] + to_light[1] * spot_axis_[1] + to_light[2] * spot_axis_[2]);
  if (!(minus_l_dot_s > 0.0)) return {0.0, 0.0, 0.0};
  if (cos_cone_ && minus_l_dot_s < *cos_cone_) return {0.0, 0.0, 0.0};
  // A negative specularExponent makes the factor grow without bound near the cone's edge; capping it keeps
  // inf * 0 (a black lighting-color channel) from becoming NaN. The caller clamps the result to [0, 1].
  const double factor = std::min(std::pow(minus_l_dot_s, spot_exponent_), 1.0e30);
  return {color[0] * factor, color[1] * factor, color[2] * factor};
}

}  // namespace curvescan::svg::detail::filter
