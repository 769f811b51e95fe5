// The background of the root <svg> (CSS Backgrounds 3, 2.11.2 "The Canvas Background and the Root
// Element"): the root element's `background-color` paints the canvas under the whole drawing, as
// browsers show a stand-alone SVG document with `<svg style="background-color: ...">`. SVG 2 makes no
// presentation attribute of it (6.6), so it comes from the style attribute or a style sheet only, and on
// any other element it paints nothing (SVG elements have no CSS boxes).
#pragma once

#include <optional>
#include <pugixml.hpp>

#include "css/style_sheet.h"
#include "curvescan/raster/paint.h"

namespace curvescan::svg::detail {

/// The canvas colour that `root`'s declared `background-color` gives, or nullopt when it declares none,
/// or a transparent one. `current_color` is the root's computed `color`, for `currentColor`. A value that
/// is not a colour is skipped as CSS drops invalid declarations (the next declaration down wins);
/// `inherit` and `initial` are transparent (the root has no parent, and the initial value is transparent).
[[nodiscard]] std::optional<Color> canvas_background_color(const pugi::xml_node& root,
                                                           const css::StyleSheets* sheets,
                                                           const Color& current_color);

}  // namespace curvescan::svg::detail
