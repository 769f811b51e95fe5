// Running a filter (Filter Effects 1, sections 8 and 9): the primitives of a <filter> element in document
// order, each reading results by name, and the CSS filter functions.
//
// Inputs (in, in2; section 9.2): SourceGraphic, SourceAlpha, or the `result` of an earlier primitive.
// BackgroundImage, BackgroundAlpha, FillPaint and StrokePaint are not supported: read, as browsers do,
// like a name no primitive gave, with a warning. A missing `in`, or one naming no earlier result, is the
// previous primitive's result (SourceGraphic for the first), as the specification says.
//
// Subregions (section 9.7): x, y, width, height of a primitive, in primitiveUnits; each missing one defaults
// to the union of its inputs' subregions, or to the filter region when an input is a standard input or it
// has none (feFlood, feImage) -- and, as browsers do, for feTile. The result is clipped to the filter
// region; nothing outside the subregion is written.
//
// Colour spaces (section 16): each primitive computes in its color-interpolation-filters space; inputs are
// converted to it, and the final result back to sRGB. SourceGraphic is sRGB.
//
// Errors: a primitive whose attributes are in error (a negative stdDeviation, ...), and a primitive this
// renderer does not implement, make the whole filter's result transparent black, with a warning.
//
// Work is bounded by what can matter (none of this changes a pixel that is used):
//  - extents: every image knows the rectangle outside which it is transparent (FilterImage::extent), and a
//    primitive that keeps transparent pixels transparent computes only over its inputs' ink;
//  - needed pixels: from the pixels the caller uses (FilterSources::needed), the graph carries back what
//    each result must hold (input_needed: moved by an offset, grown by a blur or a neighbourhood kernel),
//    and the primitives compute only that;
//  - memory: a result nobody reads any more gives its memory to the next one (cleared only where it was
//    written), a per-pixel primitive computes in place in an input read for the last time, and a blur
//    reads SourceAlpha from SourceGraphic without a copy.
#pragma once

#include <pugixml.hpp>

#include "computed_style.h"
#include "curvescan/svg/color.h"
#include "filter_image.h"
#include "filter_property.h"
#include "filter_region.h"
#include "filter_space.h"
#include "primitive_table.h"
#include "resolved_filter.h"

namespace curvescan::svg::detail::filter {

/// What the filtered element gives its filter besides its rendering.
struct FilterSources {
  const FilterImage* source_graphic = nullptr;  ///< sRGB, the filter image's size
  Color current_color;  ///< the element's `color` (drop-shadow's default colour)
  /// The pixels of the result the caller will use (those that land on the canvas): each primitive computes
  /// only what they depend on, and the result may be transparent elsewhere. Everything by default.
  PixelRect needed{-(1 << 30), -(1 << 30), 1 << 30, 1 << 30};
};

/// Runs the primitives of `definition` (read once, resolved_filter.h) over `region` (pixels of the filter
/// image) and returns the result in sRGB, transparent outside `region` (and, where the caller said it does
/// not need them, outside `sources.needed`). With `result_space`, the result may be left in the last
/// primitive's colour space, stored there, for to_image (filter_surface.h) to convert while it quantizes: one
/// pass less.
[[nodiscard]] FilterImage run_filter(const FilterDefinition& definition, const FilterSpace& space,
                                     PixelRect region, const FilterSources& sources,
                                     const FilterEnvironment& environment, Diagnostics& diagnostics,
                                     ColorSpace* result_space = nullptr);

/// Applies one CSS filter function (not kUrl) to `source` (sRGB) inside `region`; the result is in sRGB.
/// The functions compute in sRGB, as Chrome, Firefox and resvg apply them. Only the pixels of `needed`
/// are computed (the result is transparent elsewhere), as run_filter does with FilterSources::needed.
[[nodiscard]] FilterImage run_filter_function(
    const FilterFunction& function, const FilterSpace& space, PixelRect region, const FilterImage& source,
    const Color& current_color, PixelRect needed = PixelRect{-(1 << 30), -(1 << 30), 1 << 30, 1 << 30});

/// The pixels of its input that `function` (not kUrl) reads to make `result_needed` of its result: grown
/// by a blur's reach, and for drop-shadow() also moved back by the offset; the same pixels for the others.
[[nodiscard]] PixelRect function_input_needed(const FilterFunction& function, const FilterSpace& space,
                                              PixelRect result_needed) noexcept;

/// At most how many images of the filter image's size running `filter` holds at once (results still to be
/// read, standard inputs, their colour-space conversions, the result being made): what the caller budgets.
/// Computed when the filter is resolved (ResolvedFilter::peak_images).
[[nodiscard]] int peak_filter_images(const ResolvedFilter& filter);

/// `user` (a user-space rectangle) in whole filter pixels, rounded outwards (a 1e-4 pixel slack keeps a
/// rectangle meant to be whole pixels from growing by one).
[[nodiscard]] PixelRect pixel_rect(const FilterSpace& space, const Rect& user) noexcept;

}  // namespace curvescan::svg::detail::filter
