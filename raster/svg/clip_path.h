// <clipPath> (SVG 1.1 section 14.3.5, CSS Masking 1 section 6.1) resolved into an object: its units, its
// transform, its own style (and through it its own clip-path) and the children that give geometry, each
// with its outline (a shape's, or a <text>'s glyphs), the rule it is filled with and the map into the
// clipPath's user space. Resolved once per clipPath and viewport in a render (resolved_references.h), the
// outlines with it: a clip path used by many elements builds its children's geometry once, and the
// drawing walk applies it without reading the children's elements.
//
// Children. A shape, a <text>, or a <use> that refers to one of those directly (its target's style
// cascades from the <use>'s, and the <use>'s clip-path applies when the target has none); groups, images,
// <switch> and a <use> of a group or <symbol> are not valid there and are ignored (14.3.5), and so are
// children that display: none or visibility hides.
#pragma once

#include <functional>
#include <optional>
#include <pugixml.hpp>
#include <string>
#include <vector>

#include "computed_style.h"
#include "curvescan/curves/affine.h"
#include "curvescan/curves/point.h"
#include "curvescan/raster/path.h"
#include "paint_server.h"

namespace curvescan::svg::detail {

/// The outline of one clipPath child in its own user space, and the rule it is filled with: a shape's
/// clip-rule; glyph outlines are always nonzero (font.h).
struct ClipOutline {
  Path path;
  FillRule rule = FillRule::kNonZero;
};

/// One child of a <clipPath> that gives geometry.
struct ClipPathChild {
  std::optional<ClipOutline>
      outline;               ///< nullopt: no geometry (a shape without its data, text with no glyph)
  std::string clip_path_id;  ///< its own clip-path (the <use>'s when its target has none)
  Affine transform;          ///< its user space -> the clipPath's
};

struct ResolvedClipPath {
  pugi::xml_node element;           ///< the <clipPath> (its identity cuts reference loops)
  ComputedStyle style;              ///< its computed style; style.clip_path_id is its own clip-path
  bool bounding_box_units = false;  ///< clipPathUnits="objectBoundingBox"
  Affine transform;                 ///< its transform attribute or property
  std::vector<ClipPathChild> children;
};

/// What reading a clipPath needs from the document's cascade and geometry, supplied by the drawing walk.
struct ClipPathReader {
  /// The clipPath's own style, from its ancestors (SVG 1.1 6.7).
  std::function<ComputedStyle(const pugi::xml_node&)> referenced_style;
  /// The style of an element under a parent's style.
  std::function<ComputedStyle(const pugi::xml_node&, const ComputedStyle&)> style;
  /// An element's transform (about its transform-origin) for its font size.
  std::function<Affine(const pugi::xml_node&, double)> transform;
  /// A <use>'s (x, y) for its style.
  std::function<Point(const pugi::xml_node&, const ComputedStyle&)> use_offset;
  /// Whether an element is one of curvescan's curve elements (document_index.h).
  std::function<bool(const pugi::xml_node&)> is_curve;
  /// The outline of a child that gives geometry (a shape, a curve element or a <text>; a <use>'s target),
  /// under its style and the clipPath's; nullopt when it has none.
  std::function<std::optional<ClipOutline>(const pugi::xml_node& geometry, const ComputedStyle& style,
                                           const ComputedStyle& clip_style)>
      outline;
};

/// Reads <clipPath> `clip`.
[[nodiscard]] ResolvedClipPath resolve_clip_path(const pugi::xml_node& clip, const IdIndex& ids,
                                                 const ClipPathReader& reader);

}  // namespace curvescan::svg::detail
