// Shaping runs through HarfBuzz with a per-face cache (shaping_p.h).
#include <hb-ot.h>

#include <algorithm>
#include <array>

#include "font_face_p.h"
#include "shaping_p.h"

namespace curvescan::detail {

const std::vector<ShapedGlyph>* ShapeCache::find(const std::u32string& key) {
  const auto found = index_.find(std::u32string_view(key));
  if (found == index_.end()) return nullptr;
  entries_.splice(entries_.begin(), entries_, found->second);  // iterators and the key's view stay valid
  return &found->second->glyphs;
}

void ShapeCache::insert(std::u32string key, const std::vector<ShapedGlyph>& glyphs) {
  const std::size_t cost = key.size() + glyphs.size();
  if (cost > kShapeCacheBudget || index_.contains(std::u32string_view(key))) return;
  while (used_ + cost > kShapeCacheBudget && !entries_.empty()) {
    const Entry& oldest = entries_.back();
    used_ -= oldest.key.size() + oldest.glyphs.size();
    index_.erase(std::u32string_view(oldest.key));
    entries_.pop_back();
  }
  entries_.push_front({std::move(key), glyphs});
  index_.emplace(std::u32string_view(entries_.front().key), entries_.begin());
  used_ += cost;
}

namespace {

// The context HarfBuzz reads on each side of a run (HB_BUFFER_CONTEXT_LENGTH in hb-buffer.hh; not public).
constexpr std::size_t kContextLength = 5;

// The cache key: the request, the context before, the run, the context after, each part preceded by its
// length, so that no two different requests give the same key.
std::u32string cache_key(std::u32string_view line, std::size_t begin, std::size_t end,
                         const ShapeRequest& request) {
  const std::size_t before = std::min(begin, kContextLength);
  const std::size_t after = std::min(line.size() - end, kContextLength);
  std::u32string key;
  key.reserve(8 + 2 * request.features.size() + before + (end - begin) + after);
  key.push_back(static_cast<char32_t>(request.direction));
  key.push_back(static_cast<char32_t>(request.script));
  key.push_back(static_cast<char32_t>(request.features.size()));
  for (const hb_feature_t& feature : request.features) {
    key.push_back(static_cast<char32_t>(feature.tag));
    key.push_back(static_cast<char32_t>(feature.value));
  }
  key.push_back(static_cast<char32_t>(before));
  key.append(line.substr(begin - before, before));
  key.push_back(static_cast<char32_t>(end - begin));
  key.append(line.substr(begin, end - begin));
  key.append(line.substr(end, after));
  return key;
}

}  // namespace

const std::vector<ShapedGlyph>& shape_run(const Font& font, std::u32string_view line, std::size_t begin,
                                          std::size_t end, const ShapeRequest& request, hb_buffer_t* buffer) {
  const Font::Impl& impl = font.impl();
  const bool cacheable = end - begin <= kMaxCachedRunCharacters;
  std::u32string key;
  if (cacheable) {
    key = cache_key(line, begin, end, request);
    if (const std::vector<ShapedGlyph>* cached = impl.shape_cache.find(key)) {
      // Clusters are stored relative to the run's start: the same run elsewhere in a line hits too.
      impl.shaped.assign(cached->begin(), cached->end());
      for (ShapedGlyph& glyph : impl.shaped) glyph.cluster += static_cast<std::uint32_t>(begin);
      return impl.shaped;
    }
  }
  hb_buffer_clear_contents(buffer);
  static_assert(sizeof(char32_t) == sizeof(std::uint32_t));
  hb_buffer_add_utf32(buffer, reinterpret_cast<const std::uint32_t*>(line.data()),
                      static_cast<int>(line.size()), static_cast<unsigned>(begin),
                      static_cast<int>(end - begin));
  hb_buffer_set_direction(buffer, request.direction);
  hb_buffer_set_script(buffer, request.script);
  hb_buffer_guess_segment_properties(buffer);  // only the language is left: the process's default
  hb_shape(impl.hb_font, buffer, request.features.data(), static_cast<unsigned>(request.features.size()));
  unsigned count = 0;
  const hb_glyph_info_t* infos = hb_buffer_get_glyph_infos(buffer, &count);
  const hb_glyph_position_t* positions = hb_buffer_get_glyph_positions(buffer, &count);
  impl.shaped.resize(count);
  for (unsigned i = 0; i < count; ++i) {
    impl.shaped[i] = {infos[i].codepoint,     infos[i].cluster,      positions[i].x_advance,
                      positions[i].y_advance, positions[i].x_offset, positions[i].y_offset};
  }
  if (cacheable) {
    std::vector<ShapedGlyph> relative = impl.shaped;
    for (ShapedGlyph& glyph : relative) glyph.cluster -= static_cast<std::uint32_t>(begin);
    impl.shape_cache.insert(std::move(key), relative);
  }
  return impl.shaped;
}

bool has_gsub_feature(const Font& font, std::uint32_t tag) {
  const Font::Impl& impl = font.impl();
  if (const auto known = impl.gsub_features.find(tag); known != impl.gsub_features.end())
    return known->second;
  bool found = false;
  std::array<hb_tag_t, 64> tags{};
  for (unsigned start = 0;; start += static_cast<unsigned>(tags.size())) {
    unsigned count = static_cast<unsigned>(tags.size());
    const unsigned total =
        hb_ot_layout_table_get_feature_tags(impl.hb_face, HB_OT_TAG_GSUB, start, &count, tags.data());
    found = found || std::find(tags.begin(), tags.begin() + count, tag) != tags.begin() + count;
    if (found || count == 0 || start + count >= total) break;
  }
  impl.gsub_features.emplace(tag, found);
  return found;
}

}  // namespace curvescan::detail
