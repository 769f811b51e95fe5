// Gathering the content of a <text> element (text_content.h).
#include "text_content.h"

#include <algorithm>
#include <array>
#include <string>

#include "css/syntax.h"
#include "curvescan/svg/number.h"
#include "curvescan/text/utf8.h"
#include "source_positions.h"
#include "xml_names.h"

namespace curvescan::svg::detail {
namespace {

// Attributes and properties of SVG text this renderer does not implement: noted, not errors. Each with the
// value that changes nothing (its initial value, so saying it needs no warning), or empty when any value
// is noted. (The unimplemented properties of text layout that CSS cascades -- SVG 2's wrapping and
// font-size-adjust -- are named by the cascade, cascade.cpp.)
struct UnsupportedProperty {
  std::string_view name;
  std::string_view neutral;
};
constexpr std::array<UnsupportedProperty, 1> kUnsupported{{{"glyph-orientation-horizontal", ""}}};

// The warning for character data decode_utf8 refused (`why`: "not valid UTF-8: byte ... at offset ...",
// the offset within that character data), led by the line and column of the element whose text it is
// (`element_node`), when positions are known.
// A document in another encoding that says so in its XML declaration was converted before parsing
// (xml_encoding.h), so the bytes are in an undeclared one.
std::string invalid_character_data(const Diagnostics& diagnostics, const pugi::xml_node& element_node,
                                   std::string_view element, const std::string& why) {
  // pugixml's offset of an element is that of its name, one byte after the '<' (as element_prefix reads it).
  const std::ptrdiff_t offset = element_node.offset_debug();
  const std::string where = diagnostics.positions != nullptr && offset > 0
                                ? diagnostics.positions->describe(offset - 1) + ": "
                                : "";
  return where + "the character data of a " + std::string(element) + " is " + why +
         "; skipped (save the document as UTF-8, or name its encoding in the XML declaration, e.g. <?xml "
         "version=\"1.0\" encoding=\"ISO-8859-1\"?>)";
}

}  // namespace

std::string_view local_name_of(const pugi::xml_node& node) {
  const std::string_view name = node.name();
  const std::size_t colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

void TextCollector::collect_element(const pugi::xml_node& node, std::size_t style, std::size_t parent,
                                    int depth, bool text_path) {
  note_unsupported(node);
  const std::size_t index = elements.size();
  elements.push_back({node, style, parent, fragments.size(), fragments.size(), text_path});
  for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
    if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) {
      Result<std::u32string> decoded = decode_utf8(child.value());
      if (!decoded) {
        diagnostics_.warnings.push_back(
            invalid_character_data(diagnostics_, node, "<text>", decoded.error().message));
        continue;
      }
      fragments.push_back(
          {std::move(decoded).value(), styles[style].text.white_space, styles[style].text.transform, {}});
      fragment_element.push_back(index);
      continue;
    }
    if (child.type() != pugi::node_element) continue;
    // An element of another namespace is not SVG text content, whatever its local name (<a> of
    // xmlns="http://example.org/x"): neither it nor its character data is drawn (SVG 2 6.5, unknown
    // elements are not rendered). No namespace at all is read as SVG, as everywhere in this renderer.
    if (const std::string_view ns = namespace_of(child); !ns.empty() && ns != kSvgNamespace) continue;
    const std::string_view name = local_name_of(child);
    // textPath is a child of <text> only (SVG 1.1 10.13; a textPath inside a textPath or a tspan is
    // not rendered, as in browsers).
    const bool is_text_path = name == "textPath" && depth == 0;
    // Conditional processing attributes (SVG 1.1 5.8.1): on a text content element they are evaluated as
    // anywhere else, and an element whose conditions fail is not rendered, nor is its text.
    if (!context_.conditions_hold(child)) continue;
    if (name == "altGlyph") {
      // SVG 1.1 10.14: when the alternate glyphs cannot be used (SVG fonts are not supported), the
      // altGlyph is rendered as a tspan.
      note("<altGlyph> glyph substitution is not supported; its text is drawn as in a <tspan>");
    }
    if (name == "tref") {
      collect_tref(child, style, index, depth);
    } else if (name == "tspan" || name == "a" || name == "altGlyph" || is_text_path) {
      if (depth >= context_.max_depth) {
        diagnostics_.warnings.push_back("<" + std::string(name) + "> nested more than " +
                                        std::to_string(context_.max_depth) + " deep; its text is skipped");
        continue;
      }
      ComputedStyle child_style = child_style_(child, styles[style]);
      if (!child_style.display) continue;
      styles.push_back(std::move(child_style));
      collect_element(child, styles.size() - 1, index, depth + 1, is_text_path);
    } else if (name == "textPath") {
      note("<textPath> outside <text> is not supported; its text is not drawn");
    }
  }
  elements[index].end_fragment = fragments.size();
}

// <tref> (SVG 1.1 10.6): the character data of the referenced element — all of it, inside descendants
// too, in document order — as if it were the tref's own, styled and positioned as a <tspan> would be.
// A reference to nothing renders nothing (with a warning).
void TextCollector::collect_tref(const pugi::xml_node& tref, std::size_t parent_style, std::size_t parent,
                                 int depth) {
  if (depth >= context_.max_depth) {
    diagnostics_.warnings.push_back("<tref> nested more than " + std::to_string(context_.max_depth) +
                                    " deep; its text is skipped");
    return;
  }
  pugi::xml_attribute href = tref.attribute("href");
  if (!href) href = tref.attribute("xlink:href");
  const std::string_view target_id = href.value();
  const pugi::xml_node target = target_id.starts_with('#') && context_.element_for_id
                                    ? context_.element_for_id(std::string(target_id.substr(1)))
                                    : pugi::xml_node();
  if (!target) {
    diagnostics_.warnings.push_back("<tref> refers to no element ('" + std::string(target_id) +
                                    "'); its text is not drawn");
    return;
  }
  ComputedStyle style = child_style_(tref, styles[parent_style]);
  if (!style.display) return;
  std::string data;
  // Pre-order without recursion (a deep target must not exhaust the stack): down, else across, else up.
  for (pugi::xml_node node = target.first_child(); node;) {
    if (node.type() == pugi::node_pcdata || node.type() == pugi::node_cdata) data += node.value();
    if (node.first_child()) {
      node = node.first_child();
      continue;
    }
    while (node && node != target && !node.next_sibling()) node = node.parent();
    node = node && node != target ? node.next_sibling() : pugi::xml_node();
  }
  Result<std::u32string> decoded = decode_utf8(data);
  if (!decoded) {
    diagnostics_.warnings.push_back(
        invalid_character_data(diagnostics_, target, "<tref>", decoded.error().message));
    return;
  }
  styles.push_back(std::move(style));
  const std::size_t index = elements.size();
  elements.push_back({tref, styles.size() - 1, parent, fragments.size(), fragments.size(), false});
  fragments.push_back(
      {std::move(decoded).value(), styles.back().text.white_space, styles.back().text.transform, {}});
  fragment_element.push_back(index);
  elements[index].end_fragment = fragments.size();
}

// An unsupported text feature is a warning, once per kind (no silent loss; docs/svg.md).
void TextCollector::note(const std::string& message) {
  if (noted_.insert(message).second) diagnostics_.warnings.push_back(message);
}

void TextCollector::note_unsupported(const pugi::xml_node& node) {
  const auto check = [&](std::string_view name, std::string_view value) {
    const auto known =
        std::find_if(kUnsupported.begin(), kUnsupported.end(),
                     [&](const UnsupportedProperty& property) { return property.name == name; });
    if (known != kUnsupported.end() && (known->neutral.empty() || trim_whitespace(value) != known->neutral)) {
      note("<text>: '" + std::string(name) + "' is not supported; ignored");
    }
  };
  for (const pugi::xml_attribute& attribute : node.attributes()) check(attribute.name(), attribute.value());
  if (const pugi::xml_attribute css = node.attribute("style")) {
    for (const css::Declaration& declaration : css::parse_declaration_list(css.value()))
      check(declaration.name, declaration.value);
  }
}

}  // namespace curvescan::svg::detail
