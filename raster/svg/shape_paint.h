// A fill or stroke as the render tree holds it (docs/svg.md, "How a document is drawn"): the paint of
// a Path node (render_path.h) with everything the style and the references decide already settled --
// `currentColor`, `context-fill` and `context-stroke` replaced, a `url()` followed to its gradient or
// pattern (or to the fallback colour, SVG 2 13.3), objectBoundingBox units placed on the shape's box,
// fill-opacity or stroke-opacity and any group opacity folded in.
#pragma once

#include <optional>
#include <string>
#include <variant>

#include "curvescan/raster/paint.h"
#include "pattern.h"

namespace curvescan::svg::detail {

/// A pattern fill or stroke placed for its shape. It stays a pattern until drawn: its tile is drawn at
/// the resolution of the device the shape is drawn to, which only the drawing knows.
struct PatternPaint {
  const ResolvedPattern* pattern = nullptr;  ///< read once per render (resolved_references.h); not null
  PatternSetup setup;                        ///< placed on the shape's box, in the shape's user space
  double opacity = 1.0;                      ///< multiplies the tile's pixels
  std::string shown;                         ///< how a warning names the <pattern> (` id="p"` or empty)
  /// What is painted when the tile paints nothing (drawn inside itself, too deep, under a pixel): the
  /// paint's fallback colour, or none.
  std::optional<Paint> fallback;
};

/// A colour or gradient, ready for the core (paint.h), or a pattern.
using ShapePaint = std::variant<Paint, PatternPaint>;

}  // namespace curvescan::svg::detail
