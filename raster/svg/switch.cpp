// Conditional processing (switch.h).
#include "switch.h"

#include <algorithm>
#include <cctype>
#include <string_view>

#include "css/syntax.h"
#include "curvescan/svg/number.h"

namespace curvescan::svg::detail {
namespace {

// One tag of systemLanguage against the user's languages.
bool language_matches(std::string_view tag, const std::vector<std::string>& languages) {
  for (const std::string& language : languages) {
    if (css::ascii_equal_ignoring_case(tag, language)) return true;
    if (tag.size() > language.size() && tag[language.size()] == '-' &&
        css::ascii_equal_ignoring_case(tag.substr(0, language.size()), language))
      return true;
  }
  return false;
}

}  // namespace

bool conditions_hold(const pugi::xml_node& element, const std::vector<std::string>& languages) {
  if (element.attribute("requiredExtensions")) return false;
  if (const pugi::xml_attribute system_language = element.attribute("systemLanguage")) {
    std::string_view rest = system_language.value();
    while (true) {
      const std::size_t comma = rest.find(',');
      const std::string_view tag = trim_whitespace(rest.substr(0, comma));
      if (!tag.empty() && language_matches(tag, languages)) return true;
      if (comma == std::string_view::npos) return false;
      rest.remove_prefix(comma + 1);
    }
  }
  return true;
}

}  // namespace curvescan::svg::detail
