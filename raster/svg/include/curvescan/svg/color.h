// CSS colours as SVG uses them (SVG 1.1 section 4.4 "<color>", CSS Color Module Level 3 and the
// #rrggbbaa / #rgba forms of Level 4): the 148 named colours plus "transparent", #rgb, #rgba, #rrggbb,
// #rrggbbaa, rgb() and rgba() with integers or percentages, hsl() and hsla().
//
// "currentColor" is not a colour but a reference to the `color` property; callers resolve it (see
// paint.h) because only they know the inherited value.
#pragma once

#include <string_view>

#include "curvescan/raster/paint.h"
#include "curvescan/status.h"

namespace curvescan::svg {

/// Parses a CSS colour into the core's Color (paint.h). Names and function names are ASCII case-insensitive
/// (CSS). Out-of-range channel values are clamped (CSS Color 3 section 4.2.1). Fails with a message naming
/// the text otherwise.
[[nodiscard]] Result<Color> parse_color(std::string_view text);

}  // namespace curvescan::svg
