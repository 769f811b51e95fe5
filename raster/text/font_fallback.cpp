// Per-character font fallback (font_fallback.h) over fontconfig's FcFontSort.
//
// A share of the process's configuration (fontconfig_config_p.h) and the sorted font set are kept for the
// object's lifetime: the candidates' FcCharSets point into fontconfig's memory-mapped caches, which live as
// long as the configuration that loaded them (fontconfig-devel, "FcCharSetCopy": constant charsets from
// caches are not reference-counted).
#include "curvescan/text/font_fallback.h"

#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "fontconfig_config_p.h"
#include "fontconfig_query_p.h"

namespace curvescan {
namespace {

struct FontSetDeleter {
  void operator()(FcFontSet* set) const noexcept { FcFontSetDestroy(set); }
};
using FontSetPtr = std::unique_ptr<FcFontSet, FontSetDeleter>;

// One face of fontconfig's sorted list: where it is, what it covers, and the face once opened.
struct Candidate {
  std::string file;
  int face_index = 0;
  FcCharSet* coverage = nullptr;  // owned by the font set
  std::unique_ptr<Font> font;
  bool unusable = false;  // Font::open failed: never tried again
};

}  // namespace

struct FontFallback::Impl {
  const Font* primary = nullptr;
  FontQuery query;
  bool sorted = false;  // FcFontSort has run (lazily: most texts never miss a character)
  std::shared_ptr<FcConfig> config;
  FontSetPtr font_set;
  std::vector<Candidate> candidates;
  std::unordered_map<char32_t, const Font*> by_character;

  // Fills `candidates` from FcFontSort for the query; on any fontconfig failure the list stays empty and
  // every missing character is then reported missing.
  void sort_candidates() {
    sorted = true;
    std::vector<std::string> families = detail::split_family_list(query.family);
    if (families.empty()) families.push_back(primary->family_name());
    const detail::FontconfigLock fontconfig;
    config = fontconfig.share();
    if (!config) return;
    const detail::FcPatternPtr pattern = detail::query_pattern(config.get(), query, families);
    if (!pattern) return;
    FcResult result = FcResultNoMatch;
    // trim = FcTrue: faces that add no character to those before them are dropped (fontconfig-devel,
    // "FcFontSort"), so the list is short and every entry can be the answer for some character.
    font_set.reset(FcFontSort(config.get(), pattern.get(), FcTrue, nullptr, &result));
    if (!font_set) return;
    for (int i = 0; i < font_set->nfont; ++i) {
      FcPattern* face = font_set->fonts[i];
      FcChar8* file = nullptr;
      FcCharSet* coverage = nullptr;
      if (FcPatternGetString(face, FC_FILE, 0, &file) != FcResultMatch || file == nullptr ||
          FcPatternGetCharSet(face, FC_CHARSET, 0, &coverage) != FcResultMatch || coverage == nullptr) {
        continue;
      }
      Candidate candidate;
      candidate.file = reinterpret_cast<const char*>(file);
      if (FcPatternGetInteger(face, FC_INDEX, 0, &candidate.face_index) != FcResultMatch) {
        candidate.face_index = 0;
      }
      candidate.coverage = coverage;
      candidates.push_back(std::move(candidate));
    }
  }

  const Font* search(char32_t character) {
    if (!sorted) sort_candidates();
    for (Candidate& candidate : candidates) {
      if (candidate.unusable || FcCharSetHasChar(candidate.coverage, static_cast<FcChar32>(character)) == 0) {
        continue;
      }
      if (!candidate.font) {
        Result<Font> opened = Font::open(candidate.file, candidate.face_index);
        if (!opened) {
          candidate.unusable = true;
          continue;
        }
        candidate.font = std::make_unique<Font>(std::move(opened).value());
      }
      // The charset is fontconfig's reading of the cmap; FreeType's is the one drawing uses, so it decides.
      if (candidate.font->glyph_for(character) != kNotdefGlyph) return candidate.font.get();
    }
    return nullptr;
  }
};

FontFallback::FontFallback(const Font& primary, FontQuery query) : impl_(std::make_unique<Impl>()) {
  impl_->primary = &primary;
  impl_->query = std::move(query);
}
FontFallback::FontFallback(FontFallback&&) noexcept = default;
FontFallback& FontFallback::operator=(FontFallback&&) noexcept = default;
FontFallback::~FontFallback() = default;

const Font& FontFallback::primary() const noexcept {
  return *impl_->primary;
}

const Font* FontFallback::face_for(char32_t character) {
  if (impl_->primary->glyph_for(character) != kNotdefGlyph) return impl_->primary;
  if (const auto cached = impl_->by_character.find(character); cached != impl_->by_character.end()) {
    return cached->second;
  }
  const Font* face = impl_->search(character);
  impl_->by_character.emplace(character, face);
  return face;
}

std::size_t FontFallback::opened_face_count() const noexcept {
  std::size_t count = 0;
  for (const Candidate& candidate : impl_->candidates) count += candidate.font ? 1 : 0;
  return count;
}

}  // namespace curvescan
