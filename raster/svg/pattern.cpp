// <pattern> tile resolution (pattern.h).
#include "pattern.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "curvescan/svg/length.h"
#include "curvescan/svg/transform.h"
#include "curvescan/svg/viewport.h"
#include "href_chain.h"
#include "transform_origin.h"
#include "xml_names.h"

namespace curvescan::svg::detail {
namespace {

bool has_element_child(const pugi::xml_node& node) {
  for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
    if (child.type() == pugi::node_element) return true;
  }
  return false;
}

}  // namespace

ResolvedPattern resolve_pattern(const pugi::xml_node& pattern, const IdIndex& ids,
                                const ResolveContext& context, Diagnostics& diagnostics) {
  const std::vector<pugi::xml_node> chain =
      href_chain(pattern, ids, {"pattern"}, kMaxPatternChain, "pattern", diagnostics);
  ResolvedPattern resolved;
  const auto content = std::find_if(chain.begin(), chain.end(), has_element_child);
  if (content == chain.end()) return resolved;
  resolved.content = *content;

  resolved.tile_in_box = std::string_view(chain_attribute(chain, "patternUnits").value()) != "userSpaceOnUse";
  resolved.content_in_box =
      std::string_view(chain_attribute(chain, "patternContentUnits").value()) == "objectBoundingBox";
  if (const pugi::xml_attribute attribute = chain_attribute(chain, "viewBox")) {
    const Result<ViewBox> parsed = parse_view_box(attribute.value());
    if (parsed) {
      resolved.view_box = *parsed;
    } else {
      diagnostics.warnings.push_back("<pattern> " + parsed.error().message);
    }
  }

  // x, y, width, height: fractions (or percentages) of the box, or user lengths (percentages of the
  // viewport), default 0.
  const auto value = [&](const char* name, LengthAxis axis) {
    const pugi::xml_attribute attribute = chain_attribute(chain, name);
    if (!attribute) return 0.0;
    const Result<Length> length = parse_length(attribute.value());
    if (!length) {
      diagnostics.warnings.push_back("<pattern> " + std::string(name) + ": " + length.error().message);
      return 0.0;
    }
    if (resolved.tile_in_box)
      return length->unit == LengthUnit::kPercent ? length->value / 100.0 : length->value;
    return length_to_pixels(*length, LengthContext{axis.dpi, 16.0, axis.percent_reference});
  };
  resolved.x = value("x", context.horizontal());
  resolved.y = value("y", context.vertical());
  resolved.width = value("width", context.horizontal());
  resolved.height = value("height", context.vertical());

  if (const pugi::xml_attribute attribute = chain_attribute(chain, "patternTransform")) {
    const Result<Affine> parsed = parse_transform(attribute.value());
    // A singular transform would make the paint vanish; like an unparsable one it is ignored, as
    // resvg and browsers ignore it.
    if (parsed && parsed->inverse()) {
      resolved.transform = paint_server_transform(pattern, *parsed, context, diagnostics);
    } else {
      diagnostics.warnings.push_back(
          "<pattern> ignoring patternTransform '" + std::string(attribute.value()) + "'" +
          (parsed ? std::string(" (not invertible)") : ": " + parsed.error().message));
    }
  }
  if (const pugi::xml_attribute attribute = chain_attribute(chain, "preserveAspectRatio")) {
    const Result<PreserveAspectRatio> parsed = parse_preserve_aspect_ratio(attribute.value());
    if (parsed) resolved.aspect = *parsed;
  }
  return resolved;
}

std::optional<PatternSetup> place_pattern(const ResolvedPattern& pattern, const std::optional<Rect>& bbox) {
  if (!pattern.content) return std::nullopt;
  const bool has_box = bbox && bbox->width() > 0.0 && bbox->height() > 0.0;
  if ((pattern.tile_in_box || (pattern.content_in_box && !pattern.view_box)) && !has_box) return std::nullopt;
  double x = pattern.x, y = pattern.y, w = pattern.width, h = pattern.height;
  if (pattern.tile_in_box) {
    x = bbox->x0 + x * bbox->width();
    y = bbox->y0 + y * bbox->height();
    w *= bbox->width();
    h *= bbox->height();
  }
  if (!(w > 0.0) || !(h > 0.0) || !std::isfinite(x + y + w + h)) return std::nullopt;
  PatternSetup setup;
  setup.tile = Rect{x, y, x + w, y + h};
  setup.pattern_transform = pattern.transform;
  if (const std::optional<ViewBox>& view_box = pattern.view_box) {
    if (!(view_box->width > 0.0) || !(view_box->height > 0.0)) return std::nullopt;
    setup.content_transform = view_box_transform(*view_box, pattern.aspect, 0.0, 0.0, w, h);
  } else if (pattern.content_in_box) {
    setup.content_transform = Affine::scale(bbox->width(), bbox->height());
  } else {
    setup.content_transform = Affine::identity();
  }
  return setup;
}

}  // namespace curvescan::svg::detail
