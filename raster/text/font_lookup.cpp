// Font lookup through fontconfig: FcPatternBuild -> FcConfigSubstitute -> FcDefaultSubstitute ->
// FcFontMatch, the sequence fontconfig's own documentation (fontconfig-devel, "FcFontMatch") prescribes.
// fontconfig always returns a face, falling back through its alias rules, so whether a requested
// family was really found is decided afterwards by comparing family names (CSS Fonts 3 section 5.2
// compares family names case-insensitively).
#include "curvescan/text/font_lookup.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <memory>
#include <string_view>
#include <utility>
#include <vector>

#include "fontconfig_config_p.h"
#include "fontconfig_query_p.h"
#include "fontconfig_results_p.h"

namespace curvescan {
namespace detail {

std::vector<std::string> split_family_list(std::string_view list) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    std::string_view name = list.substr(start, comma - start);
    while (!name.empty() && std::isspace(static_cast<unsigned char>(name.front()))) name.remove_prefix(1);
    while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back()))) name.remove_suffix(1);
    if (name.size() >= 2 && (name.front() == '"' || name.front() == '\'') && name.back() == name.front()) {
      name = name.substr(1, name.size() - 2);
    }
    if (!name.empty()) names.emplace_back(name);
    start = comma + 1;
  }
  return names;
}

FcPatternPtr query_pattern(FcConfig* config, const FontQuery& query, const std::vector<std::string>& families,
                           bool scalable) {
  FcPatternPtr pattern(FcPatternCreate());
  if (!pattern) return pattern;
  for (const std::string& name : families) {
    FcPatternAddString(pattern.get(), FC_FAMILY, reinterpret_cast<const FcChar8*>(name.c_str()));
  }
  const double weight = std::clamp(query.weight, 1, 1000);
  FcPatternAddDouble(pattern.get(), FC_WEIGHT, FcWeightFromOpenTypeDouble(weight));
  FcPatternAddInteger(pattern.get(), FC_SLANT, query.italic ? FC_SLANT_ITALIC : FC_SLANT_ROMAN);
  // FC_WIDTH is an integer percentage; fontconfig ranks faces by the distance to it.
  const double width = std::isfinite(query.width) ? std::clamp(query.width, 1.0, 1000.0) : 100.0;
  FcPatternAddInteger(pattern.get(), FC_WIDTH, static_cast<int>(std::lround(width)));
  if (scalable) FcPatternAddBool(pattern.get(), FC_SCALABLE, FcTrue);
  FcConfigSubstitute(config, pattern.get(), FcMatchPattern);
  FcDefaultSubstitute(pattern.get());
  return pattern;
}

}  // namespace detail
namespace {

using detail::FcPatternPtr;

std::string lowercase(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

bool is_generic_family(const std::string& lower_name) {
  constexpr std::array<std::string_view, 8> kGeneric{"serif", "sans-serif", "sans",    "monospace",
                                                     "mono",  "cursive",    "fantasy", "system-ui"};
  return std::find(kGeneric.begin(), kGeneric.end(), lower_name) != kGeneric.end();
}

// fontconfig's best face for `names` (scalable ones first when `scalable`), and whether it is a colour font.
Result<std::pair<FontMatch, bool>> match_with(FcConfig* config, const FontQuery& query,
                                              const std::vector<std::string>& names, bool scalable) {
  const FcPatternPtr pattern = detail::query_pattern(config, query, names, scalable);
  if (!pattern) return Error{ErrorKind::kIoError, "fontconfig is out of memory"};
  FcResult result = FcResultNoMatch;
  FcPatternPtr match(FcFontMatch(config, pattern.get(), &result));
  // fontconfig picks the family, slant and width; the weight among that family's faces is CSS's.
  if (match) {
    if (FcPatternPtr by_weight = detail::css_weight_face(config, match.get(), query.weight))
      match = std::move(by_weight);
  }
  FcChar8* file = nullptr;
  if (!match || FcPatternGetString(match.get(), FC_FILE, 0, &file) != FcResultMatch || file == nullptr) {
    return Error{ErrorKind::kIoError,
                 "fontconfig found no installed font at all (is any font package installed?)"};
  }

  FontMatch found;
  found.file = reinterpret_cast<const char*>(file);
  int index = 0;
  if (FcPatternGetInteger(match.get(), FC_INDEX, 0, &index) == FcResultMatch) found.face_index = index;
  FcChar8* text = nullptr;
  if (FcPatternGetString(match.get(), FC_STYLE, 0, &text) == FcResultMatch) {
    found.style = reinterpret_cast<const char*>(text);
  }
  std::vector<std::string> matched_families;
  for (int i = 0; FcPatternGetString(match.get(), FC_FAMILY, i, &text) == FcResultMatch; ++i) {
    matched_families.push_back(lowercase(reinterpret_cast<const char*>(text)));
    if (i == 0) found.family = reinterpret_cast<const char*>(text);
  }
  for (const std::string& name : names) {
    const std::string lower = lowercase(name);
    if (is_generic_family(lower) ||
        std::find(matched_families.begin(), matched_families.end(), lower) != matched_families.end()) {
      found.family_found = true;
      break;
    }
  }
  FcBool color = FcFalse;
  const bool is_color =
      FcPatternGetBool(match.get(), FC_COLOR, 0, &color) == FcResultMatch && color == FcTrue;
  return std::pair<FontMatch, bool>{std::move(found), is_color};
}

// fontconfig's answer for `query` (the whole of match_font once the configuration is loaded).
Result<FontMatch> ask_fontconfig(FcConfig* config, const FontQuery& query,
                                 const std::vector<std::string>& names) {
  detail::count_fontconfig_request();
  Result<std::pair<FontMatch, bool>> scalable = match_with(config, query, names, true);
  if (!scalable) return scalable.error();
  if (scalable->first.family_found) return std::move(scalable->first);
  // None of the families has a scalable face: a bitmap colour font of one of them (CBDT emoji, which
  // fontconfig lists as not scalable) is drawn (color_glyph.h); other bitmap-only fonts are not.
  Result<std::pair<FontMatch, bool>> any = match_with(config, query, names, false);
  if (any && any->first.family_found && any->second) return std::move(any->first);
  return std::move(scalable->first);
}

}  // namespace

Result<FontMatch> match_font(const FontQuery& query) {
  const std::vector<std::string> names = detail::split_family_list(query.family);
  if (names.empty()) return Error{ErrorKind::kInvalidArgument, "the font family name is empty"};
  // The process's configuration, loaded at the first lookup (fontconfig_config_p.h), and the answers it
  // has already given (fontconfig_results_p.h): each request is matched once per process.
  const detail::FontconfigLock fontconfig;
  FcConfig* config = fontconfig.config();
  if (config == nullptr) return Error{ErrorKind::kIoError, "fontconfig could not be initialised"};
  auto& matches = fontconfig.results().matches;
  std::string key = detail::request_key('m', query, names);
  if (const auto known = matches.find(key); known != matches.end()) return known->second;
  Result<FontMatch> answer = ask_fontconfig(config, query, names);
  if (matches.size() >= detail::FontconfigResults::kMaxEntries) matches.clear();
  matches.emplace(std::move(key), answer);
  return answer;
}

Result<Font> load_font(const FontQuery& query, bool allow_fallback) {
  const Result<FontMatch> match = match_font(query);
  if (!match) return match.error();
  if (!match->family_found && !allow_fallback) {
    return Error{ErrorKind::kInvalidArgument, "no installed font family matches '" + query.family +
                                                  "' (fontconfig would fall back to '" + match->family +
                                                  "')"};
  }
  return Font::open(match->file, match->face_index);
}

}  // namespace curvescan
