// Reading an SVG-in-OpenType glyph document (the OpenType "SVG " table) into an SVG tree: the one way both
// SVG text (document.cpp) and the text command (Document::parse_glyph_document) read a glyph's document.
#pragma once

#include <cstdint>
#include <string_view>

#include "curvescan/status.h"
#include "svg_tree.h"

namespace curvescan::svg::detail {

/// Reads the glyph document `stored`, as the font stores it — plain, or gzip-compressed as the OpenType
/// specification ("SVG" table, "SVG Document List") allows — into `tree`, as every SVG document is read
/// (svg_tree.h). The inflated text and the tree each stay within `max_memory_bytes`. kLimitExceeded
/// beyond that; kCorruptInput for a broken gzip stream or a document that is not well-formed SVG, with a
/// message that completes "an SVG glyph document ..." ("cannot be inflated (...)", "is not a well-formed
/// SVG document (...)"), so that every caller words it the same.
[[nodiscard]] Status parse_svg_glyph_tree(std::string_view stored, std::int64_t max_memory_bytes,
                                          SvgTree& tree);

}  // namespace curvescan::svg::detail
