// For tests of the render tree: a render that shows each shape's Path node (render_path.h) as the drawing
// walk makes it, so that a test reads what was resolved (the paints, the placed markers) instead of
// inferring it from pixels.
#pragma once

#include <functional>
#include <pugixml.hpp>
#include <string_view>

#include "curvescan/svg/document.h"
#include "render_path.h"

namespace curvescan::svg::detail {

/// Called with the Path node of each basic shape, <path> and curve element as it is made, and the element
/// it is made from. The node and the objects it points to live only during the call.
using PathNodeProbe = std::function<void(const pugi::xml_node& element, const PathNode& path)>;

/// Renders the document `xml` as render_svg_document does, calling `probe` for every shape's Path node.
[[nodiscard]] Result<RenderedDocument> render_probing_paths(std::string_view xml,
                                                            const RenderOptions& options,
                                                            const PathNodeProbe& probe);

}  // namespace curvescan::svg::detail
