// White space handling of SVG text (text_whitespace.h).
#include "text_whitespace.h"

namespace curvescan::svg::detail {

void apply_xml_space(std::vector<TextFragment>& fragments) {
  // Whether the last character kept so far (in any fragment) is a space, and whether any was kept:
  // a default-mode space after a space or at the very start is dropped.
  bool kept_any = false;
  bool last_is_space = false;
  for (TextFragment& fragment : fragments) {
    std::u32string out;
    out.reserve(fragment.text.size());
    for (char32_t c : fragment.text) {
      const bool newline = c == U'\n' || c == U'\r';
      if (fragment.preserve) {
        out.push_back(newline || c == U'\t' ? U' ' : c);
      } else if (newline) {
        continue;
      } else if (c == U' ' || c == U'\t') {
        if (!kept_any || last_is_space) continue;
        out.push_back(U' ');
      } else {
        out.push_back(c);
      }
      kept_any = true;
      last_is_space = out.back() == U' ';
    }
    fragment.text = std::move(out);
  }
  // Trailing spaces of the element: from the end, through default-mode fragments only (a preserved
  // space is kept, and so is everything before it).
  for (auto fragment = fragments.rbegin(); fragment != fragments.rend(); ++fragment) {
    if (fragment->preserve) break;
    while (!fragment->text.empty() && fragment->text.back() == U' ') fragment->text.pop_back();
    if (!fragment->text.empty()) break;
  }
}

}  // namespace curvescan::svg::detail
