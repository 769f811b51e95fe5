// Font variants, features, kerning and width (text_font_variants.h).
#include "text_font_variants.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "curvescan/svg/number.h"

namespace curvescan::svg::detail {
namespace {

// Whether `parsed` is a value, which then replaces `target`.
bool set(std::vector<FontFeature>& target, std::optional<std::vector<FontFeature>> parsed) {
  if (!parsed) return false;
  target = std::move(*parsed);
  return true;
}

constexpr FontFeature on(std::string_view tag, std::uint32_t value = 1) {
  return {font_feature_tag(tag), value};
}

// The words of a space-separated value.
std::vector<std::string_view> words_of(std::string_view value) {
  std::vector<std::string_view> words;
  while (true) {
    value = trim_whitespace(value);
    if (value.empty()) return words;
    std::size_t end = 0;
    while (end < value.size() && !is_svg_whitespace(value[end])) ++end;
    words.push_back(value.substr(0, end));
    value.remove_prefix(end);
  }
}

// One keyword of a longhand that takes a combination of groups ("a || b || c"), each group a set of
// mutually exclusive keywords with their features. Each group at most once.
struct Keyword {
  std::string_view name;
  int group;
  std::array<FontFeature, 2> features;
  int feature_count;
};

// font-variant-ligatures (CSS Fonts 4 6.4).
constexpr int kLigatureGroups = 4;
const std::array<Keyword, 8> kLigatureKeywords{{
    {"common-ligatures", 0, {on("liga"), on("clig")}, 2},
    {"no-common-ligatures", 0, {on("liga", 0), on("clig", 0)}, 2},
    {"discretionary-ligatures", 1, {on("dlig")}, 1},
    {"no-discretionary-ligatures", 1, {on("dlig", 0)}, 1},
    {"historical-ligatures", 2, {on("hlig")}, 1},
    {"no-historical-ligatures", 2, {on("hlig", 0)}, 1},
    {"contextual", 3, {on("calt")}, 1},
    {"no-contextual", 3, {on("calt", 0)}, 1},
}};
// font-variant-numeric (6.7).
constexpr int kNumericGroups = 5;
const std::array<Keyword, 8> kNumericKeywords{{
    {"lining-nums", 0, {on("lnum")}, 1},
    {"oldstyle-nums", 0, {on("onum")}, 1},
    {"proportional-nums", 1, {on("pnum")}, 1},
    {"tabular-nums", 1, {on("tnum")}, 1},
    {"diagonal-fractions", 2, {on("frac")}, 1},
    {"stacked-fractions", 2, {on("afrc")}, 1},
    {"ordinal", 3, {on("ordn")}, 1},
    {"slashed-zero", 4, {on("zero")}, 1},
}};
// font-variant-east-asian (6.10).
constexpr int kEastAsianGroups = 3;
const std::array<Keyword, 9> kEastAsianKeywords{{
    {"jis78", 0, {on("jp78")}, 1},
    {"jis83", 0, {on("jp83")}, 1},
    {"jis90", 0, {on("jp90")}, 1},
    {"jis04", 0, {on("jp04")}, 1},
    {"simplified", 0, {on("smpl")}, 1},
    {"traditional", 0, {on("trad")}, 1},
    {"full-width", 1, {on("fwid")}, 1},
    {"proportional-width", 1, {on("pwid")}, 1},
    {"ruby", 2, {on("ruby")}, 1},
}};

template <std::size_t N>
const Keyword* find_keyword(const std::array<Keyword, N>& keywords, std::string_view word) {
  for (const Keyword& keyword : keywords)
    if (keyword.name == word) return &keyword;
  return nullptr;
}

// A combination longhand: normal, or keywords of distinct groups. nullopt when invalid.
template <std::size_t N>
std::optional<std::vector<FontFeature>> parse_combination(std::string_view value,
                                                          const std::array<Keyword, N>& keywords,
                                                          int groups) {
  const std::vector<std::string_view> words = words_of(value);
  if (words.size() == 1 && words[0] == "normal") return std::vector<FontFeature>{};
  if (words.empty()) return std::nullopt;
  std::vector<bool> seen(static_cast<std::size_t>(groups), false);
  std::vector<FontFeature> features;
  for (const std::string_view word : words) {
    const Keyword* keyword = find_keyword(keywords, word);
    if (keyword == nullptr || seen[static_cast<std::size_t>(keyword->group)]) return std::nullopt;
    seen[static_cast<std::size_t>(keyword->group)] = true;
    features.insert(features.end(), keyword->features.begin(),
                    keyword->features.begin() + keyword->feature_count);
  }
  return features;
}

std::optional<std::vector<FontFeature>> parse_ligatures(std::string_view value) {
  if (trim_whitespace(value) == "none") {
    return std::vector<FontFeature>{on("liga", 0), on("clig", 0), on("dlig", 0), on("hlig", 0),
                                    on("calt", 0)};
  }
  return parse_combination(value, kLigatureKeywords, kLigatureGroups);
}

std::optional<std::vector<FontFeature>> parse_position(std::string_view value) {
  value = trim_whitespace(value);
  if (value == "normal") return std::vector<FontFeature>{};
  if (value == "sub") return std::vector<FontFeature>{on("subs")};
  if (value == "super") return std::vector<FontFeature>{on("sups")};
  return std::nullopt;
}

// font-variant-caps: sets `caps` and the features of unicase and titling-caps.
bool parse_caps(std::string_view value, FontVariants& variants) {
  value = trim_whitespace(value);
  variants.caps_features.clear();
  if (value == "normal") {
    variants.caps = CapsVariant::kNormal;
  } else if (value == "small-caps" || value == "petite-caps") {
    variants.caps = CapsVariant::kSmallCaps;
  } else if (value == "all-small-caps" || value == "all-petite-caps") {
    variants.caps = CapsVariant::kAllSmallCaps;
  } else if (value == "unicase" || value == "titling-caps") {
    variants.caps = CapsVariant::kNormal;
    variants.caps_features.push_back(on(value == "unicase" ? "unic" : "titl"));
  } else {
    return false;
  }
  return true;
}

// A comma-separated list of `<string> value` items, or "normal" for none (font-feature-settings and
// font-variation-settings, CSS Fonts 4 7.12 and 7.13): each string a quoted tag of four characters of
// U+20-7E, its value read by `parse_value(tag, rest)` from the rest of the item, trimmed; nullopt from it,
// or a malformed tag, makes the whole declaration invalid.
template <typename Item, typename ParseValue>
std::optional<std::vector<Item>> parse_tagged_list(std::string_view value, ParseValue parse_value) {
  value = trim_whitespace(value);
  if (value == "normal") return std::vector<Item>{};
  std::vector<Item> items;
  while (true) {
    const std::size_t comma = std::min(value.find(','), value.size());
    const std::string_view item = trim_whitespace(value.substr(0, comma));
    if (item.size() < 6 || (item[0] != '"' && item[0] != '\'') || item[5] != item[0]) return std::nullopt;
    const std::string_view tag = item.substr(1, 4);
    if (!std::all_of(tag.begin(), tag.end(), [](char c) { return c >= 0x20 && c <= 0x7e; }))
      return std::nullopt;
    const std::optional<Item> parsed = parse_value(font_feature_tag(tag), trim_whitespace(item.substr(6)));
    if (!parsed) return std::nullopt;
    items.push_back(*parsed);
    if (comma == value.size()) break;
    value.remove_prefix(comma + 1);
  }
  return items;
}

// font-feature-settings (CSS Fonts 4 7.12): normal | [ <string> [ <integer [0,inf]> | on | off ]? ]#.
std::optional<std::vector<FontFeature>> parse_feature_settings(std::string_view value) {
  return parse_tagged_list<FontFeature>(
      value, [](std::uint32_t tag, std::string_view setting) -> std::optional<FontFeature> {
        if (setting.empty() || setting == "on") return FontFeature{tag, 1};
        if (setting == "off") return FontFeature{tag, 0};
        const std::optional<double> parsed = parse_number(setting);
        // An <integer>: no fraction, no exponent form that parse_number would accept as a non-integer.
        if (!parsed || *parsed < 0.0 || *parsed != std::floor(*parsed) || *parsed > 65535.0 ||
            setting.find_first_of(".eE") != std::string_view::npos) {
          return std::nullopt;
        }
        return FontFeature{tag, static_cast<std::uint32_t>(*parsed)};
      });
}

// font-variation-settings (CSS Fonts 4 7.13): normal | [ <string> <number> ]#; the tag is kept as written
// (a tag the font has no axis for is ignored at layout).
std::optional<std::vector<FontVariation>> parse_variation_settings(std::string_view value) {
  return parse_tagged_list<FontVariation>(
      value, [](std::uint32_t tag, std::string_view setting) -> std::optional<FontVariation> {
        const std::optional<double> number = parse_number(setting);
        if (!number || !std::isfinite(*number)) return std::nullopt;
        return FontVariation{tag, *number};
      });
}

// The keyword widths of font-stretch (CSS Fonts 4 2.3, table of keyword values), narrowest first.
constexpr std::array<std::pair<std::string_view, double>, 9> kStretchKeywords{{{"ultra-condensed", 50.0},
                                                                               {"extra-condensed", 62.5},
                                                                               {"condensed", 75.0},
                                                                               {"semi-condensed", 87.5},
                                                                               {"normal", 100.0},
                                                                               {"semi-expanded", 112.5},
                                                                               {"expanded", 125.0},
                                                                               {"extra-expanded", 150.0},
                                                                               {"ultra-expanded", 200.0}}};

// SVG 1.1 (10.10) and CSS 2 font-stretch wider / narrower: the next keyword width beyond the parent's.
double relative_stretch(double parent, bool wider) noexcept {
  if (wider) {
    for (const auto& [name, width] : kStretchKeywords)
      if (width > parent) return width;
    return kStretchKeywords.back().second;
  }
  for (auto it = kStretchKeywords.rbegin(); it != kStretchKeywords.rend(); ++it)
    if (it->second < parent) return it->second;
  return kStretchKeywords.front().second;
}

}  // namespace

std::vector<FontFeature> FontVariants::features() const {
  std::vector<FontFeature> all;
  for (const std::vector<FontFeature>* part :
       {&ligatures, &position, &caps_features, &numeric, &east_asian, &settings})
    all.insert(all.end(), part->begin(), part->end());
  return all;
}

bool is_css_only_font_property(std::string_view name) noexcept {
  constexpr std::array<std::string_view, 10> kCssOnly{
      "font-variant-caps",       "font-variant-ligatures", "font-variant-position", "font-variant-numeric",
      "font-variant-east-asian", "font-feature-settings",  "font-kerning",          "font-width",
      "font-variation-settings", "font-optical-sizing"};
  return std::find(kCssOnly.begin(), kCssOnly.end(), name) != kCssOnly.end();
}

std::optional<double> font_style_oblique_angle(std::string_view value) noexcept {
  value = trim_whitespace(value);
  constexpr std::string_view kOblique = "oblique";
  if (value.substr(0, kOblique.size()) != kOblique) return std::nullopt;
  value = value.substr(kOblique.size());
  if (value.empty()) return 14.0;
  if (!is_svg_whitespace(value.front())) return std::nullopt;
  value = trim_whitespace(value);
  // <angle> (CSS Values 4 7.1): a number and a unit; degrees per unit.
  constexpr std::array<std::pair<std::string_view, double>, 4> kUnits{
      {{"deg", 1.0}, {"grad", 0.9}, {"rad", 57.29577951308232}, {"turn", 360.0}}};
  for (const auto& [unit, degrees] : kUnits) {
    if (value.size() <= unit.size() || value.substr(value.size() - unit.size()) != unit) continue;
    const std::optional<double> number = parse_number(value.substr(0, value.size() - unit.size()));
    if (!number) return std::nullopt;
    const double angle = *number * degrees;
    if (!(angle >= -90.0 && angle <= 90.0)) return std::nullopt;
    return angle;
  }
  return std::nullopt;
}

std::optional<double> parse_font_stretch(std::string_view value) noexcept {
  value = trim_whitespace(value);
  for (const auto& [name, width] : kStretchKeywords)
    if (value == name) return width;
  if (value.size() > 1 && value.back() == '%') {
    const std::optional<double> number = parse_number(value.substr(0, value.size() - 1));
    if (number && *number >= 0.0 && std::isfinite(*number)) return *number;
  }
  return std::nullopt;
}

namespace font_variant {

bool font_variant(FontVariants& variants, const FontVariants& parent, std::string_view value, bool inherit) {
  if (inherit) {
    variants.caps = parent.caps;
    variants.caps_features = parent.caps_features;
    variants.ligatures = parent.ligatures;
    variants.position = parent.position;
    variants.numeric = parent.numeric;
    variants.east_asian = parent.east_asian;
    return true;
  }
  // The shorthand (6.11): normal | none | [ caps || ligatures values || position || numeric ||
  // east-asian values ]; every longhand it does not name goes back to normal. Each word is tried
  // against each longhand, and the words of one longhand are gathered and parsed together.
  FontVariants result = variants;
  result.caps = CapsVariant::kNormal;
  result.caps_features.clear();
  result.ligatures.clear();
  result.position.clear();
  result.numeric.clear();
  result.east_asian.clear();
  if (value == "normal") {
    variants = std::move(result);
    return true;
  }
  if (value == "none") {
    result.ligatures = *parse_ligatures("none");
    variants = std::move(result);
    return true;
  }
  if (value.empty()) return false;
  std::string ligatures, numeric, east_asian;
  bool caps_seen = false, position_seen = false;
  for (const std::string_view word : words_of(value)) {
    const auto append = [&](std::string& list) { (list += ' ') += word; };
    if (find_keyword(kLigatureKeywords, word) != nullptr) {
      append(ligatures);
    } else if (find_keyword(kNumericKeywords, word) != nullptr) {
      append(numeric);
    } else if (find_keyword(kEastAsianKeywords, word) != nullptr) {
      append(east_asian);
    } else if (word == "sub" || word == "super") {
      if (position_seen) return false;
      position_seen = true;
      result.position = *parse_position(word);
    } else {
      if (caps_seen || word == "normal" || !parse_caps(word, result)) return false;
      caps_seen = true;
    }
  }
  if (!ligatures.empty() && !set(result.ligatures, parse_ligatures(ligatures))) return false;
  if (!numeric.empty() && !set(result.numeric, parse_combination(numeric, kNumericKeywords, kNumericGroups)))
    return false;
  if (!east_asian.empty() &&
      !set(result.east_asian, parse_combination(east_asian, kEastAsianKeywords, kEastAsianGroups))) {
    return false;
  }
  variants = std::move(result);
  return true;
}

bool font_variant_caps(FontVariants& variants, const FontVariants& parent, std::string_view value,
                       bool inherit) {
  if (inherit) {
    variants.caps = parent.caps;
    variants.caps_features = parent.caps_features;
    return true;
  }
  return parse_caps(value, variants);
}

bool font_variant_ligatures(FontVariants& variants, const FontVariants& parent, std::string_view value,
                            bool inherit) {
  if (inherit) {
    variants.ligatures = parent.ligatures;
    return true;
  }
  return set(variants.ligatures, parse_ligatures(value));
}

bool font_variant_position(FontVariants& variants, const FontVariants& parent, std::string_view value,
                           bool inherit) {
  if (inherit) {
    variants.position = parent.position;
    return true;
  }
  return set(variants.position, parse_position(value));
}

bool font_variant_numeric(FontVariants& variants, const FontVariants& parent, std::string_view value,
                          bool inherit) {
  if (inherit) {
    variants.numeric = parent.numeric;
    return true;
  }
  return set(variants.numeric, parse_combination(value, kNumericKeywords, kNumericGroups));
}

bool font_variant_east_asian(FontVariants& variants, const FontVariants& parent, std::string_view value,
                             bool inherit) {
  if (inherit) {
    variants.east_asian = parent.east_asian;
    return true;
  }
  return set(variants.east_asian, parse_combination(value, kEastAsianKeywords, kEastAsianGroups));
}

bool font_feature_settings(FontVariants& variants, const FontVariants& parent, std::string_view value,
                           bool inherit) {
  if (inherit) {
    variants.settings = parent.settings;
    return true;
  }
  return set(variants.settings, parse_feature_settings(value));
}

bool font_variation_settings(FontVariants& variants, const FontVariants& parent, std::string_view value,
                             bool inherit) {
  if (inherit) {
    variants.variation_settings = parent.variation_settings;
    return true;
  }
  std::optional<std::vector<FontVariation>> parsed = parse_variation_settings(value);
  if (!parsed) return false;
  variants.variation_settings = std::move(*parsed);
  return true;
}

bool kerning(FontVariants& variants, const FontVariants& parent, std::string_view value, bool inherit) {
  if (inherit) {
    variants.kerning_length = parent.kerning_length;
    return true;
  }
  if (value == "auto") {
    variants.kerning_length.reset();
    return true;
  }
  const Result<Length> length = parse_length(value);
  if (!length || length->unit == LengthUnit::kPercent || !std::isfinite(length->value)) return false;
  variants.kerning_length = *length;
  return true;
}

bool font_stretch(FontVariants& variants, const FontVariants& parent, std::string_view value, bool inherit) {
  if (inherit) {
    variants.stretch = parent.stretch;
    return true;
  }
  if (value == "wider" || value == "narrower") {
    variants.stretch = relative_stretch(parent.stretch, value == "wider");
    return true;
  }
  const std::optional<double> stretch = parse_font_stretch(value);
  if (!stretch) return false;
  variants.stretch = *stretch;
  return true;
}

}  // namespace font_variant

}  // namespace curvescan::svg::detail
