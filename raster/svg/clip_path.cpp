// <clipPath> resolution (clip_path.h).
#include "clip_path.h"

#include <string>
#include <string_view>

#include "xml_names.h"

namespace curvescan::svg::detail {
namespace {

bool is_basic_shape(std::string_view name) {
  for (std::string_view known : {"path", "rect", "circle", "ellipse", "line", "polyline", "polygon"}) {
    if (name == known) return true;
  }
  return false;
}

}  // namespace

ResolvedClipPath resolve_clip_path(const pugi::xml_node& clip, const IdIndex& ids,
                                   const ClipPathReader& reader) {
  ResolvedClipPath resolved;
  resolved.element = clip;
  resolved.style = reader.referenced_style(clip);
  resolved.transform = reader.transform(clip, resolved.style.font_size);
  resolved.bounding_box_units =
      std::string_view(clip.attribute("clipPathUnits").value()) == "objectBoundingBox";
  for (pugi::xml_node child = clip.first_child(); child; child = child.next_sibling()) {
    if (child.type() != pugi::node_element) continue;
    pugi::xml_node geometry = child;  // the shape or <text> whose outline counts (a <use>'s target)
    ComputedStyle style = reader.style(child, resolved.style);  // the <use>'s in between
    ClipPathChild entry;
    entry.transform = reader.transform(child, style.font_size);
    if (local_name(child) == "use") {
      pugi::xml_attribute href = child.attribute("href");
      if (!href) href = child.attribute("xlink:href");
      const std::string_view reference = href.value();
      const auto target = reference.size() > 1 ? ids.find(std::string(reference.substr(1))) : ids.end();
      if (target == ids.end()) continue;
      geometry = target->second;
      const Point offset = reader.use_offset(child, style);
      entry.transform = entry.transform * Affine::translate(offset.x, offset.y) *
                        reader.transform(geometry, style.font_size);
      const std::string use_clip = style.clip_path_id;
      style = reader.style(geometry, style);
      if (style.clip_path_id.empty()) style.clip_path_id = use_clip;
    }
    const std::string_view name = local_name(geometry);
    // Groups, images, <switch>, <use> of a group or <symbol>: not valid in a clipPath, ignored (14.3.5).
    if (!reader.is_curve(geometry) && !is_basic_shape(name) && name != "text") continue;
    if (!style.display || !style.visible) continue;
    entry.outline = reader.outline(geometry, style, resolved.style);
    entry.clip_path_id = style.clip_path_id;
    resolved.children.push_back(std::move(entry));
  }
  return resolved;
}

}  // namespace curvescan::svg::detail
