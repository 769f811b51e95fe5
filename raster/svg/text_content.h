// The content of one SVG <text> element, gathered for layout (SVG 2 11.8.3 step 1): the character data
// of the <text> and of its <tspan>, <a>, <altGlyph> and <textPath> descendants and the text <tref>s
// reference, in document order, each fragment with the computed style of the element holding it
// (display:none elements contribute nothing), and every element with the range of fragments it spans.
// Text features this renderer does not implement are noted once each (text_element.h).
#pragma once

#include <cstddef>
#include <pugixml.hpp>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "computed_style.h"
#include "text_element.h"
#include "text_whitespace.h"

namespace curvescan::svg::detail {

/// The element name without its namespace prefix ("svg:tspan" -> "tspan").
[[nodiscard]] std::string_view local_name_of(const pugi::xml_node& node);

inline constexpr std::size_t kNoElement = static_cast<std::size_t>(-1);

// An element of the text's content and the characters its character data spans.
struct ElementRange {
  pugi::xml_node node;
  std::size_t style = 0;
  std::size_t parent = kNoElement;
  std::size_t first_fragment = 0;
  std::size_t end_fragment = 0;
  bool text_path = false;
};

/// Walks a <text> element's content (collect_element on the <text> with its style at index 0).
class TextCollector {
 public:
  TextCollector(const ChildStyle& child_style, const TextContext& context, Diagnostics& diagnostics)
      : child_style_(child_style), context_(context), diagnostics_(diagnostics) {}

  std::vector<ComputedStyle> styles;
  std::vector<TextFragment> fragments;
  std::vector<std::size_t> fragment_element;
  std::vector<ElementRange> elements;  // pre-order: descendants after their ancestors

  void collect_element(const pugi::xml_node& node, std::size_t style, std::size_t parent, int depth,
                       bool text_path);

  // <tref> (SVG 1.1 10.6): the character data of the referenced element — all of it, inside descendants
  // too, in document order — as if it were the tref's own, styled and positioned as a <tspan> would be.
  // A reference to nothing renders nothing (with a warning).
  void collect_tref(const pugi::xml_node& tref, std::size_t parent_style, std::size_t parent, int depth);

  // An unsupported text feature is a warning, once per kind (no silent loss; docs/svg.md).
  void note(const std::string& message);

 private:
  void note_unsupported(const pugi::xml_node& node);

  const ChildStyle& child_style_;
  const TextContext& context_;
  Diagnostics& diagnostics_;
  std::set<std::string> noted_;
};

}  // namespace curvescan::svg::detail
