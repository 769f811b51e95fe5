// Reading an SVG document's bytes into its tree (svg_tree.h).
#include "svg_tree.h"

#include <algorithm>

#include "repeated_attribute.h"
#include "style_elements.h"
#include "xml_encoding.h"
#include "xml_entities.h"
#include "xml_memory.h"
#include "xml_names.h"

namespace curvescan::svg::detail {
namespace {

// Line and column (1-based) of byte `offset` in `text`, for XML error messages.
std::string line_and_column(std::string_view text, std::ptrdiff_t offset) {
  const std::size_t end =
      std::min(text.size(), static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, offset)));
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// Processing instructions mean nothing to SVG except <?xml-stylesheet?> (Associating Style Sheets with XML
// documents 1.0), which links an external style sheet from the prolog: curvescan reads no external files
// for a document, so it is named once and ignored. The parser keeps no processing instructions (the
// renderer, text layout in particular, only ever meets elements and character data), so the prolog's bytes
// before the root element are searched instead; `root_offset` is where the root element starts.
void warn_about_style_sheet_links(std::string_view xml, std::ptrdiff_t root_offset,
                                  std::vector<std::string>& warnings) {
  if (root_offset < 0) return;
  const std::string_view prolog = xml.substr(0, std::min(static_cast<std::size_t>(root_offset), xml.size()));
  // Comments are skipped: a commented-out <?xml-stylesheet?> links nothing.
  for (std::size_t at = prolog.find('<'); at != std::string_view::npos; at = prolog.find('<', at + 1)) {
    const std::string_view rest = prolog.substr(at);
    if (rest.starts_with("<!--")) {
      const std::size_t end = rest.find("-->", 4);
      if (end == std::string_view::npos) return;
      at += end + 2;
    } else if (rest.starts_with("<?xml-stylesheet")) {
      warnings.push_back("<?xml-stylesheet?> is not supported (external style sheets are not read); ignored");
      return;
    }
  }
}

}  // namespace

Status parse_svg_tree(std::string_view original_xml, std::int64_t max_memory_bytes, SvgTree& tree) {
  pugi::xml_document& document = tree.xml;
  const auto tree_too_large = [&] {
    return Error{ErrorKind::kLimitExceeded, "the document's XML tree needs more than the memory limit of " +
                                                std::to_string(max_memory_bytes >> 20) +
                                                " MiB (raise --max-memory)"};
  };
  // A legacy encoding (windows-1251, ...) is converted to UTF-8 first (xml_encoding.h).
  Result<std::optional<std::string>> transcoded = transcode_to_utf8(original_xml, max_memory_bytes);
  if (!transcoded) return transcoded.error();
  const std::string_view utf8_xml = *transcoded ? std::string_view(**transcoded) : original_xml;
  const std::int64_t transcoded_bytes =
      *transcoded ? static_cast<std::int64_t>((*transcoded)->capacity()) : 0;
  // Internal DTD entities (xml_entities.h) are expanded before pugixml sees the text, which it would
  // otherwise leave as "&name;". Error positions then refer to the expanded text.
  Result<std::optional<std::string>> expanded = expand_internal_entities(utf8_xml, tree.warnings);
  if (!expanded) return expanded.error();
  const std::string_view xml = *expanded ? std::string_view(**expanded) : utf8_xml;
  const std::int64_t expanded_bytes =
      (*expanded ? static_cast<std::int64_t>((*expanded)->capacity()) : 0) + transcoded_bytes;
  if (expanded_bytes > max_memory_bytes) return tree_too_large();
  // XML 1.0 section 2.2 (Char) has no NUL character. pugixml stops reading at one in some places, so a
  // NUL after the root would hide what follows it (binary garbage, a second root) from the checks below,
  // and one inside a tag gives a misleading message ("Start-end tags mismatch"): name it instead. UTF-16
  // and UTF-32 text, which pugixml converts itself, is full of zero bytes: its byte order mark or the
  // zero bytes around its first "<" (XML 1.0 appendix F.1) tell it apart, and it is left to pugixml.
  const bool wide_encoding =
      xml.size() >= 2 &&
      (xml[0] == '\0' || xml[1] == '\0' || xml.substr(0, 2) == "\xFE\xFF" || xml.substr(0, 2) == "\xFF\xFE");
  if (const std::size_t nul = xml.find('\0'); !wide_encoding && nul != std::string_view::npos) {
    return Error{ErrorKind::kCorruptInput,
                 "the document is not well-formed XML: a NUL byte at " +
                     line_and_column(xml, static_cast<std::ptrdiff_t>(nul)) +
                     " (XML allows none; is the file binary, or cut short and padded?)"};
  }
  XmlMemoryCount count(max_memory_bytes - expanded_bytes);
  // parse_default without parse_escapes would leave &amp; in values; keep the default (escapes, EOL
  // normalization) and do not keep comments or processing instructions. Whitespace-only text is kept:
  // in <text>, "<tspan>a</tspan> <tspan>b</tspan>" has a space between the words (SVG 1.1 10.15).
  // parse_fragment keeps text outside the root element as nodes (without it pugixml drops such text
  // silently), so that the check below can refuse it.
  const pugi::xml_parse_result parsed = document.load_buffer(
      xml.data(), xml.size(), pugi::parse_default | pugi::parse_ws_pcdata | pugi::parse_fragment);
  if (count.exceeded()) return tree_too_large();
  tree.memory_bytes = count.bytes() + expanded_bytes;
  if (!parsed) {
    return Error{ErrorKind::kCorruptInput,
                 "the document is not well-formed XML: " + std::string(parsed.description()) + " at " +
                     line_and_column(xml, parsed.offset)};
  }
  // As a fragment, pugixml accepts no root, several top-level elements and text outside the root. XML 1.0
  // section 2.1 (document ::= prolog element Misc*) allows one root element and around it only comments,
  // processing instructions, the doctype and white space, so anything else is refused here.
  bool seen_root = false;
  for (const pugi::xml_node node : document.children()) {
    if (node.type() == pugi::node_element) {
      if (seen_root) {
        return Error{ErrorKind::kCorruptInput,
                     "the document is not well-formed XML: a second root element <" +
                         std::string(node.name()) + "> at " + line_and_column(xml, node.offset_debug()) +
                         " (a document has one root element)"};
      }
      seen_root = true;
    } else if (node.type() == pugi::node_pcdata || node.type() == pugi::node_cdata) {
      const std::string_view value = node.value();
      if (value.find_first_not_of(" \t\r\n") != std::string_view::npos) {
        return Error{ErrorKind::kCorruptInput, "the document is not well-formed XML: text " +
                                                   std::string(seen_root ? "after" : "before") +
                                                   " the root element at " +
                                                   line_and_column(xml, node.offset_debug())};
      }
    }
  }
  if (!seen_root) {
    return Error{ErrorKind::kCorruptInput, "the document is not well-formed XML: it has no root element"};
  }
  const pugi::xml_node root = document.document_element();
  warn_about_style_sheet_links(xml, root.offset_debug(), tree.warnings);
  if (local_name(root) != "svg") {
    return Error{ErrorKind::kCorruptInput,
                 "the root element is <" + std::string(root.name()) + ">, not <svg>"};
  }
  if (const RepeatedAttribute repeated = find_repeated_attribute(root); repeated.element) {
    return Error{ErrorKind::kCorruptInput, "the document is not well-formed XML: the attribute '" +
                                               std::string(repeated.attribute.name()) +
                                               "' appears twice in <" + std::string(repeated.element.name()) +
                                               "> at " +
                                               line_and_column(xml, repeated.element.offset_debug())};
  }
  add_style_elements(root, tree.style_sheets, tree.warnings);
  tree.positions = SourcePositions(xml);
  tree.memory_bytes += static_cast<std::int64_t>(tree.positions.memory_bytes());
  return Status::ok();
}

}  // namespace curvescan::svg::detail
