// <pattern> (SVG 1.1 section 13.3): the tile of a pattern paint server, resolved for one painted element.
//
// Attributes come from the first pattern of the href chain that specifies them (x, y, width, height,
// patternUnits, patternContentUnits, patternTransform, viewBox, preserveAspectRatio), and the content
// from the first pattern of the chain that has element children (13.3, "xlink:href"); the chain follows
// only <pattern> elements, at most kMaxPatternChain links, and stops at a cycle.
//
// Spaces. Pattern space is the painted element's user space times patternTransform. The tile is the
// rectangle (x, y, width, height) of pattern space -- fractions of the element's bounding box with
// patternUnits="objectBoundingBox" (the default). The content is drawn in tile coordinates, whose origin
// is the tile's top-left corner, through `content_transform`: the viewBox mapping to the tile's size
// when there is a viewBox, else the bounding box's scale with patternContentUnits="objectBoundingBox",
// else the identity (as browsers and resvg place it). The renderer draws that content into an image of
// the tile and paints with the image repeated (image_pattern.h).
#pragma once

#include <optional>
#include <pugixml.hpp>

#include "computed_style.h"
#include "curvescan/curves/affine.h"
#include "curvescan/curves/rect.h"
#include "paint_server.h"

namespace curvescan::svg::detail {

inline constexpr int kMaxPatternChain = 16;
/// Deepest nesting of patterns drawn inside pattern tiles (each level holds a tile image).
inline constexpr int kMaxPatternDepth = 8;

struct PatternSetup {
  pugi::xml_node content;    ///< the pattern whose children are the tile's content
  Rect tile;                 ///< in pattern space
  Affine pattern_transform;  ///< pattern space -> the element's user space
  Affine content_transform;  ///< content coordinates -> tile coordinates
};

/// Resolves `pattern` for an element with user-space bounding box `bbox`. nullopt means the paint is
/// none: a tile without positive width and height (SVG 1.1 13.3: zero disables the effect), no content
/// anywhere in the chain, or objectBoundingBox units on an element without area (7.11).
[[nodiscard]] std::optional<PatternSetup> resolve_pattern(const pugi::xml_node& pattern, const IdIndex& ids,
                                                          const std::optional<Rect>& bbox,
                                                          const ResolveContext& context,
                                                          Diagnostics& diagnostics);

}  // namespace curvescan::svg::detail
