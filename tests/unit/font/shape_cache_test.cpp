// The cache of shaped runs (raster/text/shaping_p.h): a layout through a face whose cache is warm gives
// exactly the layout of a fresh face (the plain path, nothing cached), runs that differ only in their
// context are kept apart, and the cache forgets the least recently used run first within its budget.
#include <catch2/catch.hpp>
#include <string>

#include "curvescan/text/text_layout.h"
#include "font_files.h"
#include "text/font_face_p.h"
#include "text/shaping_p.h"

using namespace curvescan;

namespace {

Font open_font(const char* file) {
  Result<Font> font = Font::open(file);
  REQUIRE(font.is_ok());
  return std::move(font).value();
}

TextLayout lay_out(const Font& font, std::u32string_view text) {
  Result<TextLayout> layout = layout_text(font, text, {10.0, 20.0}, {});
  REQUIRE(layout.is_ok());
  return std::move(layout).value();
}

// Exact equality: the cache must return HarfBuzz's own integers, so every derived number is identical.
void check_identical(const TextLayout& a, const TextLayout& b) {
  REQUIRE(a.glyphs.size() == b.glyphs.size());
  for (std::size_t i = 0; i < a.glyphs.size(); ++i) {
    CHECK(a.glyphs[i].glyph == b.glyphs[i].glyph);
    CHECK(a.glyphs[i].origin.x == b.glyphs[i].origin.x);
    CHECK(a.glyphs[i].origin.y == b.glyphs[i].origin.y);
    CHECK(a.glyphs[i].advance == b.glyphs[i].advance);
    CHECK(a.glyphs[i].character_index == b.glyphs[i].character_index);
  }
}

}  // namespace

TEST_CASE("shape cache: a warm cache gives the layout of a fresh face", "[font][layout][cache]") {
  // Repeated words in two directions, Arabic (whose joining forms depend on the neighbours), and marks
  // past the 32 that one run takes (so equal pieces of marks are cached runs too).
  std::u32string text = U"lorem \u05e9\u05dc\u05d5\u05dd lorem \u0628\u0628\u0628 \u0628 lorem a";
  text.append(70, U'\u0301');
  text += U" lorem";
  const Font warm = open_font(kDejaVuSansFile);
  const TextLayout first = lay_out(warm, text);
  const TextLayout second = lay_out(warm, text);  // every run now comes from the cache
  const Font fresh = open_font(kDejaVuSansFile);
  check_identical(second, first);
  check_identical(second, lay_out(fresh, text));
  CHECK(warm.impl().shape_cache.size() > 0);
}

TEST_CASE("shape cache: the same characters in another context are shaped again", "[font][layout][cache]") {
  const Font font = open_font(kDejaVuSansFile);
  hb_buffer_t* buffer = hb_buffer_create();
  const hb_feature_t none[1] = {};
  const detail::ShapeRequest request{HB_DIRECTION_RTL, HB_SCRIPT_ARABIC,
                                     std::span<const hb_feature_t>(none, 0)};
  // U+0628 BEH after another beh joins it (final form); after a space it stands alone (isolated form).
  const std::u32string joined = U"\u0628\u0628", alone = U" \u0628";
  const GlyphId final_form = detail::shape_run(font, joined, 1, 2, request, buffer).at(0).glyph;
  const GlyphId isolated_form = detail::shape_run(font, alone, 1, 2, request, buffer).at(0).glyph;
  CHECK(final_form != isolated_form);
  CHECK(isolated_form == font.glyph_for(U'\u0628'));  // the cmap maps the character to its isolated form
  // Asked again, each context gets its own answer from the cache.
  CHECK(detail::shape_run(font, joined, 1, 2, request, buffer).at(0).glyph == final_form);
  CHECK(detail::shape_run(font, alone, 1, 2, request, buffer).at(0).glyph == isolated_form);
  CHECK(font.impl().shape_cache.size() == 2);
  hb_buffer_destroy(buffer);
}

TEST_CASE("shape cache: bounded, least recently used forgotten first", "[font][cache]") {
  detail::ShapeCache cache;
  // Entries of a quarter of the budget each (key characters count against it, no glyphs here).
  const std::size_t quarter = detail::kShapeCacheBudget / 4;
  const auto key = [&](char32_t c) { return std::u32string(quarter, c); };
  cache.insert(key(U'a'), {});
  cache.insert(key(U'b'), {});
  cache.insert(key(U'c'), {});
  cache.insert(key(U'd'), {});
  CHECK(cache.size() == 4);
  REQUIRE(cache.find(key(U'a')) != nullptr);  // now the most recently used: 'b' is the oldest
  cache.insert(key(U'e'), {});
  CHECK(cache.size() == 4);
  CHECK(cache.find(key(U'b')) == nullptr);
  CHECK(cache.find(key(U'a')) != nullptr);
  CHECK(cache.find(key(U'e')) != nullptr);
  // An entry larger than the whole budget is not kept, and evicts nothing.
  cache.insert(std::u32string(detail::kShapeCacheBudget + 1, U'z'), {});
  CHECK(cache.size() == 4);
}
