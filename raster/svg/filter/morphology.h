// feMorphology (Filter Effects 1, section 15.20; SVG 1.1, 15.20): each channel of the result is the
// minimum (erode) or maximum (dilate) of that channel over the rectangle of 2 * rx + 1 by 2 * ry + 1 pixels
// centred on the pixel, on premultiplied values. The rectangle reads the input image where it exists --
// the input's own subregion, beyond this primitive's subregion if that is smaller (the subregion clips the
// result, Filter Effects 1, 9.7, as for the blur) -- and is clipped there, as Chromium clamps its window to
// the input's bounds: pixels beyond the input's edge neither erode nor dilate. (resvg clips the window to
// the primitive's own subregion instead.)
//
// Filter Effects 1: "A negative or zero value disables the effect of the given filter primitive (i.e., the
// result is the filter input image)"; the lacuna value is 0. A negative radius x or y, or both zero, give
// the input. With one radius zero and the other positive, the window has no extent along the zero axis and
// the primitive erodes or dilates along the other only, as Chromium (Skia's morphology filter) and Firefox
// do. A radius is converted to filter pixels and rounded to the nearest whole pixel; a radius that rounds
// to 0 pixels leaves that axis unchanged likewise.
//
// The minimum over a rectangle is a minimum of row minima, so the filter runs as two passes of a sliding
// window (a monotonic queue, morphology.cpp), each linear in the number of pixels and independent of the
// radius.
#pragma once

#include <optional>
#include <pugixml.hpp>
#include <string>

#include "filter_image.h"
#include "filter_space.h"

namespace curvescan::svg::detail::filter {

enum class MorphologyOperator { kErode, kDilate };

struct MorphologyParams {
  MorphologyOperator op = MorphologyOperator::kErode;
  double radius_x = 0.0;  ///< in primitive units; negative on either axis or 0 on both: the input
  double radius_y = 0.0;
};

/// Reads operator and radius. Never in error: an unparsable radius takes the lacuna value 0 (which
/// disables the effect), an unknown operator the lacuna value erode. `error` is left untouched.
[[nodiscard]] std::optional<MorphologyParams> read_morphology(const pugi::xml_node& primitive,
                                                              std::string& error);

/// Whether `params` leave the input unchanged (a negative radius, both radii zero, or not a number).
[[nodiscard]] bool morphology_is_identity(const MorphologyParams& params) noexcept;

/// Writes the result inside `subregion` (and `needed`, when given), reading `in` inside `input_area` (where
/// the input exists: its own subregion; `subregion` when not given). A pixel none of whose window lies in
/// `input_area` is transparent. Reads only the input's ink (`in.extent`) and one pixel around it, and
/// returns the rectangle it wrote, outside which the result is transparent.
PixelRect render_morphology(const MorphologyParams& params, const FilterSpace& space, PixelRect subregion,
                            const FilterImage& in, FilterImage& out,
                            std::optional<PixelRect> input_area = std::nullopt,
                            std::optional<PixelRect> needed = std::nullopt);

}  // namespace curvescan::svg::detail::filter
