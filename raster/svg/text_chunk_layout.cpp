// One text chunk laid out (text_layout_job.h): bidi over the chunk with unicode-bidi's controls, runs
// shaped by HarfBuzz (text_layout.h) and placed in visual order with letter- and word-spacing, dx/dy and
// rotate per character, textLength, then anchoring and each glyph's frame on its line or its path.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "curvescan/text/bidi.h"
#include "curvescan/text/cursive_script.h"
#include "curvescan/text/text_layout.h"
#include "text_layout_job.h"
#include "vertical_orientation.h"

namespace curvescan::svg::detail {
namespace {

std::string code_point_name(char32_t c) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "U+%04X", static_cast<unsigned>(c));
  return buffer;
}

// The bidi control characters that make unicode-bidi of an element a bidi embedding or isolate (CSS
// Writing Modes 3 section 2.4.2, "Bidi control codes injection table").
struct BidiControls {
  std::u32string open, close;
};
BidiControls bidi_controls(UnicodeBidi value, bool right_to_left) {
  switch (value) {
    case UnicodeBidi::kNormal:
      return {};
    case UnicodeBidi::kEmbed:
      return {right_to_left ? U"\u202B" : U"\u202A", U"\u202C"};
    case UnicodeBidi::kIsolate:
      return {right_to_left ? U"\u2067" : U"\u2066", U"\u2069"};
    case UnicodeBidi::kBidiOverride:
      return {right_to_left ? U"\u202E" : U"\u202D", U"\u202C"};
    case UnicodeBidi::kIsolateOverride:
      return {right_to_left ? U"\u2067\u202E" : U"\u2066\u202D", U"\u202C\u2069"};
    case UnicodeBidi::kPlaintext:
      return {U"\u2068", U"\u2069"};
  }
  return {};
}

// Combining marks and selectors that belong to the character before them (the blocks of combining
// diacritical marks, variation selectors): they take its orientation in vertical text.
bool is_combining(char32_t c) noexcept {
  return (c >= 0x0300 && c <= 0x036F) || (c >= 0x1AB0 && c <= 0x1AFF) || (c >= 0x1DC0 && c <= 0x1DFF) ||
         (c >= 0x20D0 && c <= 0x20FF) || (c >= 0xFE00 && c <= 0xFE0F) || (c >= 0xFE20 && c <= 0xFE2F) ||
         (c >= 0xE0100 && c <= 0xE01EF) || c == 0x200D;
}

bool is_word_separator(char32_t c) noexcept {
  // CSS Text 3 8.1: word-separator characters (the space, no-break space and the other scripts' spaces).
  return c == U' ' || c == U'\u00A0' || c == U'\u1361' || c == U'\U00010100' || c == U'\U00010101' ||
         c == U'\U0001039F' || c == U'\U0001091F';
}

// Whether `c` stands upright in vertical text with text-orientation: mixed (CSS Writing Modes 3 5.1):
// its Vertical_Orientation (UAX #50) is U or Tu, or Tr — a Tr character (brackets, the long vowel mark)
// is shaped upright with the font's 'vert' alternate, which HarfBuzz's vertical direction applies; when
// the font has none, it stays upright instead of falling back to the rotated glyph. Every other
// character is turned sideways.
bool is_upright(char32_t c) noexcept {
  return vertical_orientation(c) != VerticalOrientation::kRotated;
}

}  // namespace

// Height of `baseline` above the alphabetic baseline in font units (SVG 1.1 10.9.2; values from the
// font's metrics, font.h; hanging and mathematical as fractions of the ascender, as resvg and Chrome
// do without a BASE table).
double baseline_height(Baseline baseline, const FontMetrics& m) noexcept {
  switch (baseline) {
    case Baseline::kAuto:
    case Baseline::kAlphabetic:
      return 0.0;
    case Baseline::kMiddle:
      return 0.5 * m.x_height;
    case Baseline::kCentral:
      return 0.5 * (m.ascender + m.descender);
    case Baseline::kHanging:
      return 0.8 * m.ascender;
    case Baseline::kMathematical:
      return 0.5 * m.ascender;
    case Baseline::kTextBeforeEdge:
      return m.ascender;
    case Baseline::kTextAfterEdge:
    case Baseline::kIdeographic:
      return m.descender;
  }
  return 0.0;
}

// SVG 2 11.8.3 (simplified to what SVG 1.1 defines): the chunk's characters are ordered by the bidi
// algorithm, cut into runs of one style and one level, each run shaped (text_layout.h), and every glyph
// gets its pen position along the chunk with letter- and word-spacing, dx and dy.
void TextLayoutJob::lay_out_chunk(const Chunk& chunk) {
  const std::size_t first_glyph = glyphs_.size();
  const std::size_t n = chunk.end - chunk.begin;
  // Bidi over the chunk, with the controls of unicode-bidi injected at element boundaries; the paragraph
  // direction is the <text> element's `direction` (SVG 1.1 10.7.4).
  const std::vector<std::size_t>& bidi_elements = bidi_elements_[chunk_index_];
  std::vector<std::u32string> opens(bidi_elements.empty() ? 0 : n + 1),
      closes(bidi_elements.empty() ? 0 : n + 1);
  for (const std::size_t e : bidi_elements) {
    const TextProperties& text = c_.styles[c_.elements[e].style].text;
    const std::size_t begin = std::max(element_begin_[e], chunk.begin),
                      end = std::min(element_end_[e], chunk.end);
    if (begin >= end) continue;
    const BidiControls controls = bidi_controls(text.unicode_bidi, text.right_to_left);
    opens[begin - chunk.begin] += controls.open;
    closes[end - chunk.begin] = controls.close + closes[end - chunk.begin];
  }
  std::u32string bidi_text;
  std::vector<std::size_t> bidi_index(n);
  if (bidi_elements.empty()) {
    bidi_text = characters_.substr(chunk.begin, n);
    for (std::size_t i = 0; i < n; ++i) bidi_index[i] = i;
  } else {
    for (std::size_t i = 0; i <= n; ++i) {
      bidi_text += closes[i];
      if (i == n) break;
      bidi_text += opens[i];
      bidi_index[i] = bidi_text.size();
      bidi_text.push_back(characters_[chunk.begin + i]);
    }
  }
  const bool right_to_left = c_.styles[0].text.right_to_left;
  const BidiParagraph bidi =
      resolve_bidi(bidi_text, right_to_left ? TextDirection::kRightToLeft : TextDirection::kLeftToRight);

  // Runs of one shaping style, one level and, on a vertical line, one orientation (a combining mark
  // keeps its base's). Elements that differ only in what does not change the glyphs (fill, stroke,
  // decoration, positions) share a run, so that shaping — kerning, ligatures, joining — goes on across
  // their boundary, as browsers shape "T<tspan fill=...>e</tspan>" (CSS Text 3, "Shaping Across
  // Element Boundaries": shaping is not broken where the formatting does not change).
  struct Run {
    std::size_t begin, end;
    std::uint8_t level;
    bool upright;
  };
  const auto same_shaping = [&](std::size_t a, std::size_t b) {
    if (a == b) return true;
    const ComputedStyle& x = c_.styles[a];
    const ComputedStyle& y = c_.styles[b];
    const FontVariants& u = x.text.font_variants;
    const FontVariants& v = y.text.font_variants;
    const auto spacing = [&](const std::optional<Length>& length, std::size_t style) {
      return length ? resolve(*length, style) : 0.0;
    };
    const std::vector<FontFeature> fu = u.features(), fv = v.features();
    const bool same_features = std::equal(
        fu.begin(), fu.end(), fv.begin(), fv.end(),
        [](const FontFeature& p, const FontFeature& q) { return p.tag == q.tag && p.value == q.value; });
    return x.font_size == y.font_size && fallback_for(a) == fallback_for(b) &&
           spacing(x.text.letter_spacing, a) == spacing(y.text.letter_spacing, b) &&
           spacing(x.text.word_spacing, a) == spacing(y.text.word_spacing, b) &&
           spacing(u.kerning_length, a) == spacing(v.kerning_length, b) && u.kerning == v.kerning &&
           u.caps == v.caps && same_features;
  };
  // A tspan that positions its own characters (x, y, dx, dy or rotate; it or an ancestor below the
  // <text>) still starts a run of its own, as it did before runs crossed elements: only boundaries of
  // elements that change the paint alone are shaped across.
  const auto positioned = [&](std::size_t e) {
    for (; e != kNoElement && c_.elements[e].parent != kNoElement; e = c_.elements[e].parent) {
      for (const char* name : {"x", "y", "dx", "dy", "rotate"})
        if (c_.elements[e].node.attribute(name)) return true;
    }
    return false;
  };
  const auto positions_at_boundary = [&](std::size_t before, std::size_t after) {
    return before != after && (positioned(before) || positioned(after));
  };
  std::vector<Run> runs;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t level = bidi.levels[bidi_index[i]];
    const std::size_t style = c_.elements[character_element_[chunk.begin + i]].style;
    const char32_t c = characters_[chunk.begin + i];
    // text-orientation of the character's element (CSS Writing Modes 3 5.1): mixed follows UAX #50.
    const TextOrientation orientation = c_.styles[style].text.orientation;
    const bool upright = vertical_ && !sideways_ && orientation != TextOrientation::kSideways &&
                         (orientation == TextOrientation::kUpright ||
                          (is_combining(c) && !runs.empty() ? runs.back().upright : is_upright(c)));
    if (runs.empty() || level != runs.back().level || upright != runs.back().upright ||
        !same_shaping(style, c_.elements[character_element_[chunk.begin + runs.back().begin]].style) ||
        positions_at_boundary(character_element_[chunk.begin + i - 1], character_element_[chunk.begin + i])) {
      runs.push_back({i, i, level, upright});
    }
    runs.back().end = i + 1;
  }
  std::vector<std::uint8_t> levels(runs.size());
  for (std::size_t r = 0; r < runs.size(); ++r) levels[r] = runs[r].level;

  double pen = 0.0;
  std::optional<std::size_t> spaced_glyph;  // the last glyph given letter-spacing, and how much
  double spaced_amount = 0.0;
  for (const std::size_t r : visual_run_order(levels)) {
    const Run& run = runs[r];
    const std::size_t style_index = c_.elements[character_element_[chunk.begin + run.begin]].style;
    const ComputedStyle& style = c_.styles[style_index];
    FontFallback* fonts = fallback_for(style_index);
    if (fonts == nullptr || !(style.font_size > 0.0)) continue;
    const FontVariants& variants = style.text.font_variants;
    // SVG 1.1 10.11: a kerning length switches kerning off and adds the length between characters, as
    // letter-spacing does.
    const double letter_spacing =
        (style.text.letter_spacing ? resolve(*style.text.letter_spacing, style_index) : 0.0) +
        (variants.kerning_length ? resolve(*variants.kerning_length, style_index) : 0.0);
    const double word_spacing =
        style.text.word_spacing ? resolve(*style.text.word_spacing, style_index) : 0.0;
    TextStyle text_style;
    text_style.size = style.font_size;
    text_style.direction = run.level % 2 == 1 ? TextDirection::kRightToLeft : TextDirection::kLeftToRight;
    text_style.bidi_override = true;  // the run is at one level already
    // CSS Text 3 8.2: with letter-spacing, optional ligatures are not used (they would get no spacing).
    // Letters of cursive scripts get no letter-spacing (cursive_script.h), so a run that holds them —
    // a right-to-left run of Arabic, since bidi levels cut runs — keeps its ligatures.
    const std::size_t begin = chunk.begin + run.begin;
    const std::u32string_view run_text = std::u32string_view(characters_).substr(begin, run.end - run.begin);
    const bool cursive = std::any_of(run_text.begin(), run_text.end(), is_cursive_script);
    text_style.ligatures = letter_spacing == 0.0 || cursive;
    text_style.kerning = variants.kerning && !variants.kerning_length;
    text_style.caps = variants.caps;
    text_style.features = variants.features();
    // Upright characters of a vertical line are shaped top to bottom (HarfBuzz's vertical direction:
    // the font's vertical advances and origins, 'vert' alternates; text_layout.h).
    text_style.vertical = run.upright;
    Result<TextLayout> layout = layout_text(*fonts, run_text, {0.0, 0.0}, text_style);
    if (!layout) {
      diagnostics_.warnings.push_back("<text> run not drawn: " + layout.error().message);
      continue;
    }
    const Font* primary = &fonts->primary();
    for (const char32_t missing : layout->missing_characters) {
      if (warned_missing_.emplace(primary, missing).second) {
        diagnostics_.warnings.push_back("'" + primary->family_name() + "' has no glyph for " +
                                        code_point_name(missing) + "; drawn as the font's .notdef glyph");
      }
    }
    const FontMetrics metrics = primary->metrics();
    const double scale = style.font_size / metrics.units_per_em;
    // The layout anchors a right-to-left line at its right end: positions relative to its own start.
    const double line_start = layout->lines.empty() ? 0.0 : layout->lines.front().origin.x;
    // Offsets from the pen, along the line and across it: a vertical layout's run down its y axis.
    const auto along = [&](const PositionedGlyph& glyph) {
      return run.upright ? glyph.origin.y : glyph.origin.x - line_start;
    };
    double run_pen = 0.0;     // with spacing
    double shaped_pen = 0.0;  // the layout's own pen
    const Font* fallback_metrics_font = nullptr;  // the fallback face whose metrics are at hand
    FontMetrics fallback_metrics;
    for (const PositionedGlyph& glyph : layout->glyphs) {
      PlacedGlyph placed;
      placed.glyph = glyph.glyph;
      placed.font = glyph.font != nullptr ? glyph.font : primary;
      placed.character = begin + glyph.character_index;
      placed.element = character_element_[placed.character];
      placed.x = pen + run_pen;
      placed.offset_x = along(glyph) - shaped_pen;
      shaped_pen += glyph.advance;
      // Upright glyphs: the user-space x offset of the glyph's origin from the line (centred on it).
      placed.offset_y = run.upright ? glyph.origin.x : glyph.origin.y;
      placed.advance = glyph.advance;
      placed.size = glyph.size > 0.0 ? glyph.size : style.font_size;
      placed.upright = run.upright;
      // Spacing goes after every glyph that advances (marks do not: CSS Text 3 8.2 counts typographic
      // character units) except the letters of cursive scripts, whose joins it would break (CSS Text 4,
      // #cursive-tracking; the spaces and punctuation between their words are still spaced); word
      // spacing after word separators.
      // A tab gets none: it ends at a tab stop (set_tab_stops).
      const bool tab = characters_[placed.character] == U'\t';
      if (placed.advance != 0.0 && letter_spacing != 0.0 && !tab &&
          !is_cursive_script(characters_[placed.character])) {
        placed.advance += letter_spacing;
        placed.spacing += letter_spacing;
        spaced_glyph = glyphs_.size();
        spaced_amount = letter_spacing;
      }
      if (is_word_separator(characters_[placed.character])) {
        placed.advance += word_spacing;
        placed.spacing += word_spacing;
      }
      // Alignment: the element's alignment-baseline, else the dominant baseline (SVG 1.1 10.9.2), whose
      // "auto" is central in vertical text (CSS Writing Modes 3 4.2). The alignment baseline places the
      // element's box by its first available font; on the dominant baseline each glyph sits by its own
      // face's baseline table (CSS Inline 3 section 2: glyphs of different fonts align their own
      // baselines of the dominant type), so a fallback face's sideways glyphs in vertical text are
      // centred by its own ascent and descent, as browsers centre them.
      const TextProperties& text = c_.styles[c_.elements[placed.element].style].text;
      const bool by_alignment = text.alignment_baseline != Baseline::kAuto;
      Baseline baseline = by_alignment ? text.alignment_baseline : text.dominant_baseline;
      if (vertical_ && !sideways_ && baseline == Baseline::kAuto) baseline = Baseline::kCentral;
      double height = baseline_height(baseline, metrics) * scale;
      if (!by_alignment && placed.font != primary && baseline != Baseline::kAuto) {
        if (placed.font != fallback_metrics_font) {
          fallback_metrics_font = placed.font;
          fallback_metrics = placed.font->metrics();
        }
        height =
            baseline_height(baseline, fallback_metrics) * style.font_size / fallback_metrics.units_per_em;
      }
      placed.baseline_y = height + baseline_shift_[placed.element];
      run_pen += placed.advance;
      glyphs_.push_back(placed);
    }
    pen += run_pen;
  }
  // CSS Text 3 8.2: "letter-spacing must not be applied at the beginning or at the end of a line". The
  // spacing goes after (right of) each glyph, so only the rightmost spaced glyph of the chunk — the end of
  // a left-to-right line, the start of a right-to-left one — has it at an edge: it is taken back there,
  // and the chunk is anchored by its letters, not by a trailing gap.
  if (spaced_glyph && std::all_of(glyphs_.begin() + static_cast<std::ptrdiff_t>(*spaced_glyph) + 1,
                                  glyphs_.end(), [](const PlacedGlyph& g) { return g.advance == 0.0; })) {
    glyphs_[*spaced_glyph].advance -= spaced_amount;
    glyphs_[*spaced_glyph].spacing -= spaced_amount;
  }
  line_advance_ += set_tab_stops(first_glyph);
  // dx, dy accumulate in logical order (SVG 2 11.8.3 step 4); rotate per character.
  // Along the line and across it: on a vertical line dy moves along it and dx across it (the line's
  // local y axis points to user-space -x; on a sideways-lr line, up the page, to +x).
  // On a path an absolute x (y in vertical text) is a new distance along it for its character (SVG 1.1
  // 10.13.3: "a new absolute offset along the path"), the characters after it following; the other
  // coordinate is not a position on the path and is ignored. A character's pen position is its first
  // glyph's.
  std::vector<double> natural_x;
  if (chunk.text_path != kNoElement) {
    natural_x.assign(n, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t g = first_glyph; g < glyphs_.size(); ++g) {
      double& x = natural_x[glyphs_[g].character - chunk.begin];
      if (!(x <= glyphs_[g].x)) x = glyphs_[g].x;
    }
  }
  std::vector<double> shift_x(n), shift_y(n);
  double sx = 0.0, sy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::optional<double>& along = vertical_ ? abs_y_[chunk.begin + i] : abs_x_[chunk.begin + i];
    if (!natural_x.empty() && along && std::isfinite(natural_x[i]))
      sx = *along - chunk.anchor_x - natural_x[i];
    const double dx = rel_x_[chunk.begin + i].value_or(0.0), dy = rel_y_[chunk.begin + i].value_or(0.0);
    sx += vertical_ ? line_turn_ * dy : dx;
    sy += vertical_ ? -line_turn_ * dx : dy;
    shift_x[i] = sx;
    shift_y[i] = sy;
  }
  for (std::size_t g = first_glyph; g < glyphs_.size(); ++g) {
    PlacedGlyph& glyph = glyphs_[g];
    glyph.x += shift_x[glyph.character - chunk.begin];
    glyph.shift_y = shift_y[glyph.character - chunk.begin];
    glyph.rotate = rotate_[glyph.character].value_or(0.0);
  }
  if (vertical_) {
    pen_.x -= line_turn_ * sy;
  } else {
    pen_.y += sy;
  }
  apply_text_lengths(chunk, first_glyph);
  finish_chunk(chunk, first_glyph);
}

// Preserved tabs (white-space pre, pre-wrap, break-spaces; CSS Text 3 section 4.2, "Tab Character Size"):
// each tab advances to the next tab stop, stops every tab-size from the start edge of the line box — the
// left end of a left-to-right line, the right end of a right-to-left one, the top of a vertical line —
// and to the stop after that when the next is nearer than 0.5ch. tab-size is the <text>'s (the block
// container's): a number of advances of the space of its first available font at its font size, with
// its letter- and word-spacing, or a length. The layout of each run placed its tabs from the run's own
// start; here they are set from the line's: `line_advance_` is the advance of the line's chunks before
// this one (SVG 2 lays the line out before x, y, dx, dy and textLength move its characters, so a tab
// after an absolute x is measured along the laid-out line, as Firefox and Chrome draw it). A tab is at
// the paragraph's level (UAX #9 rule L1), so the glyphs before it on the start side are all before it
// logically. Returns the chunk's advance.
double TextLayoutJob::set_tab_stops(std::size_t first_glyph) {
  const auto is_tab = [&](const PlacedGlyph& glyph) { return characters_[glyph.character] == U'\t'; };
  double advance = 0.0;
  for (std::size_t g = first_glyph; g < glyphs_.size(); ++g) advance += glyphs_[g].advance;
  if (std::none_of(glyphs_.begin() + static_cast<std::ptrdiff_t>(first_glyph), glyphs_.end(), is_tab))
    return advance;
  const ComputedStyle& block = c_.styles[0];
  FontFallback* fonts = fallback_for(0);
  double interval = 0.0, min_gap = 0.0;
  if (fonts != nullptr && block.font_size > 0.0) {
    const Font& font = fonts->primary();
    const double scale = block.font_size / font.metrics().units_per_em;
    // CSS Text 3 4.2: the space's advance "including its associated letter-spacing and word-spacing".
    const double space = font.advance(font.glyph_for(U' ')) * scale +
                         (block.text.letter_spacing ? resolve(*block.text.letter_spacing, 0) : 0.0) +
                         (block.text.word_spacing ? resolve(*block.text.word_spacing, 0) : 0.0);
    interval = block.text.tab_size_length ? resolve(*block.text.tab_size_length, 0)
                                          : block.text.tab_size_spaces * space;
    min_gap = 0.5 * font.advance(font.glyph_for(U'0')) * scale;  // CSS Values 4: 1ch, the advance of "0"
  }
  const bool from_right = block.text.right_to_left;
  double from_start = line_advance_;
  const auto place = [&](PlacedGlyph& glyph) {
    if (is_tab(glyph)) {
      glyph.advance = tab_stop_advance(from_start, interval, min_gap);
      glyph.spacing = 0.0;
    }
    from_start += glyph.advance;
  };
  if (from_right) {
    for (std::size_t g = glyphs_.size(); g-- > first_glyph;) place(glyphs_[g]);
  } else {
    for (std::size_t g = first_glyph; g < glyphs_.size(); ++g) place(glyphs_[g]);
  }
  // The pens again, one after the other in visual order.
  double pen = first_glyph < glyphs_.size() ? glyphs_[first_glyph].x : 0.0;
  for (std::size_t g = first_glyph; g < glyphs_.size(); ++g) {
    glyphs_[g].x = pen;
    pen += glyphs_[g].advance;
  }
  return from_start - line_advance_;
}

// textLength and lengthAdjust (SVG 1.1 10.5, SVG 2 11.8.3 step 5, "resolve text length"): the advance of
// an element's characters is made textLength, innermost elements first. "spacing" spreads the difference
// evenly over the gaps between the element's units — its typographic characters outside descendants
// that have a textLength of their own, and each such descendant as one block, whose length stays the
// one it was given — taken in visual order, so that a right-to-left run (Arabic, joined) opens up from
// its right end as it is read; "spacingAndGlyphs" scales the glyphs' advances and outlines along the
// line too. Characters of the chunk after the element move by the difference, and with "spacing" by one
// step more, so that the element is followed by the gap that is between its units.
//
// SVG 2 applies textLength before the absolute x and y, over an element's whole content; here each text
// chunk is measured on its own, so an element whose characters an absolute position splits into several
// chunks is given its textLength in each chunk (where SVG 2's later absolute positions undo the shift of
// every chunk start, which is the same when its other characters are inside descendants with a
// textLength, as in <text textLength><tspan x textLength/><tspan x textLength/></text>).
//
// Cost: each element visits only its own glyphs (found by binary search in the chunk's glyphs sorted by
// character), and the move of everything after it is recorded once in a Fenwick tree over the chunk's
// characters (Fenwick, "A new data structure for cumulative frequency tables", 1994) rather than applied
// to every later glyph: O(glyphs x nesting depth x log characters) for the chunk, where a pass over the
// chunk per element was quadratic in the number of elements with a textLength.
void TextLayoutJob::apply_text_lengths(const Chunk& chunk, std::size_t first_glyph) {
  const std::vector<std::size_t>& elements = length_elements_[chunk_index_];
  if (elements.empty()) return;
  const std::size_t n = chunk.end - chunk.begin;
  // moved[i]: the sum of the differences of the elements that end at or before chunk character i - 1.
  std::vector<double> moved(n + 1, 0.0);
  const auto add_after = [&](std::size_t end_offset, double delta) {
    for (std::size_t i = end_offset + 1; i <= n; i += i & (~i + 1)) moved[i] += delta;
  };
  const auto moved_at = [&](std::size_t offset) {
    double sum = 0.0;
    for (std::size_t i = offset + 1; i > 0; i -= i & (~i + 1)) sum += moved[i];
    return sum;
  };
  // The outermost element with a textLength already applied over each chunk character (kNoElement when
  // none): the blocks an ancestor's spacing moves whole.
  std::vector<std::size_t> resolved_in(n, kNoElement);
  std::vector<std::size_t> by_character(glyphs_.size() - first_glyph);
  for (std::size_t k = 0; k < by_character.size(); ++k) by_character[k] = first_glyph + k;
  std::stable_sort(by_character.begin(), by_character.end(),
                   [&](std::size_t a, std::size_t b) { return glyphs_[a].character < glyphs_[b].character; });
  std::vector<std::size_t> visual;  // the element's glyphs in visual order (their order in glyphs_)
  for (auto it = elements.rbegin(); it != elements.rend(); ++it) {
    const std::size_t e = *it;
    const ElementRange& element = c_.elements[e];
    const std::size_t begin = std::max(element_begin_[e], chunk.begin),
                      end = std::min(element_end_[e], chunk.end);
    if (begin >= end) continue;
    const std::optional<std::vector<double>> target = length_list(
        element.node, "textLength", context_.horizontal(), c_.styles[element.style].font_size, diagnostics_);
    if (!target || target->size() != 1 || !((*target)[0] >= 0.0)) {
      if (target)
        diagnostics_.warnings.push_back("<" + std::string(local_name_of(element.node)) +
                                        "> ignoring textLength: not one non-negative length");
      continue;
    }
    const auto first =
        std::lower_bound(by_character.begin(), by_character.end(), begin,
                         [&](std::size_t g, std::size_t c) { return glyphs_[g].character < c; });
    auto last = first;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (; last != by_character.end() && glyphs_[*last].character < end; ++last) {
      const PlacedGlyph& glyph = glyphs_[*last];
      const double x = glyph.x + moved_at(glyph.character - chunk.begin);
      lo = std::min(lo, x);
      hi = std::max(hi, x + glyph.advance);
    }
    if (!(hi > lo)) continue;
    const double delta = (*target)[0] - (hi - lo);
    const bool glyphs_too =
        std::string_view(element.node.attribute("lengthAdjust").value()) == "spacingAndGlyphs";
    const double factor = (*target)[0] / (hi - lo);
    // How far the characters of the chunk after the element move: the difference, and with "spacing" one
    // more step (below).
    double after = delta;
    if (glyphs_too) {
      for (auto g = first; g != last; ++g) {
        PlacedGlyph& glyph = glyphs_[*g];
        const double before = moved_at(glyph.character - chunk.begin);
        glyph.x = lo + (glyph.x + before - lo) * factor - before;
        glyph.advance *= factor;
        glyph.spacing *= factor;
        glyph.offset_x *= factor;
        glyph.scale_x *= factor;
      }
    } else {
      // Number the units in visual order: a glyph starts a new one unless it is in the same resolved
      // descendant as the glyph before, or belongs to the same character, or does not advance (a mark).
      visual.assign(first, last);
      std::sort(visual.begin(), visual.end());
      std::vector<std::size_t> unit(visual.size(), 0);
      std::size_t units = 0;
      for (std::size_t k = 0; k < visual.size(); ++k) {
        const PlacedGlyph& glyph = glyphs_[visual[k]];
        const std::size_t block = resolved_in[glyph.character - chunk.begin];
        bool joins_previous = false;
        if (k > 0) {
          const PlacedGlyph& previous = glyphs_[visual[k - 1]];
          const std::size_t previous_block = resolved_in[previous.character - chunk.begin];
          joins_previous = block != kNoElement
                               ? block == previous_block
                               : previous_block == kNoElement &&
                                     (glyph.character == previous.character || glyph.advance == 0.0);
        }
        if (k == 0 || !joins_previous) ++units;
        unit[k] = units - 1;
      }
      if (units > 1) {
        const double step = delta / static_cast<double>(units - 1);
        for (std::size_t k = 0; k < visual.size(); ++k)
          glyphs_[visual[k]].x += step * static_cast<double>(unit[k]);
        // SVG 2's loop adds the step after every unit, the last one too, and ends with a shift of units
        // steps; what follows the element keeps that gap (Chrome's SvgTextLayoutAlgorithm moves the rest
        // of the chunk by that shift, and resvg draws it so), as letter-spacing puts space after each
        // character.
        after = step * static_cast<double>(units);
      }
    }
    for (std::size_t i = begin; i < end; ++i) resolved_in[i - chunk.begin] = e;
    add_after(end - chunk.begin, after);
  }
  for (std::size_t g = first_glyph; g < glyphs_.size(); ++g)
    glyphs_[g].x += moved_at(glyphs_[g].character - chunk.begin);
}

// Anchoring (SVG 1.1 10.9.1) and the frame of every glyph: on a line, or on the chunk's path.
void TextLayoutJob::finish_chunk(const Chunk& chunk, std::size_t first_glyph) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t g = first_glyph; g < glyphs_.size(); ++g) {
    lo = std::min(lo, glyphs_[g].x);
    hi = std::max(hi, glyphs_[g].x + glyphs_[g].advance);
  }
  if (!(hi >= lo)) lo = hi = 0.0;
  TextAnchor anchor = c_.styles[c_.elements[character_element_[chunk.begin]].style].text_anchor;
  // Start and end are the paragraph direction's: the start of right-to-left text is its right end.
  if (c_.styles[0].text.right_to_left && anchor != TextAnchor::kMiddle) {
    anchor = anchor == TextAnchor::kStart ? TextAnchor::kEnd : TextAnchor::kStart;
  }
  // With start on left-to-right text the pen starts at the chunk's x (the natural layout, lo = 0 unless
  // a dx moved the first glyph).
  const bool ltr_start = anchor == TextAnchor::kStart && !c_.styles[0].text.right_to_left;
  const double shift = ltr_start                       ? 0.0
                       : anchor == TextAnchor::kStart  ? -lo
                       : anchor == TextAnchor::kMiddle ? -0.5 * (lo + hi)
                                                       : -hi;
  const PathMeasure* path =
      chunk.text_path != kNoElement && paths_[chunk.text_path] ? &*paths_[chunk.text_path] : nullptr;
  // SVG 1.1 10.13.2: method="stretch" bends each glyph's outline along the path (text_element.cpp).
  const bool stretch =
      path != nullptr &&
      std::string_view(c_.elements[chunk.text_path].node.attribute("method").value()) == "stretch";
  // rotate turns a typographic character (a base and its combining marks: one HarfBuzz cluster, so one
  // `character`) as a whole about its current text position (SVG 2 11.8.3, the rotate attribute: the
  // value of the cluster's first character applies to all its glyphs), which is the pen of its first
  // advancing glyph. On a path each glyph has its own frame, and turns about its own pen.
  if (path == nullptr) {
    for (std::size_t g = first_glyph; g < glyphs_.size();) {
      std::size_t end = g + 1;
      while (end < glyphs_.size() && glyphs_[end].character == glyphs_[g].character) ++end;
      std::size_t base = g;
      while (base < end && glyphs_[base].advance == 0.0) ++base;
      if (base == end) base = g;
      for (std::size_t k = g; k < end; ++k) glyphs_[k].pivot_dx = glyphs_[base].x - glyphs_[k].x;
      g = end;
    }
  }
  for (std::size_t g = first_glyph; g < glyphs_.size(); ++g) {
    PlacedGlyph& glyph = glyphs_[g];
    glyph.x += shift + chunk.anchor_x;
    if (path == nullptr) {
      // A vertical line: the horizontal layout turned by 90 degrees about the chunk's start, so that it
      // runs down the page with the tops of sideways glyphs to the right (by -90 degrees on a
      // sideways-lr line: up the page, tops to the left).
      glyph.frame = vertical_ ? Affine::translate(chunk.y, 0.0) *
                                    Affine{0.0, line_turn_, -line_turn_, 0.0, 0.0, 0.0} *
                                    Affine::translate(0.0, glyph.shift_y)
                              : Affine::translate(0.0, chunk.y + glyph.shift_y);
      continue;
    }
    // On a path (SVG 1.1 10.13.3): the glyph's midpoint along its advance is placed on the path at that
    // distance, the glyph rotated to the path's tangent there; a glyph whose midpoint is off the path is
    // not drawn. dy moves perpendicular to the path. The midpoint is half the glyph's own advance past its
    // start: letter- and word-spacing are space added between characters (SVG 1.1 10.11), after the
    // glyph, not part of it — as WebKit and resvg place glyphs on a path.
    const double half = 0.5 * (glyph.advance - glyph.spacing);
    const double middle = glyph.x + half;
    if (middle < 0.0 || middle > path->length()) {
      glyph.hidden = true;
      continue;
    }
    const PathMeasure::Sample sample = path->at(middle);
    const Affine rotation{sample.tangent.x, sample.tangent.y, -sample.tangent.y, sample.tangent.x, 0.0, 0.0};
    glyph.frame = Affine::translate(sample.point.x, sample.point.y) * rotation *
                  Affine::translate(-half, glyph.shift_y);
    if (stretch && !glyph.upright) {
      glyph.stretch_path = path;
      glyph.stretch_frame = Affine::translate(middle - half, glyph.shift_y);
    }
    glyph.x = 0.0;  // the frame holds the position
  }
  if (path == nullptr) {
    (vertical_ ? pen_.y : pen_.x) = (vertical_ ? line_turn_ : 1.0) * (chunk.anchor_x + shift + hi);
  } else {
    // After a textPath the text continues from the end point of the path, wherever the text on it ended
    // (SVG 2 11.8.3, "Position on path", step 5.2.1.3: path_end is the path's end point minus the
    // position of the first character after it; Chrome places it so). A side="right" path ends where
    // the referenced path starts, since it is walked backwards.
    pen_ = path->at(path->length()).point;
  }
}

}  // namespace curvescan::svg::detail
