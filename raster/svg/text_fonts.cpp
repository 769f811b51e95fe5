// Font lookup with caching and fallback warnings (text_fonts.h).
#include "text_fonts.h"

#include "curvescan/text/font_lookup.h"

namespace curvescan::svg::detail {
namespace {

FontQuery query_of(const ComputedStyle& style) {
  return FontQuery{style.font_family, style.font_weight, style.font_italic, style.text.font_variants.stretch};
}

}  // namespace

FontCache::QueryKey FontCache::key_of(const ComputedStyle& style) {
  return {style.font_family, style.font_weight, style.font_italic, style.text.font_variants.stretch};
}

const Font* FontCache::font_for(const ComputedStyle& style, Diagnostics& diagnostics) {
  QueryKey key = key_of(style);
  if (const auto cached = queries_.find(key); cached != queries_.end()) return cached->second;
  const Font* font = nullptr;
  const FontQuery query = query_of(style);
  const Result<FontMatch> match = match_font(query);
  if (!match) {
    diagnostics.warnings.push_back("<text> not drawn: no font for font-family '" + style.font_family +
                                   "': " + match.error().message);
  } else {
    if (!match->family_found) {
      diagnostics.warnings.push_back("font-family '" + style.font_family + "' is not installed; using '" +
                                     match->family + "' (fontconfig's fallback)");
    }
    std::pair<std::string, int> face_key{match->file.string(), match->face_index};
    auto face = faces_.find(face_key);
    if (face == faces_.end()) {
      Result<Font> opened = Font::open(match->file, match->face_index);
      if (!opened) {
        diagnostics.warnings.push_back("<text> not drawn: font '" + face_key.first +
                                       "' cannot be used: " + opened.error().message);
      } else {
        face = faces_.emplace(face_key, std::make_unique<Font>(std::move(opened).value())).first;
      }
    }
    if (face != faces_.end()) font = face->second.get();
  }
  queries_.emplace(std::move(key), font);
  return font;
}

FontFallback* FontCache::fallback_for(const ComputedStyle& style, Diagnostics& diagnostics) {
  QueryKey key = key_of(style);
  if (const auto cached = fallbacks_.find(key); cached != fallbacks_.end()) return cached->second.get();
  const Font* font = font_for(style, diagnostics);
  std::unique_ptr<FontFallback> fallback;
  if (font != nullptr) {
    fallback = std::make_unique<FontFallback>(*font, query_of(style));
  }
  return fallbacks_.emplace(std::move(key), std::move(fallback)).first->second.get();
}

}  // namespace curvescan::svg::detail
