// The document's <style> elements (style_elements.h).
#include "style_elements.h"

#include "css/syntax.h"
#include "curvescan/svg/number.h"
#include "xml_names.h"

namespace curvescan::svg::detail {
namespace {

// SVG 2 6.5: the type attribute is a media type; only "text/css" (or none) is a CSS sheet. A media type
// may carry parameters ("text/css; charset=utf-8").
bool is_css_type(std::string_view type) {
  type = type.substr(0, type.find(';'));
  type = trim_whitespace(type);
  return type.empty() || css::ascii_lower(type) == "text/css";
}

}  // namespace

void add_style_elements(const pugi::xml_node& root, css::StyleSheets& sheets,
                        std::vector<std::string>& warnings) {
  // Depth-first in document order with an explicit stack: nesting depth is the input's to choose.
  std::vector<pugi::xml_node> stack{root};
  while (!stack.empty()) {
    const pugi::xml_node node = stack.back();
    stack.pop_back();
    if (local_name(node) == "style") {
      const std::string_view ns = namespace_of(node);
      if (ns.empty() || ns == kSvgNamespace) {
        const std::string_view type = node.attribute("type").value();
        if (!is_css_type(type)) {
          warnings.push_back("<style type=\"" + std::string(type) + "\"> is not CSS; skipped");
          continue;
        }
        std::string text;
        for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
          if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) text += child.value();
        }
        sheets.add(text, "<style>", warnings, node.attribute("media").value());
        continue;
      }
    }
    // Children pushed last-first so that they are visited first-first.
    for (pugi::xml_node child = node.last_child(); child; child = child.previous_sibling()) {
      if (child.type() == pugi::node_element) stack.push_back(child);
    }
  }
}

}  // namespace curvescan::svg::detail
