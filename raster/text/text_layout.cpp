// Text layout through FriBidi and HarfBuzz. Each line is split into runs of one face, one bidi level and
// one script (text_layout.h); each run goes into an hb_buffer as UTF-32 with the whole line as context
// (so clusters are indices into the line), is shaped with the requested features, and the glyph
// positions, which HarfBuzz gives in font units because the hb_font keeps its default scale of units_per_em (font_face_p.h), are scaled to user
// units and flipped to y down: origin = pen + offset, pen += advance (HarfBuzz manual, "Shaping and
// shape plans": x_advance/x_offset are in the font's scale; offsets are y up).
#include "curvescan/text/text_layout.h"

#include <locale.h>
#include <wctype.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <unordered_set>

#include "curvescan/text/utf8.h"
#include "font_face_p.h"
#include "shaping_p.h"

namespace curvescan {
namespace {

struct BufferDeleter {
  void operator()(hb_buffer_t* buffer) const noexcept { hb_buffer_destroy(buffer); }
};
using BufferPtr = std::unique_ptr<hb_buffer_t, BufferDeleter>;

hb_feature_t global_feature(std::uint32_t tag, std::uint32_t value) noexcept {
  return {tag, value, HB_FEATURE_GLOBAL_START, HB_FEATURE_GLOBAL_END};
}

// The features a run is shaped with: kerning and ligatures as the style asks, the caps feature when the
// run's face has it (`font_caps`), then the style's own features, which HarfBuzz lets win over the
// earlier ones for the same tag (hb_shape: "later features override earlier ones").
std::vector<hb_feature_t> run_features(const TextStyle& style, bool font_small_caps, bool font_caps_from_capitals) {
  std::vector<hb_feature_t> features{global_feature(font_feature_tag("kern"), style.kerning ? 1 : 0),
                                     global_feature(font_feature_tag("liga"), style.ligatures ? 1 : 0),
                                     global_feature(font_feature_tag("clig"), style.ligatures ? 1 : 0)};
  if (style.caps != CapsVariant::kNormal && font_small_caps) features.push_back(global_feature(font_feature_tag("smcp"), 1));
  if (style.caps == CapsVariant::kAllSmallCaps && font_caps_from_capitals) {
    features.push_back(global_feature(font_feature_tag("c2sc"), 1));
  }
  for (const FontFeature& feature : style.features) features.push_back(global_feature(feature.tag, feature.value));
  return features;
}

// Shapes characters [begin, end) of `line` with `face` (the whole line is HarfBuzz's context, so
// clusters are indices into the line) and appends its glyphs with the pen starting at x = pen_x user
// units on y = 0 (vertical: at y = pen_x on x = 0); returns the pen's position along the line after the
// run. `size` is the run's em size.
// The run is at bidi level `level` (odd: shaped right to left, HarfBuzz then returns its glyphs in visual
// order, left to right, and mirrors the mirrorable characters) and in `script`.
double place_run(const Font& face, std::u32string_view line, std::size_t begin, std::size_t end,
                 std::size_t line_start, std::uint8_t level, const detail::ShapeRequest& request, double size,
                 double pen_x, std::vector<PositionedGlyph>& glyphs, std::u32string& missing,
                 std::unordered_set<char32_t>& missing_seen, std::u32string_view original, hb_buffer_t* buffer) {
  const double scale = size / face.metrics().units_per_em;
  const std::vector<detail::ShapedGlyph>& shaped = detail::shape_run(face, line, begin, end, request, buffer);
  const bool vertical = request.direction == HB_DIRECTION_TTB;
  double pen_units = 0.0, pen_y = 0.0;  // font units, y up
  for (const detail::ShapedGlyph& glyph : shaped) {
    const std::size_t character_index = line_start + glyph.cluster;
    if (glyph.glyph == kNotdefGlyph && glyph.cluster < original.size()) {
      const char32_t character = original[glyph.cluster];
      // A set, not missing.find: a text of many distinct missing characters would be quadratic.
      if (missing_seen.insert(character).second) missing.push_back(character);
    }
    // Vertical (HB_DIRECTION_TTB): HarfBuzz's offsets go from the pen on the vertical line to the glyph's
    // horizontal origin (it subtracts the vertical origin), and y_advance is negative, down the line.
    // The pen starts at y = pen_x.
    const Point origin = vertical ? Point{(pen_units + glyph.x_offset) * scale, pen_x - (pen_y + glyph.y_offset) * scale}
                                  : Point{pen_x + (pen_units + glyph.x_offset) * scale, -(pen_y + glyph.y_offset) * scale};
    const double advance = vertical ? -glyph.y_advance * scale : glyph.x_advance * scale;
    glyphs.push_back({glyph.glyph, origin, character_index, &face, advance, level, size});
    pen_units += glyph.x_advance;
    pen_y += glyph.y_advance;
  }
  return vertical ? pen_x - pen_y * scale : pen_x + pen_units * scale;
}

// Case mapping for synthesized small capitals: the C.UTF-8 locale's towupper/towlower, which glibc
// fills from the Unicode character database (simple case mappings, UnicodeData.txt), whatever the
// process's own locale. Without that locale, ASCII only.
class CaseMapping {
 public:
  CaseMapping() : locale_(newlocale(LC_CTYPE_MASK, "C.UTF-8", static_cast<locale_t>(nullptr))) {}
  ~CaseMapping() {
    if (locale_ != static_cast<locale_t>(nullptr)) freelocale(locale_);
  }
  CaseMapping(const CaseMapping&) = delete;
  CaseMapping& operator=(const CaseMapping&) = delete;

  [[nodiscard]] char32_t upper(char32_t c) const noexcept {
    if (locale_ == static_cast<locale_t>(nullptr)) return c >= U'a' && c <= U'z' ? c - 32 : c;
    return static_cast<char32_t>(towupper_l(static_cast<wint_t>(c), locale_));
  }
  [[nodiscard]] char32_t lower(char32_t c) const noexcept {
    if (locale_ == static_cast<locale_t>(nullptr)) return c >= U'A' && c <= U'Z' ? c + 32 : c;
    return static_cast<char32_t>(towlower_l(static_cast<wint_t>(c), locale_));
  }

 private:
  locale_t locale_;
};

const CaseMapping& case_mapping() {
  static const CaseMapping mapping;
  return mapping;
}

// Combining marks and zero-width joiners belong to the character before them: they stay in its run
// when its face has them, so a base and its accent are shaped (and mark-positioned) by one face.
bool attaches_to_previous(char32_t character) noexcept {
  if (character == U'\u200C' || character == U'\u200D') return true;
  switch (hb_unicode_general_category(hb_unicode_funcs_get_default(), static_cast<hb_codepoint_t>(character))) {
    case HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK:
    case HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK:
    case HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK:
      return true;
    default:
      return false;
  }
}

// The script of every character of `line` for itemization (UAX #24): Common (spaces, digits,
// punctuation) and Inherited (combining marks) characters take the script of the character before them,
// those at the start the first real script of the line; a line without any is Common.
std::vector<hb_script_t> resolved_scripts(std::u32string_view line) {
  hb_unicode_funcs_t* unicode = hb_unicode_funcs_get_default();
  std::vector<hb_script_t> scripts(line.size(), HB_SCRIPT_COMMON);
  hb_script_t current = HB_SCRIPT_INVALID;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const hb_script_t script = hb_unicode_script(unicode, static_cast<hb_codepoint_t>(line[i]));
    if (script != HB_SCRIPT_COMMON && script != HB_SCRIPT_INHERITED && script != HB_SCRIPT_UNKNOWN) {
      if (current == HB_SCRIPT_INVALID) std::fill(scripts.begin(), scripts.begin() + static_cast<std::ptrdiff_t>(i), script);
      current = script;
    }
    scripts[i] = current == HB_SCRIPT_INVALID ? HB_SCRIPT_COMMON : current;
  }
  return scripts;
}

// The most attaching characters (marks, joiners) in a row that one hb_shape call gets. HarfBuzz 6 (Debian
// 12) takes time quadratic in the number of marks that follow one base (its mark-to-base attachment; the
// same marks without a base shape in linear time): 3*10^4 acute accents on one letter took 5.5 s. Past this
// many, the sequence is shaped in pieces of this many marks, each positioned by the font from the pen as if
// it had no base. No real text comes near: Unicode's Stream-Safe
// Text Format allows at most 30 non-starters in a row (UAX #15, section 13), and HarfBuzz itself stops
// reordering marks past 32 (HB_OT_SHAPE_MAX_COMBINING_MARKS).
constexpr std::size_t kMaxShapedMarks = 32;

// Which face draws each character of a line: the layout's one font, or fallback's choice.
struct FaceChooser {
  const Font* single = nullptr;
  FontFallback* fallback = nullptr;

  [[nodiscard]] const Font& primary() const noexcept { return single != nullptr ? *single : fallback->primary(); }
  [[nodiscard]] const Font& face_for(char32_t character, const Font* previous) const {
    if (single != nullptr) return *single;
    if (previous != nullptr && attaches_to_previous(character) && previous->glyph_for(character) != kNotdefGlyph) {
      return *previous;
    }
    const Font* face = fallback->face_for(character);
    return face != nullptr ? *face : fallback->primary();  // nowhere: the primary's .notdef
  }
};

// Characters [begin, end) of a line, shaped together.
struct LogicalRun {
  std::size_t begin = 0, end = 0;
  std::uint8_t level = 0;
  hb_script_t script = HB_SCRIPT_COMMON;
  const Font* face = nullptr;
  bool synthetic_small_caps = false;  // drawn as uppercase at kSyntheticSmallCapsScale of the size
  bool tab = false;                   // one U+0009, placed by tab_advance rather than shaped
};

// Tab stops every kTabSize advances of the space (CSS Text 3 section 4.2, `tab-size` initial value 8).
constexpr double kTabSize = 8.0;

// The advance of a tab that starts `from_start` from the start edge of its line (top of a vertical one):
// to the next tab stop, and past it to the one after when it is nearer than half a space (CSS Text 3
// section 4.2 says half a `ch`; the space is what the stops are measured in here).
double tab_advance(double from_start, double space) noexcept {
  return tab_stop_advance(from_start, kTabSize * space, 0.5 * space);
}

// The tabs of a right-to-left line, placed at zero width while the line was laid out left to right, get
// their advances measured from the line's start edge, its right end (CSS Text 3 section 4.2: tab stops are
// measured from the start edge of the block). A tab resolves to the paragraph level (UAX #9 rule L1), so
// everything on its right is what comes before it logically and is already laid out: the advances are
// settled from the right end leftwards, then every glyph moves right by the tabs on its left. Returns the
// line's new advance.
double place_right_to_left_tabs(std::vector<PositionedGlyph>& glyphs, std::size_t first_glyph,
                                const std::vector<std::size_t>& tab_glyphs,
                                const std::vector<double>& tab_spaces, double line_end) {
  std::vector<double> widths(tab_glyphs.size());
  double added_on_right = 0.0;
  for (std::size_t t = tab_glyphs.size(); t-- > 0;) {
    const double from_start = line_end - glyphs[tab_glyphs[t]].origin.x + added_on_right;
    widths[t] = tab_advance(from_start, tab_spaces[t]);
    added_on_right += widths[t];
  }
  double shift = 0.0;
  std::size_t next_tab = 0;
  for (std::size_t g = first_glyph; g < glyphs.size(); ++g) {
    glyphs[g].origin.x += shift;
    if (next_tab < tab_glyphs.size() && tab_glyphs[next_tab] == g) {
      glyphs[g].advance = widths[next_tab];
      shift += widths[next_tab++];
    }
  }
  return line_end + shift;
}

Result<TextLayout> layout_with(const FaceChooser& chooser, std::u32string_view text, Point origin,
                               const TextStyle& style) {
  if (!(style.size > 0.0 && style.size <= kMaxTextSize)) {
    return Error{ErrorKind::kInvalidArgument, "the font size must be a number in (0, " +
                                                  std::to_string(static_cast<int>(kMaxTextSize)) + "]"};
  }
  if (!origin.is_finite() || !std::isfinite(style.line_height) || style.line_height < 0.0) {
    return Error{ErrorKind::kInvalidArgument,
                 "the text origin and line height must be finite (line height >= 0)"};
  }
  if (text.size() > kMaxTextCharacters) {
    return Error{ErrorKind::kLimitExceeded, "the text has " + std::to_string(text.size()) +
                                                " characters, more than the limit of " +
                                                std::to_string(kMaxTextCharacters)};
  }
  const FontMetrics metrics = chooser.primary().metrics();
  TextLayout layout;
  layout.size = style.size;
  layout.scale = style.size / metrics.units_per_em;
  layout.ascent = metrics.ascender * layout.scale;
  layout.descent = -metrics.descender * layout.scale;
  layout.line_height = style.line_height > 0.0 ? style.line_height : metrics.line_height * layout.scale;
  layout.vertical = style.vertical;

  const BufferPtr buffer(hb_buffer_create());
  std::unordered_set<char32_t> missing_seen;
  std::size_t line_start = 0;
  for (std::size_t line_index = 0;; ++line_index) {
    const std::size_t newline = std::min(text.find(U'\n', line_start), text.size());
    std::u32string_view line = text.substr(line_start, newline - line_start);
    if (!line.empty() && line.back() == U'\r') line.remove_suffix(1);
    TextLine placed;
    placed.first_glyph = layout.glyphs.size();
    const BidiParagraph bidi = resolve_bidi(line, style.direction, style.bidi_override);
    placed.right_to_left = bidi.right_to_left;
    const std::vector<hb_script_t> scripts = resolved_scripts(line);
    // Logical runs: a new one at every change of face, level or script, and after kMaxShapedMarks
    // attaching characters in a row.
    std::vector<LogicalRun> runs;
    const Font* run_face = nullptr;
    std::size_t marks_in_run = 0;  // attaching characters in a row at the end of the current run
    // Synthesized small capitals are shaped from the uppercased line (`shaping_line`).
    std::u32string shaping_line;
    for (std::size_t i = 0; i < line.size(); ++i) {
      // A tab is white space of the primary face: no face's glyph for U+0009 is drawn (CSS Text 3 4.2).
      const bool tab = line[i] == U'\t';
      const Font* face = tab ? &chooser.primary() : &chooser.face_for(line[i], run_face);
      bool cut = false;
      if (attaches_to_previous(line[i])) {
        cut = ++marks_in_run > kMaxShapedMarks;
        if (cut) marks_in_run = 1;
      } else {
        marks_in_run = 0;
      }
      bool small = false;
      if (style.caps != CapsVariant::kNormal) {
        const char32_t upper = case_mapping().upper(line[i]);
        const bool lowercase = upper != line[i];
        const bool capital = style.caps == CapsVariant::kAllSmallCaps && case_mapping().lower(line[i]) != line[i];
        small = (lowercase && !detail::has_gsub_feature(*face, font_feature_tag("smcp"))) ||
                (capital && !detail::has_gsub_feature(*face, font_feature_tag("c2sc")));
        if (small && lowercase) {
          if (shaping_line.empty()) shaping_line = line;
          shaping_line[i] = upper;
        }
        // A mark takes the size of its base, so the two are shaped together.
        if (attaches_to_previous(line[i]) && !runs.empty() && runs.back().face == face) small = runs.back().synthetic_small_caps;
      }
      if (runs.empty() || cut || tab || runs.back().tab || face != run_face ||
          bidi.levels[i] != runs.back().level || scripts[i] != runs.back().script ||
          small != runs.back().synthetic_small_caps) {
        runs.push_back({i, i, bidi.levels[i], scripts[i], face, small, tab});
      }
      runs.back().end = i + 1;
      run_face = face;
    }
    std::vector<std::uint8_t> run_levels(runs.size());
    for (std::size_t r = 0; r < runs.size(); ++r) run_levels[r] = runs[r].level;
    double pen_x = 0.0;
    // A right-to-left line's tabs, in visual order, and the space each is measured in.
    std::vector<std::size_t> right_to_left_tabs;
    std::vector<double> right_to_left_tab_spaces;
    const bool tabs_after_line = placed.right_to_left && !style.vertical;
    for (const std::size_t r : visual_run_order(run_levels)) {
      const LogicalRun& run = runs[r];
      const std::size_t first_glyph = layout.glyphs.size();
      if (run.tab) {
        // Drawn as the space glyph (no outline), advancing to the next tab stop.
        const GlyphId space = run.face->glyph_for(U' ');
        const double space_advance = run.face->advance(space) * style.size / run.face->metrics().units_per_em;
        if (tabs_after_line) {
          right_to_left_tabs.push_back(layout.glyphs.size());
          right_to_left_tab_spaces.push_back(space_advance);
        }
        // Measured from the start of the line, which on a left-to-right or vertical line is where the pen
        // started; a right-to-left line's tabs are measured when the line is complete.
        const double advance = tabs_after_line ? 0.0 : tab_advance(pen_x, space_advance);
        const Point pen = style.vertical ? Point{0.0, pen_x} : Point{pen_x, 0.0};
        layout.glyphs.push_back(
            {space, pen, line_start + run.begin, run.face, advance, run.level, style.size});
        pen_x += advance;
        layout.runs.push_back({first_glyph, 1, run.face});
        continue;
      }
      const std::vector<hb_feature_t> features =
          run_features(style, detail::has_gsub_feature(*run.face, font_feature_tag("smcp")),
                       detail::has_gsub_feature(*run.face, font_feature_tag("c2sc")));
      const hb_direction_t direction = style.vertical       ? HB_DIRECTION_TTB
                                       : run.level % 2 == 1 ? HB_DIRECTION_RTL
                                                            : HB_DIRECTION_LTR;
      const detail::ShapeRequest request{direction, run.script, features};
      const double size = run.synthetic_small_caps ? style.size * kSyntheticSmallCapsScale : style.size;
      pen_x = place_run(*run.face, shaping_line.empty() ? line : std::u32string_view(shaping_line), run.begin,
                        run.end, line_start, run.level, request, size, pen_x, layout.glyphs,
                        layout.missing_characters, missing_seen, line, buffer.get());
      layout.runs.push_back({first_glyph, layout.glyphs.size() - first_glyph, run.face});
    }
    if (!right_to_left_tabs.empty()) {
      pen_x = place_right_to_left_tabs(layout.glyphs, placed.first_glyph, right_to_left_tabs,
                                       right_to_left_tab_spaces, pen_x);
    }
    placed.glyph_count = layout.glyphs.size() - placed.first_glyph;
    placed.advance = pen_x;
    // Start and end are the line's own: the start of a right-to-left line is its right end.
    TextAnchor anchor = style.anchor;
    if (placed.right_to_left && !style.vertical && anchor != TextAnchor::kMiddle) {
      anchor = anchor == TextAnchor::kStart ? TextAnchor::kEnd : TextAnchor::kStart;
    }
    const double anchor_shift = anchor == TextAnchor::kStart    ? 0.0
                                : anchor == TextAnchor::kMiddle ? -0.5 * placed.advance
                                                                : -placed.advance;
    // Vertical lines (vertical-rl) follow each other leftwards; the anchor acts along the line.
    const double line_offset = static_cast<double>(line_index) * layout.line_height;
    placed.origin = style.vertical ? Point{origin.x - line_offset, origin.y + anchor_shift}
                                   : Point{origin.x + anchor_shift, origin.y + line_offset};
    for (std::size_t g = placed.first_glyph; g < layout.glyphs.size(); ++g) {
      layout.glyphs[g].origin += placed.origin.to_vec();
    }
    layout.lines.push_back(placed);
    if (newline == text.size()) break;
    line_start = newline + 1;
  }
  return layout;
}

}  // namespace

double tab_stop_advance(double from_start, double interval, double min_gap) noexcept {
  if (!(interval > 0.0) || !std::isfinite(from_start)) return 0.0;
  double stop = (std::floor(from_start / interval) + 1.0) * interval;
  if (stop - from_start < min_gap) stop += interval;
  return stop - from_start;
}

Rect TextLayout::line_box() const noexcept {
  if (lines.empty()) return {};
  if (vertical) {
    // Each line one line height wide, centred on its vertical line, as long as its advance.
    Rect box{lines.front().origin.x, lines.front().origin.y, lines.front().origin.x, lines.front().origin.y};
    for (const TextLine& line : lines) {
      box.include({line.origin.x - 0.5 * line_height, line.origin.y});
      box.include({line.origin.x + 0.5 * line_height, line.origin.y + line.advance});
    }
    return box;
  }
  Rect box{lines.front().origin.x, lines.front().origin.y - ascent, lines.front().origin.x,
           lines.front().origin.y + descent};
  for (const TextLine& line : lines) {
    box.include({line.origin.x, line.origin.y - ascent});
    box.include({line.origin.x + line.advance, line.origin.y + descent});
  }
  return box;
}

Result<TextLayout> layout_text(const Font& font, std::u32string_view text, Point origin,
                               const TextStyle& style) {
  return layout_with(FaceChooser{&font, nullptr}, text, origin, style);
}

Result<TextLayout> layout_text(FontFallback& fonts, std::u32string_view text, Point origin,
                               const TextStyle& style) {
  return layout_with(FaceChooser{nullptr, &fonts}, text, origin, style);
}

Affine glyph_to_user(const Font& face, const TextLayout& layout, const PositionedGlyph& glyph) noexcept {
  // The glyph's em size in every face: each face's units scale by size / its own units_per_em (for the
  // primary face at the layout's size this is layout.scale, computed the same way).
  const double s = (glyph.size > 0.0 ? glyph.size : layout.size) / face.metrics().units_per_em;
  // Font units (y up) -> user units (y down) at the glyph's origin.
  return Affine{s, 0.0, 0.0, -s, glyph.origin.x, glyph.origin.y};
}

Status append_text_outlines(const Font& font, const TextLayout& layout, PathBuilder& builder) {
  for (const PositionedGlyph& glyph : layout.glyphs) {
    const Font& face = glyph.font != nullptr ? *glyph.font : font;
    CURVESCAN_PROPAGATE(face.append_glyph(glyph.glyph, glyph_to_user(face, layout, glyph), builder));
  }
  return Status::ok();
}

namespace {

template <typename Fonts>
Result<Path> text_path_with(Fonts& fonts, const Font& primary, std::string_view utf8, Point origin,
                            const TextStyle& style) {
  const Result<std::u32string> text = decode_utf8(utf8);
  if (!text) return text.error();
  const Result<TextLayout> layout = layout_text(fonts, *text, origin, style);
  if (!layout) return layout.error();
  PathBuilder builder;
  CURVESCAN_PROPAGATE(append_text_outlines(primary, *layout, builder));
  return builder.build();
}

}  // namespace

Result<Path> text_path(const Font& font, std::string_view utf8, Point origin, const TextStyle& style) {
  return text_path_with(font, font, utf8, origin, style);
}

Result<Path> text_path(FontFallback& fonts, std::string_view utf8, Point origin, const TextStyle& style) {
  return text_path_with(fonts, fonts.primary(), utf8, origin, style);
}

}  // namespace curvescan
