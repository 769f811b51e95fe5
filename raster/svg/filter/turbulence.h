// feTurbulence (Filter Effects 1, section 15.26; SVG 1.1, section 15.25): Perlin noise, summed over octaves
// as "turbulence" (sum of |noise|) or "fractalNoise" (sum of noise), from the specification's reference C
// code. Everything that decides a pixel value — the Park-Miller random number generator seeded per spec,
// the lattice permutation, the four gradient tables, noise2 and the octave loop with its stitching
// bookkeeping — is reproduced operation for operation (turbulence.cpp), so a given seed draws the same
// pattern as every other conforming renderer.
//
// The noise is a function of user-space coordinates: pixel (x, y) of the filter image samples the noise at
// the user-space point of that pixel's top-left corner, (origin_x + x / scale_x, origin_y + y / scale_y).
// This is the point resvg and Chromium sample (both map the integer pixel position back through the
// filter-space scale), so patterns line up with theirs at any resolution.
#pragma once

#include <optional>
#include <pugixml.hpp>
#include <string>

#include "filter_image.h"
#include "filter_space.h"

namespace curvescan::svg::detail::filter {

/// Octaves beyond this add less than 2^-24 of the output range — below float precision — so numOctaves is
/// clamped here; it bounds the cost (each octave is one noise evaluation per channel and pixel).
inline constexpr int kMaxTurbulenceOctaves = 24;

struct TurbulenceParams {
  double base_frequency_x = 0.0;  ///< >= 0, per user unit
  double base_frequency_y = 0.0;  ///< >= 0
  int num_octaves = 1;            ///< in [0, kMaxTurbulenceOctaves]
  long long seed = 0;             ///< already truncated towards zero, within the generator's range
  bool stitch_tiles = false;
  bool fractal_noise = false;  ///< type="fractalNoise"; false for type="turbulence"
};

/// Reads type, baseFrequency, numOctaves, seed and stitchTiles. nullopt and `error` for a negative
/// baseFrequency (an error per Filter Effects 1). Unparsable values take the lacuna values (turbulence,
/// 0, 1, 0, noStitch); a negative numOctaves gives zero octaves; seed is truncated towards zero.
[[nodiscard]] std::optional<TurbulenceParams> read_turbulence(const pugi::xml_node& primitive,
                                                              std::string& error);

/// Writes the noise into `out` inside `subregion` (clipped to `out`), premultiplied; only inside `written`
/// when given (the pixels a filter needs). The tile of stitchTiles is the subregion in user space.
void render_turbulence(const TurbulenceParams& params, const FilterSpace& space, PixelRect subregion,
                       FilterImage& out, std::optional<PixelRect> written = std::nullopt);

}  // namespace curvescan::svg::detail::filter
