// The filter primitives by element name (Filter Effects 1, section 9): how many inputs each reads, the
// function that reads its attributes into values (once per filter, resolved_filter.h) and the one that
// computes its result from those values. resolved_filter.cpp looks primitives up here;
// a primitive that is an SVG filter primitive but has no entry is reported as unsupported and makes its
// filter's result transparent black (Filter Effects 1, section 8: a filter with an error is not applied,
// the element renders as transparent black, rather than being silently drawn unfiltered).
//
// Adding a primitive: write its pixel function in its own file (params, read_x, render_x), its values in
// primitive_params.h, then one entry in kPrimitives (primitive_table.cpp) with a reader that reads the
// values and an adapter that calls the render function with them.
#pragma once

#include <functional>
#include <optional>
#include <pugixml.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../computed_style.h"
#include "../paint_server.h"
#include "color_space.h"
#include "curvescan/svg/color.h"
#include "filter_image.h"
#include "filter_space.h"
#include "flood.h"
#include "primitive_params.h"

namespace curvescan::svg::detail::filter {

struct ResolvedPrimitive;  // resolved_filter.h

/// What a primitive needs from the document beyond its own attributes.
struct FilterEnvironment {
  /// feImage: draws what `image` refers to into `out` (sRGB, transparent, the filter image's size) inside
  /// `subregion`, whose user-space rectangle is `user_subregion`. Empty when the document cannot (tests).
  std::function<void(const ImageParams& image, const FilterSpace& space, const Rect& user_subregion,
                     PixelRect subregion, FilterImage& out)>
      draw_fe_image;
};

/// One primitive to compute: its values, where it writes, and its inputs already in `color_space`.
struct PrimitiveCall {
  const PrimitiveParams& params;  ///< its attributes, read once (resolved_filter.h)
  const FilterSpace& space;
  PixelRect subregion;     ///< clipped to the filter region
  Rect user_subregion;     ///< the same in user space (feImage places its content in it)
  ColorSpace color_space;  ///< color-interpolation-filters of the primitive
  const FilterImage* in = nullptr;
  PixelRect in_subregion;  ///< the subregion of `in` (feTile's tile)
  const FilterImage* in2 = nullptr;
  std::vector<const FilterImage*> merge_inputs;  ///< feMerge: its feMergeNode inputs in order
  const FilterEnvironment& environment;
  Diagnostics& diagnostics;
  /// The filter image's size. On entry its extent is the subregion and it is transparent there; the
  /// adapter may narrow the extent to where its result can be other than transparent black (the input's
  /// ink, FilterImage::extent), compute only there and write nothing outside it. For a primitive whose
  /// entry says `in_place`, `out` may be the very image `in`, `in2` or a merge input is: its adapter reads
  /// the inputs' extents before it sets `out.extent`, always sets it, and its kernel reads each pixel
  /// before it writes it.
  FilterImage& out;
  /// `in` is SourceAlpha read from SourceGraphic: its colour channels count as zero (feGaussianBlur only).
  bool in_alpha_only = false;
  /// Only these pixels of the result are read later (FilterSources::needed, carried back through the
  /// primitives that read this one): an adapter may leave the rest transparent.
  PixelRect needed{-(1 << 30), -(1 << 30), 1 << 30, 1 << 30};
  /// feMerge: the inputs still in the other colour space than `color_space` (merge converts them a row at
  /// a time); empty when none is.
  std::vector<bool> merge_other_space{};
  /// feComposite: `in` (`in2`) is this premultiplied colour, in `color_space`, at every pixel of the
  /// subregion (an feFlood not drawn), and the image pointer is null.
  const float* in_constant = nullptr;
  const float* in2_constant = nullptr;
};

enum class PrimitiveInputs { kNone, kIn, kInAndIn2, kMergeNodes };

/// What reading a primitive's attributes needs: the element, its colour space (flood-color and
/// lighting-color are read in it), the style sheets its properties cascade with, where warnings go, and
/// where what is in error is said (the filter's result then becomes transparent black); for feImage, the
/// ids and the computed style of an element from its own ancestors.
struct PrimitiveReading {
  pugi::xml_node node;
  ColorSpace color_space;
  const css::StyleSheets* style_sheets;
  Diagnostics& diagnostics;
  std::string& error;
  const IdIndex& ids;
  const std::function<ComputedStyle(const pugi::xml_node&)>& style_of;
};

/// Reads the primitive's attributes into values (NoParams when it sets `error`).
using PrimitiveReader = PrimitiveParams (*)(const PrimitiveReading& reading);

/// Computes the primitive from its values.
using PrimitiveFunction = void (*)(const PrimitiveCall& call);

struct PrimitiveEntry {
  std::string_view name;
  PrimitiveInputs inputs;
  PrimitiveReader read;
  PrimitiveFunction run;
  /// The adapter writes every pixel of the extent it leaves in `out`, so the graph need not clear reused
  /// memory there first.
  bool writes_whole_extent = false;
  /// The result may be computed in the memory of an input read for the last time (see PrimitiveCall::out):
  /// each result pixel depends only on the same pixel of the inputs, or (feOffset) the kernel visits the
  /// pixels in an order that reads each before it writes it.
  bool in_place = false;
};

/// The entry of an implemented primitive, or null.
[[nodiscard]] const PrimitiveEntry* find_primitive(std::string_view name) noexcept;

/// True for the 17 filter primitives of Filter Effects 1 (fe* elements that are primitives, not
/// feFuncR / feMergeNode / light sources), implemented here or not.
[[nodiscard]] bool is_filter_primitive(std::string_view name) noexcept;

/// A primitive property (flood-color, lighting-color) of `node` as colour in `space`, unpremultiplied:
/// the cascaded value of `color_name` (currentColor: the inherited `color`) with `opacity_name`'s value
/// (empty: none) as alpha. Unset and invalid values (with a warning) take `initial`: opaque black is
/// flood-color's initial value; lighting-color's is white.
[[nodiscard]] FilterColor primitive_color(const pugi::xml_node& node, std::string_view color_name,
                                          std::string_view opacity_name, ColorSpace space,
                                          const css::StyleSheets* style_sheets, Diagnostics& diagnostics,
                                          const Color& initial = Color{0.0, 0.0, 0.0, 1.0});

/// color-interpolation-filters of `node` (inherited: the nearest ancestor that sets it); linearRGB by
/// default, and for auto.
[[nodiscard]] ColorSpace color_interpolation_filters(const pugi::xml_node& node,
                                                     const css::StyleSheets* style_sheets) noexcept;

}  // namespace curvescan::svg::detail::filter

namespace curvescan::svg::detail::filter {

/// The pixels of its inputs that `primitive` reads to make `result_needed` of its result: the same pixels for
/// the per-pixel primitives, moved for feOffset, grown by the blur's reach for feGaussianBlur with
/// edgeMode none, and `everything` for the others (and for attributes in error).
[[nodiscard]] PixelRect input_needed(const ResolvedPrimitive& primitive, const FilterSpace& space,
                                     PixelRect result_needed, PixelRect everything);

/// How far a primitive carries content, per axis in user units: 3σ for a blur, |dx| and |dy| for an offset
/// (both for feDropShadow), the radius for feMorphology, |scale| / 2 for feDisplacementMap, 0 for the
/// per-pixel primitives and unstitched feTurbulence. nullopt when this is not known in user units --
/// feConvolveMatrix and lighting (a reach in filter pixels), feTile (its result depends on where its input
/// lies), stitched feTurbulence (its tile is the whole subregion) -- and the caller must then keep the whole
/// filter region. `space` gives primitiveUnits.
[[nodiscard]] std::optional<std::pair<double, double>> primitive_reach(const ResolvedPrimitive& primitive,
                                                                       const FilterSpace& space);

}  // namespace curvescan::svg::detail::filter
