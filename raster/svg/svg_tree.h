// Reading an SVG document's bytes into its XML tree: the one way every SVG document is read, the one given
// to the renderer and each one an <image> or <feImage> draws. A legacy character encoding is converted to
// UTF-8 (xml_encoding.h), internal DTD entities are expanded (xml_entities.h), pugixml parses within the
// memory bound (xml_memory.h), what XML 1.0 does not allow around the root element is refused, the root
// must be <svg>, and the <style> sheets are read (style_elements.h).
#pragma once

#include <cstdint>
#include <pugixml.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "css/style_sheet.h"
#include "curvescan/status.h"
#include "source_positions.h"

namespace curvescan::svg::detail {

/// An SVG document's tree and what was learned while reading it. pugixml documents do not move: the
/// caller keeps this in place.
struct SvgTree {
  pugi::xml_document xml;
  std::int64_t memory_bytes = 0;  ///< pugixml's allocations while parsing, plus the converted text
  css::StyleSheets style_sheets;  ///< the <style> elements' rules (style_elements.h)
  std::vector<std::string>
      warnings;               ///< found while reading: entities, style sheets, processing instructions
  SourcePositions positions;  ///< line and column of the nodes, for warnings about an element
};

/// Reads `text` into `tree`, within `max_memory_bytes` for the tree and the converted text.
/// kLimitExceeded beyond that; kCorruptInput, with the line and column, for a document that is not
/// well-formed XML, an encoding iconv does not know or bytes invalid in it, and a root that is not <svg>.
[[nodiscard]] Status parse_svg_tree(std::string_view text, std::int64_t max_memory_bytes, SvgTree& tree);

}  // namespace curvescan::svg::detail
