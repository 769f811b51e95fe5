// White space handling of SVG text (text_whitespace.h).
#include "text_whitespace.h"

#include <glib.h>

#include <cstddef>

namespace curvescan::svg::detail {
namespace {

// What one source character becomes before spaces are collapsed.
enum class Kind {
  kCharacter,         // kept as it is
  kPreservedSpace,    // a space or tab that is kept (xml:space="preserve", pre): not collapsible
  kCollapsibleSpace,  // a space or tab that collapses (drawn as U+0020 when kept)
  kCollapsibleBreak,  // a segment break of normal or nowrap: removed or turned into a space
  kForcedBreak,       // a segment break that is kept (pre, pre-wrap, pre-line, break-spaces)
  kRemoved,
};

struct Token {
  char32_t c;
  Kind kind;
  std::size_t fragment;
  bool legacy;  // xml:space="default": a space after any space is dropped (SVG 1.1 10.15)
};

bool is_segment_break(char32_t c) noexcept {
  return c == U'\n' || c == U'\r';
}
bool is_space_or_tab(char32_t c) noexcept {
  return c == U' ' || c == U'\t';
}

Token classify(char32_t c, WhiteSpace mode, std::size_t fragment) {
  const bool space = is_space_or_tab(c), segment_break = is_segment_break(c);
  switch (mode) {
    case WhiteSpace::kXmlDefault:
      if (segment_break) return {c, Kind::kRemoved, fragment, true};
      return {space ? U' ' : c, space ? Kind::kCollapsibleSpace : Kind::kCharacter, fragment, true};
    case WhiteSpace::kXmlPreserve:
      return {space || segment_break ? U' ' : c,
              space || segment_break ? Kind::kPreservedSpace : Kind::kCharacter, fragment, false};
    case WhiteSpace::kPreserve:
      if (segment_break) return {kForcedLineBreak, Kind::kForcedBreak, fragment, false};
      return {c, space ? Kind::kPreservedSpace : Kind::kCharacter, fragment, false};
    case WhiteSpace::kPreserveBreaks:
      if (segment_break) return {kForcedLineBreak, Kind::kForcedBreak, fragment, false};
      return {space ? U' ' : c, space ? Kind::kCollapsibleSpace : Kind::kCharacter, fragment, false};
    case WhiteSpace::kCollapse:
      if (segment_break) return {U' ', Kind::kCollapsibleBreak, fragment, false};
      return {space ? U' ' : c, space ? Kind::kCollapsibleSpace : Kind::kCharacter, fragment, false};
  }
  return {c, Kind::kCharacter, fragment, false};
}

bool is_break(Kind kind) noexcept {
  return kind == Kind::kCollapsibleBreak || kind == Kind::kForcedBreak;
}

// East_Asian_Width Fullwidth, Wide or Halfwidth (UAX #11), not Hangul: the characters between which CSS
// Text 3 section 4.1.3 removes a segment break. GLib's g_unichar_iswide is F and W; the halfwidth forms are
// the H block of U+FF61..U+FFDC and U+FFE8..U+FFEE (EastAsianWidth.txt); U+20A9 WON SIGN, the one other
// H character, is a currency sign that no text puts a line between.
bool removes_break_beside(char32_t c) noexcept {
  const gunichar u = static_cast<gunichar>(c);
  const bool wide = g_unichar_iswide(u) || (c >= 0xFF61 && c <= 0xFFDC) || (c >= 0xFFE8 && c <= 0xFFEE);
  return wide && g_unichar_get_script(u) != G_UNICODE_SCRIPT_HANGUL;
}

// CSS Text 3 section 4.1.3, the segment break transformation rules, for the break at `i` whose nearest
// kept neighbours are `before` and `after` (0: none, or a forced break).
Kind transformed_break(char32_t before, char32_t after) noexcept {
  if (before == U'\u200B' || after == U'\u200B') return Kind::kRemoved;
  if (before != 0 && after != 0 && removes_break_beside(before) && removes_break_beside(after))
    return Kind::kRemoved;
  return Kind::kCollapsibleSpace;
}

}  // namespace

void apply_white_space(std::vector<TextFragment>& fragments) {
  std::vector<Token> tokens;
  for (std::size_t f = 0; f < fragments.size(); ++f) {
    for (const char32_t c : fragments[f].text) {
      Token token = classify(c, fragments[f].white_space, f);
      if (token.kind != Kind::kRemoved) tokens.push_back(token);
    }
  }
  const std::size_t n = tokens.size();
  // Phase I, step 1: collapsible spaces and tabs just before or after a segment break are removed.
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_break(tokens[i].kind)) continue;
    for (std::size_t j = i; j-- > 0 && tokens[j].kind == Kind::kCollapsibleSpace;)
      tokens[j].kind = Kind::kRemoved;
    for (std::size_t j = i + 1; j < n && tokens[j].kind == Kind::kCollapsibleSpace; ++j)
      tokens[j].kind = Kind::kRemoved;
  }
  // Step 2: a collapsible segment break after another (nothing but removed spaces between) is removed;
  // the others become a space or nothing by their neighbours.
  std::size_t previous = n;  // the last kept token
  for (std::size_t i = 0; i < n; ++i) {
    if (tokens[i].kind == Kind::kRemoved) continue;
    if (tokens[i].kind == Kind::kCollapsibleBreak && previous < n &&
        tokens[previous].kind == Kind::kCollapsibleBreak) {
      tokens[i].kind = Kind::kRemoved;
      continue;
    }
    previous = i;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (tokens[i].kind != Kind::kCollapsibleBreak) continue;
    char32_t before = 0, after = 0;
    for (std::size_t j = i; j-- > 0;) {
      if (tokens[j].kind == Kind::kRemoved) continue;
      if (!is_break(tokens[j].kind)) before = tokens[j].c;
      break;
    }
    for (std::size_t j = i + 1; j < n; ++j) {
      if (tokens[j].kind == Kind::kRemoved) continue;
      if (!is_break(tokens[j].kind)) after = tokens[j].c;
      break;
    }
    tokens[i].kind = transformed_break(before, after);
    tokens[i].c = U' ';
  }
  // Steps 3-4 and phase II: a collapsible space after another collapsible space (after any space, under
  // xml:space="default") or at the start of a line is removed; then those at the end of each line.
  std::vector<Token> kept;
  kept.reserve(n);
  const auto trim_line_end = [&kept] {
    while (!kept.empty() && kept.back().kind == Kind::kCollapsibleSpace) kept.pop_back();
  };
  for (const Token& token : tokens) {
    if (token.kind == Kind::kRemoved) continue;
    if (token.kind == Kind::kCollapsibleSpace) {
      const bool line_start = kept.empty() || kept.back().kind == Kind::kForcedBreak;
      const bool after_space = !line_start && (kept.back().kind == Kind::kCollapsibleSpace ||
                                               (token.legacy && kept.back().c == U' '));
      if (line_start || after_space) continue;
    }
    if (token.kind == Kind::kForcedBreak) trim_line_end();
    kept.push_back(token);
  }
  trim_line_end();
  for (TextFragment& fragment : fragments) fragment.text.clear();
  for (const Token& token : kept) fragments[token.fragment].text.push_back(token.c);
}

}  // namespace curvescan::svg::detail
