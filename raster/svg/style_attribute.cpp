// The style attribute's declaration block (style_attribute.h).
#include "curvescan/svg/style_attribute.h"

#include <algorithm>

#include "curvescan/svg/number.h"

namespace curvescan::svg {
namespace {

// `text` with every /* ... */ comment replaced by a space (an unterminated comment runs to the end).
std::string without_comments(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  while (!text.empty()) {
    const std::size_t open = text.find("/*");
    if (open == std::string_view::npos) {
      out += text;
      break;
    }
    out += text.substr(0, open);
    out += ' ';
    const std::size_t close = text.find("*/", open + 2);
    if (close == std::string_view::npos) break;
    text.remove_prefix(close + 2);
  }
  return out;
}

}  // namespace

std::vector<StyleDeclaration> parse_style_attribute(std::string_view text) {
  const std::string clean = without_comments(text);
  std::vector<StyleDeclaration> declarations;
  std::string_view rest(clean);
  while (!rest.empty()) {
    const std::size_t end = rest.find(';');
    const std::string_view item = rest.substr(0, end);
    rest.remove_prefix(end == std::string_view::npos ? rest.size() : end + 1);
    const std::size_t colon = item.find(':');
    if (colon == std::string_view::npos) continue;
    std::string name(trim_whitespace(item.substr(0, colon)));
    std::string_view value = trim_whitespace(item.substr(colon + 1));
    if (const std::size_t bang = value.rfind('!'); bang != std::string_view::npos) {
      std::string flag(trim_whitespace(value.substr(bang + 1)));
      std::transform(flag.begin(), flag.end(), flag.begin(),
                     [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; });
      if (flag == "important") value = trim_whitespace(value.substr(0, bang));
    }
    std::transform(name.begin(), name.end(), name.begin(),
                   [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; });
    if (name.empty() || value.empty()) continue;
    declarations.push_back({std::move(name), std::string(value)});
  }
  return declarations;
}

}  // namespace curvescan::svg
