// A resolved <filter> (resolved_filter.h) placed for one filtered element (Filter Effects 1, sections 7 and
// 8; SVG 1.1 15.5-15.7): the filter region in the element's user space.
//
//  - filterUnits="objectBoundingBox" (the default): the region's numbers are fractions of the element's
//    bounding box; with userSpaceOnUse they are user-space lengths, settled when the filter was resolved.
//  - An objectBoundingBox filterUnits or primitiveUnits on an element whose box has no area disables the
//    element's rendering (SVG 1.1 7.11), and so does a region of zero or negative width or height.
#pragma once

#include <optional>
#include <pugixml.hpp>
#include <string_view>

#include "../computed_style.h"
#include "../paint_server.h"
#include "curvescan/curves/rect.h"
#include "resolved_filter.h"

namespace curvescan::svg::detail::filter {

struct FilterDefinition {
  const ResolvedFilter* filter = nullptr;  ///< what runs: the primitives, read once
  Rect region;                             ///< the filter region in the element's user space
  bool bounding_box_primitives = false;    ///< primitiveUnits="objectBoundingBox"
};

/// `filter` placed for an element whose user-space bounding box is `bbox`; nullopt when the element must
/// not be rendered (see above). `filter` must outlive the result.
[[nodiscard]] std::optional<FilterDefinition> place_filter(const ResolvedFilter& filter,
                                                           const std::optional<Rect>& bbox);

/// One of x, y, width, height: in bounding-box units a number is a fraction and a percentage hundredths;
/// otherwise a length in user units with percentages of `reference`. `fallback` (already in the attribute's
/// units) when it is missing or invalid (invalid: with a warning naming `element`).
[[nodiscard]] double region_attribute(const pugi::xml_attribute& attribute, double fallback,
                                      bool bounding_box, LengthAxis axis, std::string_view element,
                                      Diagnostics& diagnostics);

}  // namespace curvescan::svg::detail::filter
