// For tests of the render tree: a render that shows each Group node (render_group.h) as the drawing walk
// makes it, so that a test reads what was resolved (transform, opacity, the clip path, mask and filter
// objects, the box) instead of inferring it from pixels.
#pragma once

#include <functional>
#include <pugixml.hpp>
#include <string_view>

#include "curvescan/svg/document.h"
#include "render_group.h"

namespace curvescan::svg::detail {

/// Called with each Group node as it is made, and the element it is made from. The node and the objects
/// it points to live only during the call.
using GroupNodeProbe = std::function<void(const pugi::xml_node& element, const GroupNode& group)>;

/// Renders the document `xml` as render_svg_document does, calling `probe` for every Group node made.
[[nodiscard]] Result<RenderedDocument> render_probing_groups(std::string_view xml,
                                                             const RenderOptions& options,
                                                             const GroupNodeProbe& probe);

}  // namespace curvescan::svg::detail
