// Per-character font fallback (font_fallback.h) over fontconfig's FcFontSort.
//
// The sorted list is asked of fontconfig once per process for each request and shared
// (fontconfig_results_p.h); the object keeps its share, which keeps the configuration alive: the
// candidates' FcCharSets point into fontconfig's memory-mapped caches, which live as long as the
// configuration that loaded them (fontconfig-devel, "FcCharSetCopy": constant charsets from caches are not
// reference-counted). The faces it opens are its own (a Font is used by one thread at a time).
#include "curvescan/text/font_fallback.h"

#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "fontconfig_config_p.h"
#include "fontconfig_query_p.h"
#include "fontconfig_results_p.h"

namespace curvescan {
namespace {

// FcFontSort's list for `query` with `families`; null on any fontconfig failure (then every missing
// character is reported missing). Asked of fontconfig the first time, answered from the kept list after.
std::shared_ptr<const detail::SortedFaces> sorted_faces(const FontQuery& query,
                                                        const std::vector<std::string>& families) {
  const detail::FontconfigLock fontconfig;
  if (fontconfig.config() == nullptr) return nullptr;
  auto& sorts = fontconfig.results().sorts;
  std::string key = detail::request_key('s', query, families);
  if (const auto known = sorts.find(key); known != sorts.end()) return known->second;
  detail::count_fontconfig_request();
  auto answer = std::make_shared<detail::SortedFaces>();
  answer->config = fontconfig.share();
  const detail::FcPatternPtr pattern = detail::query_pattern(answer->config.get(), query, families);
  if (!pattern) return nullptr;  // out of memory: not kept, asked again next time
  FcResult result = FcResultNoMatch;
  // trim = FcTrue: faces that add no character to those before them are dropped (fontconfig-devel,
  // "FcFontSort"), so the list is short and every entry can be the answer for some character.
  answer->font_set.reset(FcFontSort(answer->config.get(), pattern.get(), FcTrue, nullptr, &result));
  if (answer->font_set) {
    for (int i = 0; i < answer->font_set->nfont; ++i) {
      FcPattern* face = answer->font_set->fonts[i];
      FcChar8* file = nullptr;
      FcCharSet* coverage = nullptr;
      if (FcPatternGetString(face, FC_FILE, 0, &file) != FcResultMatch || file == nullptr ||
          FcPatternGetCharSet(face, FC_CHARSET, 0, &coverage) != FcResultMatch || coverage == nullptr) {
        continue;
      }
      detail::SortedFace entry;
      entry.file = reinterpret_cast<const char*>(file);
      if (FcPatternGetInteger(face, FC_INDEX, 0, &entry.face_index) != FcResultMatch) entry.face_index = 0;
      entry.coverage = coverage;
      answer->faces.push_back(std::move(entry));
    }
  }
  if (sorts.size() >= detail::FontconfigResults::kMaxEntries) sorts.clear();
  sorts.emplace(std::move(key), answer);
  return answer;
}

// One face of the sorted list, and the face once this object opened it.
struct Candidate {
  const detail::SortedFace* face = nullptr;  // in Impl::sorted
  std::unique_ptr<Font> font;
  bool unusable = false;  // Font::open failed: never tried again
};

}  // namespace

struct FontFallback::Impl {
  const Font* primary = nullptr;
  FontQuery query;
  bool sorted = false;  // the sorted list is fetched lazily: most texts never miss a character
  std::shared_ptr<const detail::SortedFaces> sorted_list;
  std::vector<Candidate> candidates;
  std::unordered_map<char32_t, const Font*> by_character;

  void sort_candidates() {
    sorted = true;
    std::vector<std::string> families = detail::split_family_list(query.family);
    if (families.empty()) families.push_back(primary->family_name());
    sorted_list = sorted_faces(query, families);
    if (!sorted_list) return;
    for (const detail::SortedFace& face : sorted_list->faces)
      candidates.push_back(Candidate{&face, nullptr, false});
  }

  const Font* search(char32_t character) {
    if (!sorted) sort_candidates();
    for (Candidate& candidate : candidates) {
      if (candidate.unusable ||
          FcCharSetHasChar(candidate.face->coverage, static_cast<FcChar32>(character)) == 0) {
        continue;
      }
      if (!candidate.font) {
        Result<Font> opened = Font::open(candidate.face->file, candidate.face->face_index);
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
