// Text layout: a string shaped by HarfBuzz into positioned glyphs, and their outlines appended to a
// Path — the API an SVG <text> element needs (SVG 1.1 chapter 10: x/y give the start of the baseline,
// font-size is the em size in user units, text-anchor aligns by the advance width).
//
// Shaping is HarfBuzz's (hb_shape with the font's GSUB/GPOS, or its legacy 'kern' table when it has no
// GPOS kerning), so kerning, ligatures, mark positioning and the complex scripts HarfBuzz supports come
// from the font. Each line is a paragraph of the Unicode Bidirectional Algorithm (bidi.h, UAX #9): its
// characters get embedding levels, the line is cut into runs of one level, one face and one script
// (Unicode Script property, UAX #24; Common and Inherited characters take the script of the run they
// are in), each run is shaped with its script and its direction (odd level: right-to-left, which also
// makes HarfBuzz mirror "(" into ")"), and the runs are placed left to right in the visual order of
// rule L2. There is no line wrapping: lines break only at U+000A (a CR before it is dropped).
//
// Font fallback (font_fallback.h): layout_text with a FontFallback splits each line into runs by face —
// every character goes to the primary face when it has a glyph for it, else to the face fallback finds,
// a combining mark or joiner staying with the face of the character before it when that face has it —
// shapes each run with its own face (HarfBuzz sees the whole line as context) and lays the runs out in
// sequence, each face scaled to the same em size.
//
// Small capitals (TextStyle::caps) come from the face's 'smcp'/'c2sc' features when it has them, else
// are synthesized per character (runs are also cut where synthesis starts or stops). Shaped runs are
// cached per face (raster/text/shaping_p.h), so repeated strings are shaped once.
//
// Coordinates: user units, y down (canvas convention). A glyph's origin is its point on the baseline.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "curvescan/curves/point.h"
#include "curvescan/curves/rect.h"
#include "curvescan/raster/path.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/status.h"
#include "curvescan/text/bidi.h"
#include "curvescan/text/font.h"
#include "curvescan/text/font_fallback.h"

namespace curvescan {

/// Largest font size (em, user units) layout accepts: beyond it the outlines of a single glyph exceed
/// the largest canvas (limits.h, kMaxImageDimension = 32767) anyway.
inline constexpr double kMaxTextSize = 32767.0;
/// Largest number of characters one layout accepts (about a book chapter); keeps a runaway input from
/// building gigabytes of outlines.
inline constexpr std::size_t kMaxTextCharacters = std::size_t{1} << 20;

/// SVG text-anchor (SVG 1.1 section 10.9.1): which point of each line's advance lies at the origin x.
/// Start and end follow the line's direction: the start of a right-to-left line is its right end.
enum class TextAnchor { kStart, kMiddle, kEnd };

/// An OpenType feature applied to the whole text (CSS Fonts 4 section 7.12, font-feature-settings): its
/// four-letter tag and value (0 off, 1 on, n > 1 the n-th alternate).
struct FontFeature {
  std::uint32_t tag = 0;
  std::uint32_t value = 1;
};

/// The tag of four ASCII characters ("smcp"), packed as OpenType does (big-endian, HB_TAG).
[[nodiscard]] constexpr std::uint32_t font_feature_tag(std::string_view four) noexcept {
  std::uint32_t tag = 0;
  for (std::size_t i = 0; i < 4; ++i) tag = tag << 8 | static_cast<unsigned char>(i < four.size() ? four[i] : ' ');
  return tag;
}

/// CSS Fonts 4 section 6.6 font-variant-caps, the values that a font without the feature can still
/// show: small capitals from the font's 'smcp' (and 'c2sc') feature when it has one, else synthesized
/// (section 6.6 and 3.8 font-synthesis-small-caps): the lowercase letters (all letters for
/// kAllSmallCaps) drawn as uppercase at kSyntheticSmallCapsScale of the size.
enum class CapsVariant { kNormal, kSmallCaps, kAllSmallCaps };
/// The size of synthesized small capitals relative to the font size: 0.7, as Blink and WebKit
/// (CSS Fonts 4 leaves the ratio to the user agent).
inline constexpr double kSyntheticSmallCapsScale = 0.7;

struct TextStyle {
  double size = 16.0;  ///< em size in user units (CSS font-size), (0, kMaxTextSize]
  TextAnchor anchor = TextAnchor::kStart;
  bool kerning = true;       ///< OpenType 'kern' feature (GPOS or the legacy kern table)
  bool ligatures = true;     ///< OpenType 'liga' and 'clig' features
  double line_height = 0.0;  ///< baseline-to-baseline distance; 0: the font's (FontMetrics) at size
  /// Each line's base direction (UAX #9 paragraph direction; CSS `direction` when forced).
  TextDirection direction = TextDirection::kAuto;
  /// Every character at the base direction's level, no implicit reordering (CSS `unicode-bidi:
  /// bidi-override`): a right-to-left override draws the characters right to left as they come.
  bool bidi_override = false;
  CapsVariant caps = CapsVariant::kNormal;
  /// Vertical lines (CSS Writing Modes 3, vertical-rl with text-orientation: upright): every run shaped
  /// top to bottom with HarfBuzz's vertical direction (HB_DIRECTION_TTB), so glyphs get the font's
  /// vertical advances (vmtx; HarfBuzz's fallback without one: ascender - descender), vertical origins
  /// (vhea/VORG; fallback: half the horizontal advance, the ascender) and vertical alternates ('vert'
  /// and 'vrt2', which HarfBuzz applies for this direction). The origin is the top of the first line;
  /// glyphs are centred on the line; PositionedGlyph::advance is the downward advance and TextLine::advance
  /// the line's length; later lines stand one line height to the left; the anchor acts along the line.
  bool vertical = false;
  /// Features applied after kerning, ligatures and caps, so that an explicit setting wins (CSS Fonts 4
  /// section 7.2, "Feature precedence": font-feature-settings comes last).
  std::vector<FontFeature> features;
};

struct PositionedGlyph {
  GlyphId glyph = kNotdefGlyph;
  Point origin;                     ///< on the baseline, user units
  std::size_t character_index = 0;  ///< index in the decoded text of the first character it draws
  const Font* font = nullptr;       ///< the face it comes from (nullptr: the font given to append)
  double advance = 0.0;             ///< the pen's horizontal move after it (shaped, kerning included), user units
  std::uint8_t bidi_level = 0;      ///< UAX #9 level of its characters: odd = right-to-left
  /// Its em size, user units: TextStyle::size, or kSyntheticSmallCapsScale of it for a synthesized small
  /// capital.
  double size = 0.0;
};

/// A run of consecutive glyphs of one line drawn from one face.
struct FontRun {
  std::size_t first_glyph = 0;
  std::size_t glyph_count = 0;
  const Font* font = nullptr;
};

struct TextLine {
  std::size_t first_glyph = 0;
  std::size_t glyph_count = 0;
  Point origin;          ///< the pen's start on this line's baseline, after anchoring
  double advance = 0.0;  ///< sum of the glyph advances (kerning included), user units
  bool right_to_left = false;  ///< the line's resolved base direction (TextStyle::direction)
};

struct TextLayout {
  std::vector<PositionedGlyph> glyphs;
  std::vector<TextLine> lines;
  /// Runs of one face, one bidi level and one script, in visual order (left to right) within each line;
  /// empty lines have none. A sequence of more
  /// than 32 combining marks or joiners in a row is also cut into runs of 32, each shaped on its own
  /// (text_layout.cpp, kMaxShapedMarks): marks past the 32nd are positioned without their base.
  std::vector<FontRun> runs;
  /// Characters drawn as .notdef, each once, in order of first appearance: those the font has no glyph
  /// for, or with fallback, those no installed face has a glyph for.
  std::u32string missing_characters;
  double size = 0.0;         ///< the em size, user units (TextStyle::size)
  double scale = 0.0;        ///< the font's (primary face's) units -> user units: size / units_per_em
  double ascent = 0.0;       ///< the font's ascender at this size (> 0), user units
  double descent = 0.0;      ///< the font's descender at this size, as a positive distance
  double line_height = 0.0;  ///< baseline-to-baseline distance used
  bool vertical = false;     ///< TextStyle::vertical

  /// The union of the lines' boxes: advance wide, from ascent above to descent below each baseline
  /// (vertical: advance tall and one line height wide, centred on each line).
  /// The layout extent a text box is sized by (ink may stick out: an italic overhang, a tall accent).
  [[nodiscard]] Rect line_box() const noexcept;
};

/// Shapes `text` with `font` at `style`, the first baseline starting at `origin`. kInvalidArgument for a
/// size outside (0, kMaxTextSize], a non-finite origin or line height; kLimitExceeded beyond
/// kMaxTextCharacters. An empty text gives one empty line.
[[nodiscard]] Result<TextLayout> layout_text(const Font& font, std::u32string_view text, Point origin,
                                             const TextStyle& style);

/// layout_text with per-character fallback: runs by face as described above, the vertical metrics
/// (ascent, descent, line height) the primary face's. Same errors as layout_text.
[[nodiscard]] Result<TextLayout> layout_text(FontFallback& fonts, std::u32string_view text, Point origin,
                                             const TextStyle& style);

/// Sets the lines of a horizontal layout as one block of text, each line aligned at the start of its own
/// direction: the block is as wide as its widest line and starts at the leftmost line's left end; a
/// left-to-right line starts at the block's left edge and a right-to-left one ends at its right edge. This
/// is CSS Text 3 `text-align: start` with every line a bidi paragraph of its own (CSS Writing Modes 3,
/// `unicode-bidi: plaintext`), and how pango lays out a paragraph of mixed lines; layout_text alone
/// anchors each line at the origin by its own direction, which puts a right-to-left line after a
/// left-to-right one to the left of it. A vertical layout, or one whose lines all have one direction, is
/// left as it is (its lines already share their start).
void align_lines_at_start(TextLayout& layout) noexcept;

/// The advance of a tab (CSS Text 3 section 4.2, "Tab Character Size") whose start is `from_start` from
/// the start edge of its line, with tab stops every `interval` from that edge: to the next stop, or to the
/// one after it when the next is nearer than `min_gap` (CSS Text 3: 0.5ch). An `interval` that is not
/// positive gives 0 (`tab-size: 0` draws tabs as nothing).
[[nodiscard]] double tab_stop_advance(double from_start, double interval, double min_gap) noexcept;

/// The mapping of `glyph` (of face `face`) from font units, y up, to user units, y down: scaled to the
/// glyph's size (PositionedGlyph::size, or the layout's) by the face's own units per em, at its origin.
[[nodiscard]] Affine glyph_to_user(const Font& face, const TextLayout& layout,
                                   const PositionedGlyph& glyph) noexcept;

/// Appends the outline of every glyph of `layout` to `builder` — each glyph from its own face
/// (PositionedGlyph::font, or `font` where that is null) scaled to its size — each glyph's contours
/// closed, to be filled with FillRule::kNonZero.
[[nodiscard]] Status append_text_outlines(const Font& font, const TextLayout& layout, PathBuilder& builder);

/// decode_utf8 (utf8.h), layout_text and append_text_outlines in one call: the Path of `utf8` at
/// `origin`. Fails with the first error of the three.
[[nodiscard]] Result<Path> text_path(const Font& font, std::string_view utf8, Point origin,
                                     const TextStyle& style);
/// The same with per-character fallback.
[[nodiscard]] Result<Path> text_path(FontFallback& fonts, std::string_view utf8, Point origin,
                                     const TextStyle& style);

}  // namespace curvescan
