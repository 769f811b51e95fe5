// Font lookup with caching, fallback warnings and variable-font instances (text_fonts.h).
#include "text_fonts.h"

#include <algorithm>

#include "curvescan/text/font_lookup.h"
#include "curvescan/text/text_layout.h"

namespace curvescan::svg::detail {
namespace {

FontQuery query_of(const ComputedStyle& style) {
  return FontQuery{style.font_family, style.font_weight, style.font_italic, style.text.font_variants.stretch};
}

}  // namespace

std::vector<FontVariation> variations_for(const ComputedStyle& style, const Font& face) {
  const FontVariants& variants = style.text.font_variants;
  std::vector<FontVariation> wanted{{font_feature_tag("wght"), static_cast<double>(style.font_weight)},
                                    {font_feature_tag("wdth"), variants.stretch}};
  if (variants.oblique_angle) {
    // OpenType's slnt counts degrees counter-clockwise, CSS's oblique angle clockwise (CSS Fonts 4 2.4).
    wanted.push_back({font_feature_tag("slnt"), -*variants.oblique_angle});
  } else if (style.font_italic) {
    wanted.push_back({font_feature_tag("ital"), 1.0});
  }
  if (variants.optical_sizing) wanted.push_back({font_feature_tag("opsz"), style.font_size});
  wanted.insert(wanted.end(), variants.variation_settings.begin(), variants.variation_settings.end());
  // Keep the last value of each axis the face has: set_variations would apply the same, and the list is
  // the key of the instance, so equal coordinates must give equal lists.
  std::vector<FontVariation> result;
  for (auto it = wanted.rbegin(); it != wanted.rend(); ++it) {
    const bool seen = std::any_of(result.begin(), result.end(),
                                  [&](const FontVariation& v) { return v.tag == it->tag; });
    if (!seen && face.has_variation_axis(it->tag)) result.push_back(*it);
  }
  std::sort(result.begin(), result.end());
  return result;
}

FontCache::QueryKey FontCache::key_of(const ComputedStyle& style) {
  return {style.font_family, style.font_weight, style.font_italic, style.text.font_variants.stretch};
}

const Font* FontCache::base_font_for(const ComputedStyle& style, Diagnostics& diagnostics) {
  QueryKey key = key_of(style);
  if (const auto cached = queries_.find(key); cached != queries_.end()) return cached->second;
  const Font* font = nullptr;
  FontQuery query = query_of(style);
  Result<FontMatch> match = match_font(query);
  if (match && !match->family_found) {
    // None of the names is installed: the user agent's default family, the initial value serif (CSS
    // Fonts 4 5.1), as browsers do, rather than whatever fontconfig ranks first.
    query.family = "serif";
    Result<FontMatch> fallback = match_font(query);
    if (fallback) {
      diagnostics.warnings.push_back("font-family '" + style.font_family + "' is not installed; using '" +
                                     fallback->family + "' (the default serif family)");
      match = std::move(fallback);
    }
  }
  if (!match) {
    diagnostics.warnings.push_back("<text> not drawn: no font for font-family '" + style.font_family +
                                   "': " + match.error().message);
  } else {
    FaceKey face_key{match->file.string(), match->face_index};
    auto face = faces_.find(face_key);
    if (face == faces_.end()) {
      Result<Font> opened = Font::open(match->file, match->face_index);
      if (!opened) {
        diagnostics.warnings.push_back("<text> not drawn: font '" + face_key.first +
                                       "' cannot be used: " + opened.error().message);
      } else {
        face = faces_.emplace(face_key, std::make_unique<Font>(std::move(opened).value())).first;
        face_keys_.emplace(face->second.get(), face_key);
        variable_.emplace(face->second.get(), face->second->is_variable());
      }
    }
    if (face != faces_.end()) font = face->second.get();
  }
  queries_.emplace(std::move(key), font);
  return font;
}

const Font* FontCache::font_for(const ComputedStyle& style, Diagnostics& diagnostics) {
  const Font* base = base_font_for(style, diagnostics);
  if (base == nullptr || !variable_.at(base)) return base;
  std::vector<FontVariation> variations = variations_for(style, *base);
  if (variations.empty()) return base;
  const FaceKey& face_key = face_keys_.at(base);
  auto key = std::make_pair(face_key, std::move(variations));
  if (const auto found = instances_.find(key); found != instances_.end()) return found->second.get();
  // A Font of its own for these coordinates: a face holds one point of the design space at a time, and
  // its shaped runs are cached for that point (shaping_p.h).
  Result<Font> opened = Font::open(face_key.first, face_key.second);
  if (!opened) return base;  // it opened a moment ago; keep the default coordinates
  auto instance = std::make_unique<Font>(std::move(opened).value());
  if (const Status set = instance->set_variations(key.second); !set.is_ok()) {
    diagnostics.warnings.push_back("font-variation-settings ignored: " + set.error().message);
    return base;
  }
  return instances_.emplace(std::move(key), std::move(instance)).first->second.get();
}

FontFallback* FontCache::fallback_for(const ComputedStyle& style, Diagnostics& diagnostics) {
  const Font* font = font_for(style, diagnostics);
  auto key = std::make_pair(key_of(style), font);
  if (const auto cached = fallbacks_.find(key); cached != fallbacks_.end()) return cached->second.get();
  std::unique_ptr<FontFallback> fallback;
  if (font != nullptr) {
    fallback = std::make_unique<FontFallback>(*font, query_of(style));
  }
  return fallbacks_.emplace(std::move(key), std::move(fallback)).first->second.get();
}

void FontCache::warn_outline_only(const Font& face, ColorGlyphKind kind, Diagnostics& diagnostics) {
  // By the name the warning shows: the instances of one variable face are one font to the user.
  const std::string warning = outline_only_warning(face, kind);
  if (!warning.empty() && outline_only_warned_.emplace(warning, kind).second)
    diagnostics.warnings.push_back(warning);
}

}  // namespace curvescan::svg::detail
