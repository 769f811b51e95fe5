#include "displacement_map.h"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "primitive_numbers.h"

namespace curvescan::svg::detail::filter {

namespace {

ColorChannel read_channel(const pugi::xml_node& primitive, const char* name) {
  const std::string_view value = primitive.attribute(name).value();
  if (value == "R") return ColorChannel::kR;
  if (value == "G") return ColorChannel::kG;
  if (value == "B") return ColorChannel::kB;
  return ColorChannel::kA;
}

/// The unpremultiplied value of one channel of a premultiplied pixel (alpha itself for kA).
double unpremultiplied(const float* pixel, ColorChannel channel) noexcept {
  const int c = static_cast<int>(channel);
  if (c == 3) return pixel[3];
  return pixel[3] > 0.0f ? std::min(1.0, static_cast<double>(pixel[c]) / pixel[3]) : 0.0;
}

/// The pixel index holding the displaced point `centre + offset`, or nullopt when it is outside [lo, hi).
std::optional<int> displaced_index(int i, double offset, int lo, int hi) noexcept {
  const double position = std::floor(i + 0.5 + offset);
  if (!(position >= lo && position < hi)) return std::nullopt;
  return static_cast<int>(position);
}

}  // namespace

std::optional<DisplacementMapParams> read_displacement_map(const pugi::xml_node& primitive,
                                                           std::string& /*error*/) {
  DisplacementMapParams params;
  params.scale = primitive_number(primitive, "scale").value_or(0.0);
  params.x_channel = read_channel(primitive, "xChannelSelector");
  params.y_channel = read_channel(primitive, "yChannelSelector");
  return params;
}

void render_displacement_map(const DisplacementMapParams& params, const FilterSpace& space,
                             PixelRect subregion, const FilterImage& in, const FilterImage& in2,
                             FilterImage& out) {
  const PixelRect area = subregion.intersect(out.bounds()).intersect(in.bounds()).intersect(in2.bounds());
  if (area.empty()) return;
  const double scale_x = space.x_to_pixels(space.user_width(params.scale));
  const double scale_y = space.y_to_pixels(space.user_height(params.scale));
  for (int y = area.y0; y < area.y1; ++y) {
    for (int x = area.x0; x < area.x1; ++x) {
      const float* map = in2.pixel(x, y);
      const auto sx =
          displaced_index(x, scale_x * (unpremultiplied(map, params.x_channel) - 0.5), area.x0, area.x1);
      const auto sy =
          displaced_index(y, scale_y * (unpremultiplied(map, params.y_channel) - 0.5), area.y0, area.y1);
      if (!sx || !sy) continue;  // out stays transparent black
      std::copy_n(in.pixel(*sx, *sy), 4, out.pixel(x, y));
    }
  }
}

}  // namespace curvescan::svg::detail::filter
