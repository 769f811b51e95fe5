// feDisplacementMap (Filter Effects 1, section 15.13; SVG 1.1, 15.13):
//   P'(x, y) <- P(x + scale * (XC(x, y) - 0.5), y + scale * (YC(x, y) - 0.5))
// where XC and YC are the channels of the displacement map `in2` chosen by xChannelSelector and
// yChannelSelector, taken unpremultiplied (the specification requires the map's colour unpremultiplied),
// and P is the premultiplied image `in`.
//
// scale is a length in primitive units; along x it becomes filter pixels by the x scale and along y by the
// y scale (with primitiveUnits="objectBoundingBox", by the bounding box's width and height), as Chromium
// and resvg apply it.
//
// Sampling: the displaced point of a pixel's centre lands in some pixel of `in`; that pixel's value is
// taken as is (nearest pixel, no interpolation), as browsers do. Points outside the primitive subregion
// read transparent black.
#pragma once

#include <optional>
#include <pugixml.hpp>
#include <string>

#include "filter_image.h"
#include "filter_space.h"

namespace curvescan::svg::detail::filter {

enum class ColorChannel { kR = 0, kG = 1, kB = 2, kA = 3 };

struct DisplacementMapParams {
  double scale = 0.0;  ///< in primitive units
  ColorChannel x_channel = ColorChannel::kA;
  ColorChannel y_channel = ColorChannel::kA;
};

/// Reads scale, xChannelSelector and yChannelSelector. Never in error: an unparsable scale is 0 and an
/// unknown selector A (the lacuna values). `error` is left untouched.
[[nodiscard]] std::optional<DisplacementMapParams> read_displacement_map(const pugi::xml_node& primitive,
                                                                         std::string& error);

/// `in` is displaced by the map `in2`.
void render_displacement_map(const DisplacementMapParams& params, const FilterSpace& space,
                             PixelRect subregion, const FilterImage& in, const FilterImage& in2,
                             FilterImage& out);

}  // namespace curvescan::svg::detail::filter
