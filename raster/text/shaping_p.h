// One run of text shaped by HarfBuzz, through a bounded cache of shaped runs kept per face.
//
// Shaping is the costly step of text layout, and documents repeat themselves: chart labels, the same
// word in many <tspan>s, a long sequence of combining marks cut into equal pieces (text_layout.cpp). A
// run's glyphs depend only on the face, the characters of the run, the characters HarfBuzz looks at
// around it (at most HB_BUFFER_CONTEXT_LENGTH = 5 on each side: HarfBuzz manual, "hb_buffer_add_utf32"),
// the direction, the script and the features. They do not depend on the font size: the hb_font keeps its
// default scale of units_per_em and sets no ppem (font_face_p.h), so HarfBuzz works in font units,
// unhinted, and the caller scales. The language is HarfBuzz's default for the process, the same for
// every call. So the cache key is (face, context and characters, direction, script, features), the face
// being the Font that owns the cache.
//
// Bounds: a run longer than kMaxCachedRunCharacters is shaped but not kept (a long run seldom repeats);
// the cache holds at most kShapeCacheBudget characters and glyphs together and forgets the least
// recently used run first.
#pragma once

#include <hb.h>

#include <cstddef>
#include <cstdint>
#include <list>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "curvescan/text/font.h"

namespace curvescan::detail {

/// One glyph of a shaped run, in font units (y up), as hb_glyph_info_t / hb_glyph_position_t give it.
struct ShapedGlyph {
  GlyphId glyph = kNotdefGlyph;
  std::uint32_t cluster = 0;  ///< index in the line of its first character (HarfBuzz's cluster)
  std::int32_t x_advance = 0, y_advance = 0, x_offset = 0, y_offset = 0;
};

inline constexpr std::size_t kMaxCachedRunCharacters = 1024;
inline constexpr std::size_t kShapeCacheBudget = std::size_t{1} << 18;

class ShapeCache {
 public:
  /// The cached glyphs for `key`, now the most recently used, or nullptr.
  [[nodiscard]] const std::vector<ShapedGlyph>* find(const std::u32string& key);
  /// Keeps `glyphs` under `key` (when it fits the bounds), forgetting the least recently used runs.
  void insert(std::u32string key, const std::vector<ShapedGlyph>& glyphs);
  [[nodiscard]] std::size_t size() const noexcept { return entries_.size(); }

 private:
  struct Entry {
    std::u32string key;
    std::vector<ShapedGlyph> glyphs;
  };
  std::list<Entry> entries_;                                                   // most recently used first
  std::unordered_map<std::u32string_view, std::list<Entry>::iterator> index_;  // views into entries_' keys
  std::size_t used_ = 0;
};

/// What a run is shaped with besides its characters.
struct ShapeRequest {
  hb_direction_t direction = HB_DIRECTION_LTR;
  hb_script_t script = HB_SCRIPT_COMMON;
  std::span<const hb_feature_t> features;  ///< global features (start 0, end unbounded)
};

/// Shapes characters [begin, end) of `line` (the rest of the line is HarfBuzz's context; clusters are
/// indices into the line) with `font`, reusing `buffer`, through the font's cache. The glyphs are in
/// HarfBuzz's output order: visual order, left to right, for a horizontal run. The reference stays valid
/// until the next call with the same font.
[[nodiscard]] const std::vector<ShapedGlyph>& shape_run(const Font& font, std::u32string_view line,
                                                        std::size_t begin, std::size_t end,
                                                        const ShapeRequest& request, hb_buffer_t* buffer);

/// Whether the face's GSUB table lists the feature `tag` (for any script or language), remembered per
/// face: decides between a font's own small capitals and synthesized ones (text_layout.cpp).
[[nodiscard]] bool has_gsub_feature(const Font& font, std::uint32_t tag);

}  // namespace curvescan::detail
