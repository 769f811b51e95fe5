// The gallery's colours: Okabe and Ito's palette for colour-blind readers ("Color Universal Design",
// 2008), which stays distinguishable under every common colour-vision deficiency, plus the greys of the
// axes, grids and control polygons. Written as 8-bit channels (Color::from_rgba8).
#pragma once

#include <array>
#include <cstddef>

#include "curvescan/raster/paint.h"

namespace curvescan::figure {

inline constexpr Color kInk = Color::from_rgba8(33, 37, 41);          ///< text, axes
inline constexpr Color kMutedInk = Color::from_rgba8(108, 117, 125);  ///< tick labels, secondary text
inline constexpr Color kGrid = Color::from_rgba8(222, 226, 230);      ///< grid lines
inline constexpr Color kControl = Color::from_rgba8(134, 142, 150);   ///< control polygons and their points
inline constexpr Color kPaper = Color::from_rgba8(255, 255, 255);     ///< background
inline constexpr Color kPanel = Color::from_rgba8(248, 249, 250);     ///< panel background

inline constexpr Color kBlue = Color::from_rgba8(0, 114, 178);
inline constexpr Color kVermillion = Color::from_rgba8(213, 94, 0);
inline constexpr Color kGreen = Color::from_rgba8(0, 158, 115);
inline constexpr Color kPurple = Color::from_rgba8(204, 121, 167);
inline constexpr Color kOrange = Color::from_rgba8(230, 159, 0);
inline constexpr Color kSky = Color::from_rgba8(86, 180, 233);
inline constexpr Color kYellow = Color::from_rgba8(240, 228, 66);

/// Curve colours in the order figures use them for the 1st, 2nd, ... curve of a plot.
inline constexpr std::array<Color, 6> kSeries{kBlue, kVermillion, kGreen, kPurple, kOrange, kSky};

/// The i-th series colour, cycling.
[[nodiscard]] constexpr Color series(std::size_t i) noexcept {
  return kSeries[i % kSeries.size()];
}

/// `color` with alpha `alpha` (0..255).
[[nodiscard]] constexpr Color with_alpha(Color color, int alpha) noexcept {
  return {color.r, color.g, color.b, alpha / 255.0};
}

}  // namespace curvescan::figure
