// text-transform of SVG text (text_transform.h).
#include "text_transform.h"

#include <glib.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace curvescan::svg::detail {
namespace {

// CSS Text 3 appendix G, "Small Kana Mappings": each small kana and its full-size form.
constexpr std::array<std::pair<char32_t, char32_t>, 58> kSmallKana{{
    {0x3041, 0x3042},  {0x3043, 0x3044},  {0x3045, 0x3046},  {0x3047, 0x3048},  {0x3049, 0x304A},
    {0x3063, 0x3064},  {0x3083, 0x3084},  {0x3085, 0x3086},  {0x3087, 0x3088},  {0x308E, 0x308F},
    {0x3095, 0x304B},  {0x3096, 0x3051},  {0x30A1, 0x30A2},  {0x30A3, 0x30A4},  {0x30A5, 0x30A6},
    {0x30A7, 0x30A8},  {0x30A9, 0x30AA},  {0x30C3, 0x30C4},  {0x30E3, 0x30E4},  {0x30E5, 0x30E6},
    {0x30E7, 0x30E8},  {0x30EE, 0x30EF},  {0x30F5, 0x30AB},  {0x30F6, 0x30B1},  {0x31F0, 0x30AF},
    {0x31F1, 0x30B7},  {0x31F2, 0x30B9},  {0x31F3, 0x30C8},  {0x31F4, 0x30CC},  {0x31F5, 0x30CF},
    {0x31F6, 0x30D2},  {0x31F7, 0x30D5},  {0x31F8, 0x30D8},  {0x31F9, 0x30DB},  {0x31FA, 0x30E0},
    {0x31FB, 0x30E9},  {0x31FC, 0x30EA},  {0x31FD, 0x30EB},  {0x31FE, 0x30EC},  {0x31FF, 0x30ED},
    {0xFF67, 0xFF71},  {0xFF68, 0xFF72},  {0xFF69, 0xFF73},  {0xFF6A, 0xFF74},  {0xFF6B, 0xFF75},
    {0xFF6C, 0xFF94},  {0xFF6D, 0xFF95},  {0xFF6E, 0xFF96},  {0xFF6F, 0xFF82},  {0x1B132, 0x3053},
    {0x1B150, 0x3090}, {0x1B151, 0x3091}, {0x1B152, 0x3092}, {0x1B155, 0x30B3}, {0x1B164, 0x30F0},
    {0x1B165, 0x30F1}, {0x1B166, 0x30F2}, {0x1B167, 0x30F3},
}};

char32_t full_size_kana(char32_t c) noexcept {
  for (const auto& [small, full] : kSmallKana) {
    if (small == c) return full;
  }
  return c;
}

// The single character `c`'s compatibility decomposition is, or 0 when it is not one character.
char32_t single_decomposition(char32_t c) {
  std::array<gunichar, G_UNICHAR_MAX_DECOMPOSITION_LENGTH> out{};
  const gsize length = g_unichar_fully_decompose(static_cast<gunichar>(c), TRUE, out.data(), out.size());
  return length == 1 && out[0] != static_cast<gunichar>(c) ? static_cast<char32_t>(out[0]) : 0;
}

// Narrow character -> its full-width form, from the decompositions of the full-width forms (U+3000 and
// U+FF01..U+FF60, U+FFE0..U+FFE6 are exactly the <wide> decompositions of UnicodeData.txt), and the
// halfwidth forms (U+FF61..U+FFEE, each a <narrow> decomposition) -> their ordinary characters.
class FullWidthMap {
 public:
  FullWidthMap() {
    const auto add_wide = [this](char32_t wide) {
      if (const char32_t narrow = single_decomposition(wide)) pairs_.emplace_back(narrow, wide);
    };
    add_wide(0x3000);
    for (char32_t c = 0xFF01; c <= 0xFF60; ++c) add_wide(c);
    for (char32_t c = 0xFFE0; c <= 0xFFE6; ++c) add_wide(c);
    for (char32_t c = 0xFF61; c <= 0xFFEE; ++c) {
      if (c >= 0xFFE0 && c <= 0xFFE6) continue;
      if (const char32_t full = single_decomposition(c)) pairs_.emplace_back(c, full);
    }
    std::sort(pairs_.begin(), pairs_.end());
  }
  [[nodiscard]] char32_t operator()(char32_t c) const noexcept {
    const auto it = std::lower_bound(pairs_.begin(), pairs_.end(), std::pair<char32_t, char32_t>{c, 0});
    return it != pairs_.end() && it->first == c ? it->second : c;
  }

 private:
  std::vector<std::pair<char32_t, char32_t>> pairs_;
};

const FullWidthMap& full_width_map() {
  static const FullWidthMap map;
  return map;
}

std::u32string mapped(char32_t c, gchar* (*map)(const gchar*, gssize)) {
  std::array<gchar, 8> utf8{};
  const gint length = g_unichar_to_utf8(static_cast<gunichar>(c), utf8.data());
  gchar* changed = map(utf8.data(), length);
  std::u32string out;
  for (const gchar* p = changed; p != nullptr && *p != '\0'; p = g_utf8_next_char(p))
    out.push_back(static_cast<char32_t>(g_utf8_get_char(p)));
  g_free(changed);
  if (out.empty()) out.push_back(c);
  return out;
}

bool is_cased(char32_t c) noexcept {
  const gunichar u = static_cast<gunichar>(c);
  return g_unichar_isupper(u) || g_unichar_islower(u) || g_unichar_istitle(u);
}

// Letters, numbers and marks make words (a "typographic letter unit" is of general category L or N,
// CSS Text 3 2.1; marks belong to the letter before them).
bool is_word_character(char32_t c) noexcept {
  const gunichar u = static_cast<gunichar>(c);
  return g_unichar_isalnum(u) || g_unichar_ismark(u);
}

// UAX #29 MidLetter, MidNumLet and Single_Quote: inside a word when letters are on both sides ("don't").
bool is_mid_letter(char32_t c) noexcept {
  switch (c) {
    case 0x0027:
    case 0x002E:
    case 0x003A:
    case 0x00B7:
    case 0x0387:
    case 0x055F:
    case 0x05F4:
    case 0x2018:
    case 0x2019:
    case 0x2024:
    case 0x2027:
    case 0xFE13:
    case 0xFE52:
    case 0xFE55:
    case 0xFF07:
    case 0xFF0E:
    case 0xFF1A:
      return true;
    default:
      return false;
  }
}

std::u32string titlecase(char32_t c) {
  const gunichar u = static_cast<gunichar>(c);
  if (!g_unichar_islower(u)) return {c};  // "if lowercase" (CSS Text 3 2.1)
  const std::u32string upper = full_case(c, true);
  const gunichar title = g_unichar_totitle(u);
  if (title != u && upper.size() <= 1) return {static_cast<char32_t>(title)};
  // A full mapping to several characters: the first as uppercase, the rest lowercased ("ß" -> "Ss").
  std::u32string out(1, upper.front());
  for (std::size_t i = 1; i < upper.size(); ++i) out += full_case(upper[i], false);
  return out;
}

}  // namespace

std::u32string full_case(char32_t c, bool upper) {
  return mapped(c, upper ? g_utf8_strup : g_utf8_strdown);
}

void apply_text_transform(std::vector<TextFragment>& fragments) {
  if (std::none_of(fragments.begin(), fragments.end(),
                   [](const TextFragment& fragment) { return fragment.transform.any(); }))
    return;
  // The whole element's characters, for the context of words and of a final sigma.
  std::u32string all;
  for (const TextFragment& fragment : fragments) all += fragment.text;
  std::size_t index = 0;  // in `all`
  bool in_word = false;
  for (TextFragment& fragment : fragments) {
    std::u32string out;
    std::vector<bool> middle;
    out.reserve(fragment.text.size());
    middle.reserve(fragment.text.size());
    const TextTransform& transform = fragment.transform;
    for (const char32_t c : fragment.text) {
      const char32_t before = index > 0 ? all[index - 1] : 0;
      const char32_t after = index + 1 < all.size() ? all[index + 1] : 0;
      const bool word_start = is_word_character(c) && !in_word;
      if (is_word_character(c)) {
        in_word = true;
      } else if (!(is_mid_letter(c) && in_word && g_unichar_isalpha(static_cast<gunichar>(before)) &&
                   g_unichar_isalpha(static_cast<gunichar>(after)))) {
        in_word = false;
      }
      ++index;
      std::u32string result(1, c);
      switch (transform.case_transform) {
        case TextTransform::Case::kNone:
          break;
        case TextTransform::Case::kUppercase:
          result = full_case(c, true);
          break;
        case TextTransform::Case::kLowercase:
          // Final_Sigma (Unicode 3.13, Table 3-17): a capital sigma after a cased letter and not before one
          // is the final form.
          // GLib's g_utf8_strdown judges a sigma by its own string only, which here is the sigma alone.
          if (c == U'\u03A3') {
            const bool final = before != 0 && is_cased(before) && !(after != 0 && is_cased(after));
            result = std::u32string(1, final ? U'\u03C2' : U'\u03C3');
          } else {
            result = full_case(c, false);
          }
          break;
        case TextTransform::Case::kCapitalize:
          if (word_start) result = titlecase(c);
          break;
      }
      for (std::size_t k = 0; k < result.size(); ++k) {
        char32_t r = result[k];
        if (transform.full_width) r = full_width_map()(r);
        if (transform.full_size_kana) r = full_size_kana(r);
        out.push_back(r);
        middle.push_back(k > 0);
      }
    }
    fragment.text = std::move(out);
    fragment.middle = std::move(middle);
  }
}

}  // namespace curvescan::svg::detail
