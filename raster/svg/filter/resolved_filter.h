// A <filter> element read from the XML once per render and viewport (docs/svg.md, "How a document is
// drawn", step 2; memoised by ResolvedReferences): its href chain followed with loops cut, its region and
// units, and its primitives with their inputs planned and their attributes parsed into values
// (primitive_params.h). The warnings about its attributes are given by that one reading. The drawing
// places the result for each filtered element (place_filter, filter_region.h: the bounding box) and runs it
// (filter_graph.h: the filter image's resolution); neither reads an attribute.
//
//  - filterUnits (default objectBoundingBox): x, y, width, height are fractions of the element's bounding
//    box (a percentage is hundredths of it), default -10 %, -10 %, 120 %, 120 %; with userSpaceOnUse they
//    are user-space lengths, percentages of the viewport where the filter is used.
//  - href (xlink:href) inheritance, as gradients and patterns have it (SVG 1.1 15.3): each of these
//    attributes comes from the nearest filter of the chain that has it, and the primitives from the
//    nearest one that has any child element.
//  - Primitives (Filter Effects 1, 9.2, 9.7): each one's inputs resolved to a standard input or the earlier
//    primitive that makes them, its subregion attributes in primitiveUnits, its color-interpolation-filters.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <pugixml.hpp>
#include <string>
#include <unordered_map>
#include <vector>

#include "../computed_style.h"
#include "../paint_server.h"
#include "color_space.h"
#include "primitive_params.h"
#include "primitive_table.h"

namespace curvescan::svg::detail::filter {

/// Where a primitive's input comes from.
struct PrimitiveInput {
  std::string standard;  ///< SourceGraphic, SourceAlpha: a standard input
  int producer = -1;     ///< otherwise the primitive whose result it is
};

struct ResolvedPrimitive {
  pugi::xml_node node;  ///< the element (for messages and tests; the drawing reads `params`)
  const PrimitiveEntry* entry = nullptr;
  std::vector<PrimitiveInput> inputs;  ///< in, in2, or feMerge's nodes, in order
  int last_use = -1;                   ///< the last primitive that reads this one's result
  /// x, y, width, height (9.7) in primitiveUnits: fractions of the bounding box with objectBoundingBox,
  /// otherwise user units with percentages of the viewport; NaN where missing or invalid (the default).
  std::array<double, 4> subregion{};
  ColorSpace color_space = ColorSpace::kLinearRgb;  ///< color-interpolation-filters
  PrimitiveParams params;
  /// What is in error in its attributes ("" when nothing): running it makes the filter's result
  /// transparent black (Filter Effects 1, section 8).
  std::string error;
};

struct ResolvedFilter {
  pugi::xml_node element;                ///< the <filter> the reference names (the start of the href chain)
  bool region_in_box = true;             ///< filterUnits="objectBoundingBox"
  bool bounding_box_primitives = false;  ///< primitiveUnits="objectBoundingBox"
  /// The filter region in filterUnits: fractions of the box, or user units.
  double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
  std::vector<ResolvedPrimitive> primitives;  ///< in document order, up to the first not implemented
  std::unordered_map<std::string, int> standard_last_use;  ///< the last primitive reading each standard input
  std::string unsupported;  ///< the first primitive without an implementation ("" when none): no result
  /// At most how many images of the filter image's size running it holds at once (filter_graph.h).
  int peak_images = 1;
  /// Passes over the pixels: one per primitive, one per feMergeNode (the work budget, kFilterWorkPixels).
  std::int64_t passes = 0;
};

/// `filter` read for `context`'s viewport; its primitives' properties cascade with `style_sheets`, and
/// `style_of` gives the style an feImage's element inherits (the drawing walk owns the document's cascade).
[[nodiscard]] ResolvedFilter resolve_filter(
    const pugi::xml_node& filter, const IdIndex& ids, const ResolveContext& context,
    const css::StyleSheets* style_sheets, const std::function<ComputedStyle(const pugi::xml_node&)>& style_of,
    Diagnostics& diagnostics);

}  // namespace curvescan::svg::detail::filter
