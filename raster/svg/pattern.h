// <pattern> (SVG 1.1 section 13.3): the tile of a pattern paint server, resolved once per pattern and
// viewport in a render (resolved_references.h), then placed for each painted element.
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
#include "curvescan/svg/viewport.h"
#include "paint_server.h"

namespace curvescan::svg::detail {

inline constexpr int kMaxPatternChain = 16;
/// Deepest nesting of patterns drawn inside pattern tiles (each level holds a tile image).
inline constexpr int kMaxPatternDepth = 8;

/// A <pattern> with its href chain followed and every attribute read (resolve_pattern): what a use of it
/// needs besides the painted element's box. Lengths are settled for the viewport of the ResolveContext
/// it was resolved for; with patternUnits="objectBoundingBox" x, y, width and height are fractions of the
/// box.
struct ResolvedPattern {
  /// The pattern whose children are the tile's content; null when no pattern of the chain has any (the
  /// paint is none).
  pugi::xml_node content;
  /// The content's computed style (its own cascade through its ancestors), set by the caller that draws it.
  ComputedStyle content_style;
  bool tile_in_box = true;      ///< patternUnits="objectBoundingBox" (the default)
  bool content_in_box = false;  ///< patternContentUnits="objectBoundingBox"
  double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
  /// patternTransform about the pattern's transform-origin (identity when none, or ignored with a warning).
  Affine transform = Affine::identity();
  std::optional<ViewBox> view_box;
  PreserveAspectRatio aspect;
};

/// Reads `pattern`: follows its href chain (only <pattern> elements, loops cut with a warning) and takes
/// each attribute from the first pattern of the chain that has it, with the warnings for bad values.
/// `content_style` is left for the caller.
[[nodiscard]] ResolvedPattern resolve_pattern(const pugi::xml_node& pattern, const IdIndex& ids,
                                              const ResolveContext& context, Diagnostics& diagnostics);

/// A pattern placed for one painted element.
struct PatternSetup {
  Rect tile;                 ///< in pattern space
  Affine pattern_transform;  ///< pattern space -> the element's user space
  Affine content_transform;  ///< content coordinates -> tile coordinates
};

/// `pattern` for an element with user-space bounding box `bbox`. nullopt means the paint is none: a tile
/// without positive width and height (SVG 1.1 13.3: zero disables the effect), an empty viewBox, no
/// content anywhere in the chain, or objectBoundingBox units on an element without area (7.11).
[[nodiscard]] std::optional<PatternSetup> place_pattern(const ResolvedPattern& pattern,
                                                        const std::optional<Rect>& bbox);

}  // namespace curvescan::svg::detail
