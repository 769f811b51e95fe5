// The light sources of feDiffuseLighting and feSpecularLighting (Filter Effects 1, sections 15.15-15.17:
// feDistantLight, fePointLight, feSpotLight): reading them from the primitive's children and the two
// quantities the lighting equations need per surface point — the unit vector L towards the light and the
// light's colour at that point (the spot light's cone and fall-off).
#pragma once

#include <array>
#include <optional>
#include <pugixml.hpp>
#include <string>

#include "filter_space.h"

namespace curvescan::svg::detail::filter {

enum class LightKind { kDistant, kPoint, kSpot };

/// A light source as written (user space or primitiveUnits numbers, spec lacuna values applied).
struct LightSource {
  LightKind kind = LightKind::kDistant;
  double azimuth = 0.0;                                            ///< feDistantLight, degrees
  double elevation = 0.0;                                          ///< feDistantLight, degrees
  double x = 0.0, y = 0.0, z = 0.0;                                ///< fePointLight, feSpotLight
  double points_at_x = 0.0, points_at_y = 0.0, points_at_z = 0.0;  ///< feSpotLight
  double spot_exponent = 1.0;                                      ///< feSpotLight specularExponent
  std::optional<double> limiting_cone_angle;                       ///< feSpotLight, degrees
};

/// The first feDistantLight, fePointLight or feSpotLight child of `primitive` (later ones are ignored, as
/// browsers do); nullopt and `error` when there is none — the primitive is then in error.
[[nodiscard]] std::optional<LightSource> read_light_source(const pugi::xml_node& primitive,
                                                           std::string& error);

/// A light source with its positions in filter pixels (z scaled as an axis-free length).
class PlacedLight {
 public:
  PlacedLight(const LightSource& light, const FilterSpace& space) noexcept;

  /// The unit vector from the surface point (x, y, z), in filter pixels, towards the light.
  [[nodiscard]] std::array<double, 3> direction_to_light(double x, double y, double z) const noexcept;
  /// The light's colour arriving along the unit vector `to_light`: `color` itself for distant and point
  /// lights, attenuated by pow(-L.S, specularExponent) and cut to black outside limitingConeAngle for a
  /// spot light (no smoothing of the cone's edge).
  [[nodiscard]] std::array<double, 3> color_along(const std::array<double, 3>& to_light,
                                                  const std::array<float, 3>& color) const noexcept;

 private:
  LightKind kind_;
  std::array<double, 3> distant_direction_{};
  std::array<double, 3> position_{};
  std::array<double, 3> spot_axis_{};  // unit vector from the spot light towards pointsAt
  double spot_exponent_ = 1.0;
  std::optional<double> cos_cone_;
};

}  // namespace curvescan::svg::detail::filter
