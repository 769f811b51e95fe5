#include "lighting.h"

#include <algorithm>
#include <cmath>

#include "xml_names.h"

namespace curvescan::svg::detail::filter {

namespace {

/// The attributes both lighting primitives share. false and `error` on the spec's error cases.
bool read_common(const pugi::xml_node& primitive, double& surface_scale,
                 std::optional<NumberPair>& kernel_unit, LightSource& light, std::string& error) {
  surface_scale = primitive_number(primitive, "surfaceScale").value_or(1.0);
  if (primitive.attribute("kernelUnitLength")) {
    // Filter Effects 1, 15.14: "A negative or zero value is an error"; an unparsable value is as if absent.
    kernel_unit = primitive_number_pair(primitive, "kernelUnitLength");
    if (kernel_unit && (kernel_unit->x <= 0.0 || kernel_unit->y <= 0.0)) {
      error = std::string(local_name(primitive)) + ": kernelUnitLength must be positive";
      return false;
    }
  }
  const auto source = read_light_source(primitive, error);
  if (!source) return false;
  light = *source;
  return true;
}

double alpha_at(const FilterImage& image, int x, int y) noexcept {
  return image.pixel(x, y)[3];
}

std::array<double, 3> unit_normal(const std::array<double, 2>& n) noexcept {
  // Scaled by the largest component first so that normals of huge surfaceScale values do not overflow.
  const double largest = std::max({std::fabs(n[0]), std::fabs(n[1]), 1.0});
  const double x = n[0] / largest, y = n[1] / largest, z = 1.0 / largest;
  const double length = std::sqrt(x * x + y * y + z * z);
  return {x / length, y / length, z / length};
}

double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) noexcept {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// Clamps to [0, 1]; NaN (from infinite light positions or surface scales of 1e308) becomes 0.
float unit_clamp(double v) noexcept {
  return v >= 0.0 ? static_cast<float>(std::min(v, 1.0)) : 0.0f;
}

/// Calls `shade(x, y, unit normal, unit vector to light, light colour)` for every pixel of the area inside
/// `written`; `edge` is the height map's edge (the area, or the input's own subregion when that reaches
/// beyond it).
template <typename Shade>
void for_each_lit_pixel(const LightSource& light, double surface_scale, const FilterSpace& space,
                        PixelRect area, PixelRect edge, PixelRect written, const FilterImage& in,
                        const std::array<float, 3>& lighting_color, Shade&& shade) {
  const PlacedLight placed(light, space);
  const PixelRect lit = area.intersect(written);
  for (int y = lit.y0; y < lit.y1; ++y) {
    for (int x = lit.x0; x < lit.x1; ++x) {
      const auto normal = unit_normal(surface_normal(in, edge, x, y, surface_scale));
      const double z = surface_scale * alpha_at(in, x, y);
      const auto to_light = placed.direction_to_light(x, y, z);
      shade(x, y, normal, to_light, placed.color_along(to_light, lighting_color));
    }
  }
}

}  // namespace

std::array<double, 2> surface_normal(const FilterImage& in, PixelRect area, int x, int y,
                                     double surface_scale) noexcept {
  // Every table of the specification is one rule: along x, a central difference where both neighbours
  // exist and a one-sided difference at an edge; across it, the rows y-1, y, y+1 weighted 1, 2, 1 where
  // they exist; FACTOR = 2 / (sum of the row weights * the x distance of the difference). This gives the
  // interior 1/4, the edges 1/3 and 1/2 and the corners 2/3 of the tables (tests compare with the tables).
  const bool left = x > area.x0, right = x<area.x1 - 1, up = y> area.y0, down = y < area.y1 - 1;
  double nx = 0.0, ny = 0.0;
  const int xl = left ? x - 1 : x, xr = right ? x + 1 : x;
  if (xr > xl) {
    double sum = 2.0 * (alpha_at(in, xr, y) - alpha_at(in, xl, y));
    double weights = 2.0;
    if (up) {
      sum += alpha_at(in, xr, y - 1) - alpha_at(in, xl, y - 1);
      weights += 1.0;
    }
    if (down) {
      sum += alpha_at(in, xr, y + 1) - alpha_at(in, xl, y + 1);
      weights += 1.0;
    }
    nx = -surface_scale * (2.0 / (weights * (xr - xl))) * sum;
  }
  const int yu = up ? y - 1 : y, yd = down ? y + 1 : y;
  if (yd > yu) {
    double sum = 2.0 * (alpha_at(in, x, yd) - alpha_at(in, x, yu));
    double weights = 2.0;
    if (left) {
      sum += alpha_at(in, x - 1, yd) - alpha_at(in, x - 1, yu);
      weights += 1.0;
    }
    if (right) {
      sum += alpha_at(in, x + 1, yd) - alpha_at(in, x + 1, yu);
      weights += 1.0;
    }
    ny = -surface_scale * (2.0 / (weights * (yd - yu))) * sum;
  }
  return {nx, ny};
}

std::optional<DiffuseLightingParams> read_diffuse_lighting(const pugi::xml_node& primitive,
                                                           std::string& error) {
  DiffuseLightingParams params;
  if (!read_common(primitive, params.surface_scale, params.kernel_unit_length, params.light, error))
    return std::nullopt;
  // kd "can be any non-negative number" (Filter Effects 1, 9.11); the specification names no error for a
  // negative one, and Chrome clamps it to 0: the surface is then unlit (opaque black), not an error.
  params.diffuse_constant = std::max(primitive_number(primitive, "diffuseConstant").value_or(1.0), 0.0);
  return params;
}

std::optional<SpecularLightingParams> read_specular_lighting(const pugi::xml_node& primitive,
                                                             std::string& error) {
  SpecularLightingParams params;
  if (!read_common(primitive, params.surface_scale, params.kernel_unit_length, params.light, error))
    return std::nullopt;
  params.specular_constant = primitive_number(primitive, "specularConstant").value_or(1.0);
  if (params.specular_constant < 0.0) {
    error = "feSpecularLighting: specularConstant must not be negative";
    return std::nullopt;
  }
  params.specular_exponent = primitive_number(primitive, "specularExponent").value_or(1.0);
  if (!(params.specular_exponent >= 1.0 && params.specular_exponent <= 128.0)) {
    error = "feSpecularLighting: specularExponent must be between 1 and 128";
    return std::nullopt;
  }
  return params;
}

void render_diffuse_lighting(const DiffuseLightingParams& params, const FilterSpace& space,
                             PixelRect subregion, const FilterImage& in,
                             const std::array<float, 3>& lighting_color, FilterImage& out,
                             std::optional<PixelRect> written, std::optional<PixelRect> input_area) {
  const PixelRect area = subregion.intersect(out.bounds()).intersect(in.bounds());
  if (area.empty()) return;
  // The height map is the input where it exists, beyond the subregion too (its edge, for the normals'
  // kernels, is the farther of the two).
  const PixelRect edge = area.unite(input_area.value_or(area).intersect(in.bounds()));
  for_each_lit_pixel(params.light, params.surface_scale, space, area, edge, written.value_or(area), in,
                     lighting_color,
                     [&](int x, int y, const auto& normal, const auto& to_light, const auto& color) {
                       const double k = params.diffuse_constant * dot(normal, to_light);
                       float* pixel = out.pixel(x, y);
                       for (int c = 0; c < 3; ++c)
                         pixel[c] = unit_clamp(k * color[static_cast<std::size_t>(c)]);
                       pixel[3] = 1.0f;
                     });
}

void render_specular_lighting(const SpecularLightingParams& params, const FilterSpace& space,
                              PixelRect subregion, const FilterImage& in,
                              const std::array<float, 3>& lighting_color, FilterImage& out,
                              std::optional<PixelRect> written, std::optional<PixelRect> input_area) {
  const PixelRect area = subregion.intersect(out.bounds()).intersect(in.bounds());
  if (area.empty()) return;
  // The height map is the input where it exists, beyond the subregion too (its edge, for the normals'
  // kernels, is the farther of the two).
  const PixelRect edge = area.unite(input_area.value_or(area).intersect(in.bounds()));
  for_each_lit_pixel(
      params.light, params.surface_scale, space, area, edge, written.value_or(area), in, lighting_color,
      [&](int x, int y, const auto& normal, const auto& to_light, const auto& color) {
        // H, the halfway vector between the light and the eye at (0, 0, 1).
        std::array<double, 3> halfway = {to_light[0], to_light[1], to_light[2] + 1.0};
        const double length = std::sqrt(dot(halfway, halfway));
        double k = 0.0;
        if (length > 0.0) {
          const double n_dot_h = dot(normal, halfway) / length;
          k = params.specular_constant * std::pow(std::max(n_dot_h, 0.0), params.specular_exponent);
        }
        float* pixel = out.pixel(x, y);
        for (int c = 0; c < 3; ++c) pixel[c] = unit_clamp(k * color[static_cast<std::size_t>(c)]);
        pixel[3] = std::max({pixel[0], pixel[1], pixel[2]});
      });
}

}  // namespace curvescan::svg::detail::filter
