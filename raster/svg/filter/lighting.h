// feDiffuseLighting and feSpecularLighting (Filter Effects 1, sections 15.14 and 15.22; SVG 1.1, 15.14 and
// 15.22): the input's alpha channel is a height map z = surfaceScale * A(x, y); its surface normal comes
// from the Sobel kernels of the specification (one table each for interior, edge and corner pixels), and
// the Phong model lights it:
//   diffuse:  RGB = kd * N.L * Lr,              A = 1
//   specular: RGB = ks * pow(N.H, exp) * Lr,    A = max(R, G, B),   H = normalize(L + (0, 0, 1))
// with L the unit vector to the light and Lr the light's colour there (light_source.h).
//
// Choices where the specification is silent or loose, matching Chromium and resvg:
// - The height map's "image" is the primitive subregion: its first and last rows and columns take the
//   edge and corner kernels. A subregion one pixel wide or high has no neighbour along that axis, and the
//   normal's component along it is 0.
// - A surface point is the pixel's integer position (its top-left corner) in filter pixels, the same
//   point feTurbulence samples.
// - The specular result (R, G, B, max) is used as premultiplied colour, as both browsers' engines do:
//   colour never exceeds alpha by construction.
// - kernelUnitLength is read and validated but the normal is computed at device resolution (one filter
//   pixel), as in Chromium and resvg; the caller warns that the attribute is approximated.
#pragma once

#include <array>
#include <optional>
#include <pugixml.hpp>
#include <string>

#include "filter_image.h"
#include "filter_space.h"
#include "light_source.h"
#include "primitive_numbers.h"

namespace curvescan::svg::detail::filter {

struct DiffuseLightingParams {
  double surface_scale = 1.0;
  double diffuse_constant = 1.0;                 ///< kd >= 0
  std::optional<NumberPair> kernel_unit_length;  ///< given and > 0: approximated (see above)
  LightSource light;
};

struct SpecularLightingParams {
  double surface_scale = 1.0;
  double specular_constant = 1.0;                ///< ks >= 0
  double specular_exponent = 1.0;                ///< in [1, 128]
  std::optional<NumberPair> kernel_unit_length;  ///< given and > 0: approximated (see above)
  LightSource light;
};

/// Reads surfaceScale, diffuseConstant, kernelUnitLength and the light source child. nullopt and `error`
/// for a missing light source, a negative diffuseConstant or a kernelUnitLength that is not positive.
[[nodiscard]] std::optional<DiffuseLightingParams> read_diffuse_lighting(const pugi::xml_node& primitive,
                                                                         std::string& error);
/// Reads surfaceScale, specularConstant, specularExponent, kernelUnitLength and the light source child.
/// nullopt and `error` as read_diffuse_lighting, and for a specularExponent outside [1, 128] (the range the
/// specification gives; Firefox and resvg also reject it).
[[nodiscard]] std::optional<SpecularLightingParams> read_specular_lighting(const pugi::xml_node& primitive,
                                                                           std::string& error);

/// `lighting_color` is the lighting-color property in the primitive's colour space, each channel in [0, 1].
/// Only the pixels of the subregion inside `written` are computed and written (a pixel's normal reads its
/// neighbours, so the result there does not change). The height map is `in` where it exists: `input_area`
/// (the input's own subregion) when it reaches beyond the subregion -- which only clips the result, Filter
/// Effects 1, 9.7 -- and the edge of the specification's normal kernels is then the edge of the two
/// together; without `input_area`, the subregion's edge.
void render_diffuse_lighting(const DiffuseLightingParams& params, const FilterSpace& space,
                             PixelRect subregion, const FilterImage& in,
                             const std::array<float, 3>& lighting_color, FilterImage& out,
                             std::optional<PixelRect> written = std::nullopt,
                             std::optional<PixelRect> input_area = std::nullopt);
void render_specular_lighting(const SpecularLightingParams& params, const FilterSpace& space,
                              PixelRect subregion, const FilterImage& in,
                              const std::array<float, 3>& lighting_color, FilterImage& out,
                              std::optional<PixelRect> written = std::nullopt,
                              std::optional<PixelRect> input_area = std::nullopt);

/// The unnormalized surface normal (Nx, Ny) at pixel (x, y) of `in`, whose alpha is the height map, with
/// the kernel of the specification's table for that pixel's position in `area`: surfaceScale * FACTOR *
/// (K (*) A), negated. The normal is (Nx, Ny, 1) before normalization. Exposed for the tests.
[[nodiscard]] std::array<double, 2> surface_normal(const FilterImage& in, PixelRect area, int x, int y,
                                                   double surface_scale) noexcept;

}  // namespace curvescan::svg::detail::filter
