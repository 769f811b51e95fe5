// The <filter> element resolved for one filtered element (Filter Effects 1, sections 7 and 8; SVG 1.1
// 15.5-15.7): the filter region in the element's user space, primitiveUnits, and where its primitives are.
//
//  - filterUnits (default objectBoundingBox): x, y, width, height are fractions of the element's bounding
//    box (a percentage is hundredths of it), default -10 %, -10 %, 120 %, 120 %; with userSpaceOnUse they
//    are user-space lengths, percentages of the viewport.
//  - An objectBoundingBox filterUnits or primitiveUnits on an element whose box has no area disables the
//    element's rendering (SVG 1.1 7.11), and so does a region of zero or negative width or height.
//  - href (xlink:href) inheritance, as gradients and patterns have it (SVG 1.1 15.3): each of these
//    attributes comes from the nearest filter of the chain that has it, and the primitives from the
//    nearest one that has any.
#pragma once

#include <optional>
#include <pugixml.hpp>

#include "computed_style.h"
#include "curvescan/curves/rect.h"
#include "paint_server.h"

namespace curvescan::svg::detail::filter {

struct FilterDefinition {
  pugi::xml_node primitives;             ///< the <filter> whose children are the primitives
  Rect region;                           ///< the filter region in the element's user space
  bool bounding_box_primitives = false;  ///< primitiveUnits="objectBoundingBox"
};

/// `filter` resolved for an element whose user-space bounding box is `bbox`; nullopt when the element
/// must not be rendered (see above).
[[nodiscard]] std::optional<FilterDefinition> resolve_filter_element(const pugi::xml_node& filter,
                                                                     const IdIndex& ids,
                                                                     const std::optional<Rect>& bbox,
                                                                     const ResolveContext& context,
                                                                     Diagnostics& diagnostics);

/// One of x, y, width, height: in bounding-box units a number is a fraction and a percentage hundredths;
/// otherwise a length in user units with percentages of `reference`. `fallback` (already in the attribute's
/// units) when it is missing or invalid (invalid: with a warning naming `element`).
[[nodiscard]] double region_attribute(const pugi::xml_attribute& attribute, double fallback,
                                      bool bounding_box, LengthAxis axis, std::string_view element,
                                      Diagnostics& diagnostics);

}  // namespace curvescan::svg::detail::filter
