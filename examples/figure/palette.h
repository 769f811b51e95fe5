// The gallery's colours: Okabe and Ito's palette for colour-blind readers ("Color Universal Design",
// 2008), which stays distinguishable under every common colour-vision deficiency, plus the greys of the
// axes, grids and control polygons. Straight (unpremultiplied) RGBA8, as Paint::solid takes them.
#pragma once

#include <array>
#include <cstddef>

#include "curvescan/raster/pixel_format.h"

namespace curvescan::figure {

inline constexpr StraightRgba8 kInk{33, 37, 41, 255};          ///< text, axes
inline constexpr StraightRgba8 kMutedInk{108, 117, 125, 255};  ///< tick labels, secondary text
inline constexpr StraightRgba8 kGrid{222, 226, 230, 255};      ///< grid lines
inline constexpr StraightRgba8 kControl{134, 142, 150, 255};   ///< control polygons and their points
inline constexpr StraightRgba8 kPaper{255, 255, 255, 255};     ///< background
inline constexpr StraightRgba8 kPanel{248, 249, 250, 255};     ///< panel background

inline constexpr StraightRgba8 kBlue{0, 114, 178, 255};
inline constexpr StraightRgba8 kVermillion{213, 94, 0, 255};
inline constexpr StraightRgba8 kGreen{0, 158, 115, 255};
inline constexpr StraightRgba8 kPurple{204, 121, 167, 255};
inline constexpr StraightRgba8 kOrange{230, 159, 0, 255};
inline constexpr StraightRgba8 kSky{86, 180, 233, 255};
inline constexpr StraightRgba8 kYellow{240, 228, 66, 255};

/// Curve colours in the order figures use them for the 1st, 2nd, ... curve of a plot.
inline constexpr std::array<StraightRgba8, 6> kSeries{kBlue, kVermillion, kGreen, kPurple, kOrange, kSky};

/// The i-th series colour, cycling.
[[nodiscard]] constexpr StraightRgba8 series(std::size_t i) noexcept {
  return kSeries[i % kSeries.size()];
}

/// `color` with alpha `alpha` (0..255).
[[nodiscard]] constexpr StraightRgba8 with_alpha(StraightRgba8 color, int alpha) noexcept {
  return {color.r, color.g, color.b, static_cast<std::uint8_t>(alpha)};
}

}  // namespace curvescan::figure
