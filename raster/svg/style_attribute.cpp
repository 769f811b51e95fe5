// The style attribute's declaration block (style_attribute.h): the CSS parser's declaration list.
#include "curvescan/svg/style_attribute.h"

#include "css/syntax.h"

namespace curvescan::svg {

std::vector<StyleDeclaration> parse_style_attribute(std::string_view text) {
  std::vector<StyleDeclaration> declarations;
  for (css::Declaration& declaration : css::parse_declaration_list(text)) {
    if (declaration.value.empty()) continue;  // invalid for every property (style_attribute.h)
    declarations.push_back({std::move(declaration.name), std::move(declaration.value)});
  }
  return declarations;
}

}  // namespace curvescan::svg
