// SVG <text> layout (text_element.h).
#include "text_element.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include "css/syntax.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/svg/length.h"
#include "curvescan/svg/number.h"
#include "curvescan/svg/path_data.h"
#include "curvescan/text/bidi.h"
#include "curvescan/text/text_layout.h"
#include "curvescan/text/utf8.h"
#include "text_path_measure.h"
#include "text_whitespace.h"

namespace curvescan::svg::detail {
namespace {

std::string_view local_name_of(const pugi::xml_node& node) {
  const std::string_view name = node.name();
  const std::size_t colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

// Attributes and properties of SVG text this renderer does not implement: noted, not errors.
constexpr std::array<std::string_view, 2> kUnsupported{"glyph-orientation-horizontal", "glyph-orientation-vertical"};

constexpr std::size_t kNoElement = static_cast<std::size_t>(-1);

// An element of the text's content and the characters its character data spans.
struct ElementRange {
  pugi::xml_node node;
  std::size_t style = 0;
  std::size_t parent = kNoElement;
  std::size_t first_fragment = 0;
  std::size_t end_fragment = 0;
  bool text_path = false;
};

class TextCollector {
 public:
  TextCollector(const ChildStyle& child_style, const TextContext& context, Diagnostics& diagnostics)
      : child_style_(child_style), context_(context), diagnostics_(diagnostics) {}

  std::vector<ComputedStyle> styles;
  std::vector<TextFragment> fragments;
  std::vector<std::size_t> fragment_element;
  std::vector<ElementRange> elements;  // pre-order: descendants after their ancestors

  void collect_element(const pugi::xml_node& node, std::size_t style, std::size_t parent, int depth,
                       bool text_path) {
    note_unsupported(node);
    const std::size_t index = elements.size();
    elements.push_back({node, style, parent, fragments.size(), fragments.size(), text_path});
    for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
      if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) {
        Result<std::u32string> decoded = decode_utf8(child.value());
        if (!decoded) {
          diagnostics_.warnings.push_back("<text> character data skipped: " + decoded.error().message);
          continue;
        }
        fragments.push_back({std::move(decoded).value(), styles[style].preserve_spaces});
        fragment_element.push_back(index);
        continue;
      }
      if (child.type() != pugi::node_element) continue;
      const std::string_view name = local_name_of(child);
      // textPath is a child of <text> only (SVG 1.1 10.13; a textPath inside a textPath or a tspan is
      // not rendered, as in browsers).
      const bool is_text_path = name == "textPath" && depth == 0;
      if (name == "altGlyph") {
        // SVG 1.1 10.14: when the alternate glyphs cannot be used (SVG fonts are not supported), the
        // altGlyph is rendered as a tspan.
        note("<altGlyph> glyph substitution is not supported; its text is drawn as in a <tspan>");
      }
      if (name == "tref") {
        collect_tref(child, style, index, depth);
      } else if (name == "tspan" || name == "a" || name == "altGlyph" || is_text_path) {
        if (depth >= context_.max_depth) {
          diagnostics_.warnings.push_back("<" + std::string(name) + "> nested more than " +
                                          std::to_string(context_.max_depth) + " deep; its text is skipped");
          continue;
        }
        ComputedStyle child_style = child_style_(child, styles[style]);
        if (!child_style.display) continue;
        styles.push_back(std::move(child_style));
        collect_element(child, styles.size() - 1, index, depth + 1, is_text_path);
      } else if (name == "textPath") {
        note("<textPath> outside <text> is not supported; its text is not drawn");
      }
    }
    elements[index].end_fragment = fragments.size();
  }

  // <tref> (SVG 1.1 10.6): the character data of the referenced element — all of it, inside descendants
  // too, in document order — as if it were the tref's own, styled and positioned as a <tspan> would be.
  // A reference to nothing renders nothing (with a warning).
  void collect_tref(const pugi::xml_node& tref, std::size_t parent_style, std::size_t parent, int depth) {
    if (depth >= context_.max_depth) {
      diagnostics_.warnings.push_back("<tref> nested more than " + std::to_string(context_.max_depth) +
                                      " deep; its text is skipped");
      return;
    }
    pugi::xml_attribute href = tref.attribute("href");
    if (!href) href = tref.attribute("xlink:href");
    const std::string_view target_id = href.value();
    const pugi::xml_node target = target_id.starts_with('#') && context_.element_for_id
                                      ? context_.element_for_id(std::string(target_id.substr(1)))
                                      : pugi::xml_node();
    if (!target) {
      diagnostics_.warnings.push_back("<tref> refers to no element ('" + std::string(target_id) +
                                      "'); its text is not drawn");
      return;
    }
    ComputedStyle style = child_style_(tref, styles[parent_style]);
    if (!style.display) return;
    std::string data;
    // Pre-order without recursion (a deep target must not exhaust the stack): down, else across, else up.
    for (pugi::xml_node node = target.first_child(); node;) {
      if (node.type() == pugi::node_pcdata || node.type() == pugi::node_cdata) data += node.value();
      if (node.first_child()) {
        node = node.first_child();
        continue;
      }
      while (node && node != target && !node.next_sibling()) node = node.parent();
      node = node && node != target ? node.next_sibling() : pugi::xml_node();
    }
    Result<std::u32string> decoded = decode_utf8(data);
    if (!decoded) {
      diagnostics_.warnings.push_back("<tref> character data skipped: " + decoded.error().message);
      return;
    }
    styles.push_back(std::move(style));
    const std::size_t index = elements.size();
    elements.push_back({tref, styles.size() - 1, parent, fragments.size(), fragments.size(), false});
    fragments.push_back({std::move(decoded).value(), styles.back().preserve_spaces});
    fragment_element.push_back(index);
    elements[index].end_fragment = fragments.size();
  }

  // An unsupported text feature is a warning, once per kind (no silent loss; docs/svg.md).
  void note(const std::string& message) {
    if (noted_.insert(message).second) diagnostics_.warnings.push_back(message);
  }

 private:
  void note_unsupported(const pugi::xml_node& node) {
    const auto check = [&](std::string_view name) {
      if (std::find(kUnsupported.begin(), kUnsupported.end(), name) != kUnsupported.end()) {
        note("<text>: '" + std::string(name) + "' is not supported; ignored");
      }
    };
    for (const pugi::xml_attribute& attribute : node.attributes()) check(attribute.name());
    if (const pugi::xml_attribute css = node.attribute("style")) {
      for (const css::Declaration& declaration : css::parse_declaration_list(css.value()))
        check(declaration.name);
    }
  }

  const ChildStyle& child_style_;
  const TextContext& context_;
  Diagnostics& diagnostics_;
  std::set<std::string> noted_;
};

// A list of numbers or lengths (x, y, dx, dy: SVG 1.1 10.4; rotate: numbers) separated by comma-wsp.
// nullopt with a warning when any entry is malformed (the attribute is then ignored).
std::optional<std::vector<double>> length_list(const pugi::xml_node& node, const char* attribute,
                                               double percent_reference, double font_size,
                                               const TextContext& context, Diagnostics& diagnostics) {
  std::string_view rest = trim_whitespace(node.attribute(attribute).value());
  std::vector<double> values;
  while (!rest.empty()) {
    std::size_t end = 0;
    while (end < rest.size() && rest[end] != ',' && !is_svg_whitespace(rest[end])) ++end;
    const Result<Length> length = parse_length(rest.substr(0, end));
    if (!length || !std::isfinite(length->value)) {
      diagnostics.warnings.push_back("<" + std::string(local_name_of(node)) + "> ignoring " + attribute + ": " +
                                     (length ? "not a finite number" : length.error().message));
      return std::nullopt;
    }
    values.push_back(length_to_pixels(*length, LengthContext{context.dpi, font_size, percent_reference}));
    rest.remove_prefix(end);
    skip_comma_whitespace(rest);
  }
  return values;
}

std::string code_point_name(char32_t c) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "U+%04X", static_cast<unsigned>(c));
  return buffer;
}

// One glyph of the text, placed. `x` is along the chunk's baseline (or along its path), before anchoring.
struct PlacedGlyph {
  GlyphId glyph = kNotdefGlyph;
  const Font* font = nullptr;
  std::size_t character = 0;  // index in the text of its first character
  std::size_t element = 0;    // innermost element holding that character
  double x = 0.0;             // pen position along the baseline
  double offset_x = 0.0;      // HarfBuzz's offset from the pen (marks), user units
  double offset_y = 0.0;      // y down
  double advance = 0.0;       // with letter- and word-spacing
  double size = 0.0;          // em size (the font size; smaller for synthesized small capitals)
  double scale_x = 1.0;       // lengthAdjust="spacingAndGlyphs"
  double shift_y = 0.0;       // dy accumulated, y down
  double baseline_y = 0.0;    // baseline-shift and alignment, y down
  double rotate = 0.0;        // degrees
  bool hidden = false;        // off its path
  bool upright = false;       // vertical text: shaped vertically and drawn upright (CJK), not turned sideways
  Affine frame;               // chunk -> user space at this glyph (set when the chunk is finished)
};

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

// Whether `c` stands upright in vertical text: the blocks whose Vertical_Orientation is U (upright) in
// UAX #50 — Hangul, CJK radicals, symbols and punctuation, kana, Bopomofo, CJK ideographs, Yi, Hangul
// syllables, compatibility ideographs and forms, fullwidth forms, the supplementary ideographic planes.
// Every other character is turned sideways (CSS Writing Modes 3 text-orientation: mixed).
bool is_upright(char32_t c) noexcept {
  constexpr std::pair<char32_t, char32_t> kUpright[] = {
      {0x1100, 0x11FF}, {0x2E80, 0x2FFF}, {0x3000, 0x303F}, {0x3040, 0x31FF}, {0x3200, 0x4DBF},
      {0x4E00, 0x9FFF}, {0xA000, 0xA4CF}, {0xAC00, 0xD7AF}, {0xF900, 0xFAFF}, {0xFE10, 0xFE1F},
      {0xFE30, 0xFE4F}, {0xFF01, 0xFF60}, {0xFFE0, 0xFFE6}, {0x20000, 0x3FFFD}};
  for (const auto& [first, last] : kUpright)
    if (c >= first && c <= last) return true;
  return false;
}

// The <text> element being laid out: its characters, their styles and positions.
class TextLayoutJob {
 public:
  TextLayoutJob(TextCollector& collector, const TextContext& context, FontCache& fonts, Diagnostics& diagnostics)
      : c_(collector), context_(context), fonts_(fonts), diagnostics_(diagnostics) {}

  std::vector<TextPiece> run();

 private:
  struct Chunk {
    std::size_t begin = 0, end = 0;  // characters
    std::size_t text_path = kNoElement;
    double anchor_x = 0.0, y = 0.0;
  };

  void gather_characters();
  void gather_positions();
  void lay_out_chunk(const Chunk& chunk);
  void apply_text_lengths(const Chunk& chunk, std::size_t first_glyph);
  void finish_chunk(const Chunk& chunk, std::size_t first_glyph);
  void emit(std::vector<TextPiece>& pieces);
  void emit_decorations(std::vector<TextPiece>& pieces, bool line_through);
  FontFallback* fallback_for(std::size_t style) { return fonts_.fallback_for(c_.styles[style], diagnostics_); }
  double resolve(const Length& length, std::size_t style) const {
    return length_to_pixels(length, LengthContext{context_.dpi, c_.styles[style].font_size, c_.styles[style].font_size});
  }

  TextCollector& c_;
  const TextContext& context_;
  FontCache& fonts_;
  Diagnostics& diagnostics_;

  std::u32string characters_;
  std::vector<std::size_t> offsets_;            // character offset of each fragment
  std::vector<std::size_t> character_element_;  // innermost element of each character
  std::vector<std::size_t> element_begin_, element_end_;
  std::vector<double> baseline_shift_;  // per element, accumulated from the ancestors, y down
  std::vector<std::optional<double>> abs_x_, abs_y_, rel_x_, rel_y_, rotate_;
  std::vector<PlacedGlyph> glyphs_;
  std::set<std::pair<const Font*, char32_t>> warned_missing_;
  Point pen_;
  std::vector<std::optional<PathMeasure>> paths_;  // per element: the measured path of a textPath
  // Per chunk, the elements (pre-order) over its characters with a unicode-bidi other than normal, and
  // those with a textLength: found once, so that many chunks and many elements stay linear.
  std::vector<std::vector<std::size_t>> bidi_elements_, length_elements_;
  std::size_t chunk_index_ = 0;
  // writing-mode of the <text> (SVG 1.1 10.7.2: it applies to <text> only): vertical lines run down the
  // page; each chunk is laid out along its line as horizontal text is and the line turned by 90 degrees.
  bool vertical_ = false;
};

void TextLayoutJob::gather_characters() {
  offsets_.assign(1, 0);
  for (const TextFragment& fragment : c_.fragments) offsets_.push_back(offsets_.back() + fragment.text.size());
  const std::size_t count = offsets_.back();
  characters_.reserve(count);
  character_element_.resize(count);
  for (std::size_t f = 0; f < c_.fragments.size(); ++f) {
    characters_ += c_.fragments[f].text;
    std::fill(character_element_.begin() + static_cast<std::ptrdiff_t>(offsets_[f]),
              character_element_.begin() + static_cast<std::ptrdiff_t>(offsets_[f + 1]), c_.fragment_element[f]);
  }
  element_begin_.resize(c_.elements.size());
  element_end_.resize(c_.elements.size());
  baseline_shift_.assign(c_.elements.size(), 0.0);
  for (std::size_t e = 0; e < c_.elements.size(); ++e) {
    element_begin_[e] = offsets_[c_.elements[e].first_fragment];
    element_end_[e] = offsets_[c_.elements[e].end_fragment];
    // baseline-shift (SVG 1.1 10.9.3): relative to the parent's (shifted) baseline; sub and super from
    // the element's font (OS/2 sub/superscript offsets), a percentage of the font size. y down.
    const ElementRange& element = c_.elements[e];
    const BaselineShift& shift = c_.styles[element.style].text.baseline_shift;
    double own = 0.0;
    if (shift.kind == BaselineShift::Kind::kLength) {
      own = -resolve(shift.length, element.style);
    } else if (shift.kind != BaselineShift::Kind::kBaseline) {
      if (FontFallback* fonts = fallback_for(element.style)) {
        const FontMetrics m = fonts->primary().metrics();
        const double scale = c_.styles[element.style].font_size / m.units_per_em;
        own = shift.kind == BaselineShift::Kind::kSub ? m.subscript_offset * scale : -m.superscript_offset * scale;
      }
    }
    baseline_shift_[e] = (element.parent == kNoElement ? 0.0 : baseline_shift_[element.parent]) + own;
  }
}

void TextLayoutJob::gather_positions() {
  const std::size_t count = characters_.size();
  abs_x_.assign(count, std::nullopt);
  abs_y_.assign(count, std::nullopt);
  rel_x_.assign(count, std::nullopt);
  rel_y_.assign(count, std::nullopt);
  rotate_.assign(count, std::nullopt);
  // Ancestors first, so that descendants' values win for their characters (SVG 1.1 10.5).
  for (std::size_t e = 0; e < c_.elements.size(); ++e) {
    const ElementRange& element = c_.elements[e];
    const std::size_t begin = element_begin_[e], end = element_end_[e];
    const double font_size = c_.styles[element.style].font_size;
    const auto list = [&](const char* name, double reference) -> std::optional<std::vector<double>> {
      if (!element.node.attribute(name)) return std::nullopt;
      return length_list(element.node, name, reference, font_size, context_, diagnostics_);
    };
    const auto assign = [&](const char* name, double reference, std::vector<std::optional<double>>& target) {
      if (element.text_path && (name[0] == 'x' || name[0] == 'y')) return;  // textPath has no x and y
      const std::optional<std::vector<double>> values = list(name, reference);
      if (!values) return;
      for (std::size_t k = 0; k < values->size() && begin + k < end; ++k) target[begin + k] = (*values)[k];
    };
    assign("x", context_.viewport_width, abs_x_);
    assign("y", context_.viewport_height, abs_y_);
    assign("dx", context_.viewport_width, rel_x_);
    assign("dy", context_.viewport_height, rel_y_);
    // rotate (SVG 1.1 10.5): numbers in degrees; the last one applies to every later character of the
    // element that has none of its own from a descendant.
    if (const std::optional<std::vector<double>> angles = list("rotate", 0.0); angles && !angles->empty()) {
      for (std::size_t k = 0; begin + k < end; ++k) rotate_[begin + k] = (*angles)[std::min(k, angles->size() - 1)];
    }
  }
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
  std::vector<std::u32string> opens(bidi_elements.empty() ? 0 : n + 1), closes(bidi_elements.empty() ? 0 : n + 1);
  for (const std::size_t e : bidi_elements) {
    const TextProperties& text = c_.styles[c_.elements[e].style].text;
    const std::size_t begin = std::max(element_begin_[e], chunk.begin), end = std::min(element_end_[e], chunk.end);
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

  // Runs of one style, one level and, on a vertical line, one orientation (a combining mark keeps its
  // base's).
  struct Run {
    std::size_t begin, end;
    std::uint8_t level;
    bool upright;
  };
  std::vector<Run> runs;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t level = bidi.levels[bidi_index[i]];
    const std::size_t style = c_.elements[character_element_[chunk.begin + i]].style;
    const char32_t c = characters_[chunk.begin + i];
    const bool upright = vertical_ && (is_combining(c) && !runs.empty() ? runs.back().upright : is_upright(c));
    if (runs.empty() || level != runs.back().level || upright != runs.back().upright ||
        style != c_.elements[character_element_[chunk.begin + runs.back().begin]].style) {
      runs.push_back({i, i, level, upright});
    }
    runs.back().end = i + 1;
  }
  std::vector<std::uint8_t> levels(runs.size());
  for (std::size_t r = 0; r < runs.size(); ++r) levels[r] = runs[r].level;

  double pen = 0.0;
  for (const std::size_t r : visual_run_order(levels)) {
    const Run& run = runs[r];
    const std::size_t style_index = c_.elements[character_element_[chunk.begin + run.begin]].style;
    const ComputedStyle& style = c_.styles[style_index];
    FontFallback* fonts = fallback_for(style_index);
    if (fonts == nullptr || !(style.font_size > 0.0)) continue;
    const FontVariants& variants = style.text.font_variants;
    // SVG 1.1 10.11: a kerning length switches kerning off and adds the length between characters, as
    // letter-spacing does.
    const double letter_spacing = (style.text.letter_spacing ? resolve(*style.text.letter_spacing, style_index) : 0.0) +
                                  (variants.kerning_length ? resolve(*variants.kerning_length, style_index) : 0.0);
    const double word_spacing = style.text.word_spacing ? resolve(*style.text.word_spacing, style_index) : 0.0;
    TextStyle text_style;
    text_style.size = style.font_size;
    text_style.direction = run.level % 2 == 1 ? TextDirection::kRightToLeft : TextDirection::kLeftToRight;
    text_style.bidi_override = true;  // the run is at one level already
    // CSS Text 3 8.2: with letter-spacing, optional ligatures are not used (they would get no spacing).
    text_style.ligatures = letter_spacing == 0.0;
    text_style.kerning = variants.kerning && !variants.kerning_length;
    text_style.caps = variants.caps;
    text_style.features = variants.features();
    // Upright characters of a vertical line are shaped top to bottom (HarfBuzz's vertical direction:
    // the font's vertical advances and origins, 'vert' alternates; text_layout.h).
    text_style.vertical = run.upright;
    const std::size_t begin = chunk.begin + run.begin;
    Result<TextLayout> layout =
        layout_text(*fonts, std::u32string_view(characters_).substr(begin, run.end - run.begin), {0.0, 0.0}, text_style);
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
    const auto along = [&](const PositionedGlyph& glyph) { return run.upright ? glyph.origin.y : glyph.origin.x - line_start; };
    double run_pen = 0.0;     // with spacing
    double shaped_pen = 0.0;  // the layout's own pen
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
      // character units), word spacing after word separators.
      if (placed.advance != 0.0) placed.advance += letter_spacing;
      if (is_word_separator(characters_[placed.character])) placed.advance += word_spacing;
      // Alignment: the element's alignment-baseline, else the dominant baseline (SVG 1.1 10.9.2), whose
      // "auto" is central in vertical text (CSS Writing Modes 3 4.2).
      const TextProperties& text = c_.styles[c_.elements[placed.element].style].text;
      Baseline baseline = text.alignment_baseline != Baseline::kAuto ? text.alignment_baseline : text.dominant_baseline;
      if (vertical_ && baseline == Baseline::kAuto) baseline = Baseline::kCentral;
      placed.baseline_y = baseline_height(baseline, metrics) * scale + baseline_shift_[placed.element];
      run_pen += placed.advance;
      glyphs_.push_back(placed);
    }
    pen += run_pen;
  }
  // dx, dy accumulate in logical order (SVG 2 11.8.3 step 4); rotate per character.
  // Along the line and across it: on a vertical line dy moves along it and dx across it (the line's
  // local y axis points to user-space -x).
  std::vector<double> shift_x(n), shift_y(n);
  double sx = 0.0, sy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = rel_x_[chunk.begin + i].value_or(0.0), dy = rel_y_[chunk.begin + i].value_or(0.0);
    sx += vertical_ ? dy : dx;
    sy += vertical_ ? -dx : dy;
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
    pen_.x -= sy;
  } else {
    pen_.y += sy;
  }
  apply_text_lengths(chunk, first_glyph);
  finish_chunk(chunk, first_glyph);
}

// textLength and lengthAdjust (SVG 1.1 10.5, SVG 2 11.8.3 step 5): the advance of an element's characters
// is made textLength, innermost elements first. "spacing" spreads the difference over the gaps between
// its characters; "spacingAndGlyphs" scales the glyphs' advances and outlines horizontally too. Characters
// of the chunk after the element move by the difference.
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
  std::vector<std::size_t> by_character(glyphs_.size() - first_glyph);
  for (std::size_t k = 0; k < by_character.size(); ++k) by_character[k] = first_glyph + k;
  std::stable_sort(by_character.begin(), by_character.end(),
                   [&](std::size_t a, std::size_t b) { return glyphs_[a].character < glyphs_[b].character; });
  for (auto it = elements.rbegin(); it != elements.rend(); ++it) {
    const std::size_t e = *it;
    const ElementRange& element = c_.elements[e];
    const std::size_t begin = std::max(element_begin_[e], chunk.begin), end = std::min(element_end_[e], chunk.end);
    if (begin >= end) continue;
    const std::optional<std::vector<double>> target =
        length_list(element.node, "textLength", context_.viewport_width, c_.styles[element.style].font_size, context_,
                    diagnostics_);
    if (!target || target->size() != 1 || !((*target)[0] >= 0.0)) {
      if (target) diagnostics_.warnings.push_back("<" + std::string(local_name_of(element.node)) +
                                                  "> ignoring textLength: not one non-negative length");
      continue;
    }
    const auto first = std::lower_bound(by_character.begin(), by_character.end(), begin,
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
    const bool glyphs_too = std::string_view(element.node.attribute("lengthAdjust").value()) == "spacingAndGlyphs";
    const double factor = (*target)[0] / (hi - lo);
    const std::size_t characters = end - begin;
    for (auto g = first; g != last; ++g) {
      PlacedGlyph& glyph = glyphs_[*g];
      if (glyphs_too) {
        const double before = moved_at(glyph.character - chunk.begin);
        glyph.x = lo + (glyph.x + before - lo) * factor - before;
        glyph.advance *= factor;
        glyph.offset_x *= factor;
        glyph.scale_x *= factor;
      } else if (characters > 1) {
        glyph.x += delta * static_cast<double>(glyph.character - begin) / static_cast<double>(characters - 1);
      }
    }
    add_after(end - chunk.begin, delta);
  }
  for (std::size_t g = first_glyph; g < glyphs_.size(); ++g) glyphs_[g].x += moved_at(glyphs_[g].character - chunk.begin);
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
  const double shift = ltr_start                        ? 0.0
                       : anchor == TextAnchor::kStart  ? -lo
                       : anchor == TextAnchor::kMiddle ? -0.5 * (lo + hi)
                                                       : -hi;
  const PathMeasure* path = chunk.text_path != kNoElement && paths_[chunk.text_path] ? &*paths_[chunk.text_path] : nullptr;
  for (std::size_t g = first_glyph; g < glyphs_.size(); ++g) {
    PlacedGlyph& glyph = glyphs_[g];
    glyph.x += shift + chunk.anchor_x;
    if (path == nullptr) {
      // A vertical line: the horizontal layout turned by 90 degrees about the chunk's start, so that it
      // runs down the page with the tops of sideways glyphs to the right.
      glyph.frame = vertical_ ? Affine::translate(chunk.y, 0.0) * Affine{0.0, 1.0, -1.0, 0.0, 0.0, 0.0} *
                                    Affine::translate(0.0, glyph.shift_y)
                              : Affine::translate(0.0, chunk.y + glyph.shift_y);
      continue;
    }
    // On a path (SVG 1.1 10.13.3): the glyph's midpoint along its advance is placed on the path at that
    // distance, the glyph rotated to the path's tangent there; a glyph whose midpoint is off the path is
    // not drawn. dy moves perpendicular to the path.
    const double middle = glyph.x + 0.5 * glyph.advance;
    if (middle < 0.0 || middle > path->length()) {
      glyph.hidden = true;
      continue;
    }
    const PathMeasure::Sample sample = path->at(middle);
    const Affine rotation{sample.tangent.x, sample.tangent.y, -sample.tangent.y, sample.tangent.x, 0.0, 0.0};
    glyph.frame = Affine::translate(sample.point.x, sample.point.y) * rotation *
                  Affine::translate(-0.5 * glyph.advance, glyph.shift_y);
    glyph.x = 0.0;  // the frame holds the position
  }
  if (path == nullptr) {
    (vertical_ ? pen_.y : pen_.x) = chunk.anchor_x + shift + hi;
  } else {
    // After a textPath the text continues from the path's point at the end of its advance (SVG 1.1 10.13).
    pen_ = path->at(chunk.anchor_x + shift + hi).point;
  }
}

std::vector<TextPiece> TextLayoutJob::run() {
  gather_characters();
  const std::size_t count = characters_.size();
  if (count == 0) return {};
  if (count > kMaxTextCharacters) {
    diagnostics_.warnings.push_back("<text> with " + std::to_string(count) + " characters, more than the limit of " +
                                    std::to_string(kMaxTextCharacters) + " (text_layout.h), is not drawn");
    return {};
  }
  gather_positions();
  vertical_ = c_.styles[0].text.vertical;

  // The paths of the textPath elements (href to a shape, or SVG 2's path attribute), with startOffset.
  paths_.resize(c_.elements.size());
  std::vector<double> start_offsets(c_.elements.size(), 0.0);
  for (std::size_t e = 0; e < c_.elements.size(); ++e) {
    const ElementRange& element = c_.elements[e];
    if (!element.text_path) continue;
    std::optional<Path> path;
    const pugi::xml_attribute data = element.node.attribute("path");
    pugi::xml_attribute href = element.node.attribute("href");
    if (!href) href = element.node.attribute("xlink:href");
    if (data) {  // SVG 2: the path attribute wins over href
      PathBuilder builder;
      if (const std::optional<PathDataError> error = append_path_data(data.value(), builder)) {
        diagnostics_.warnings.push_back("<textPath> path data: " + error->message);
      }
      Result<Path> built = builder.build();
      if (built) path = std::move(built).value();
    } else if (href && std::string_view(href.value()).starts_with('#') && context_.path_for_id) {
      path = context_.path_for_id(std::string(href.value() + 1));
    }
    if (!path) {
      // SVG 2 11.8.1: a textPath whose path is missing or invalid renders nothing.
      diagnostics_.warnings.push_back("<textPath> refers to no path ('" + std::string(href.value()) +
                                      "'); its text is not drawn");
      continue;
    }
    const std::string_view side = element.node.attribute("side").value();
    paths_[e] = PathMeasure::measure(*path, 0.01, side == "right");
    const std::string_view method = element.node.attribute("method").value();
    if (method == "stretch") diagnostics_.unsupported("<textPath method=\"stretch\">");
    if (paths_[e]) {
      const std::optional<std::vector<double>> offset =
          element.node.attribute("startOffset")
              ? length_list(element.node, "startOffset", paths_[e]->length(), c_.styles[element.style].font_size,
                            context_, diagnostics_)
              : std::nullopt;
      if (offset && !offset->empty()) start_offsets[e] = (*offset)[0];
      // SVG 2 9.4.5 / 11.8.1: with a pathLength on the referenced path, a startOffset that is not a
      // percentage is in the author's length units: scaled by the path's real length / pathLength. A
      // percentage is a fraction of the path, whatever pathLength says. pathLength 0 or invalid: ignored.
      const std::string_view offset_text = trim_whitespace(element.node.attribute("startOffset").value());
      const pugi::xml_node target = !data && href && std::string_view(href.value()).starts_with('#') && context_.element_for_id
                                        ? context_.element_for_id(std::string(href.value() + 1))
                                        : pugi::xml_node();
      const std::optional<double> author_length =
          target && target.attribute("pathLength") ? parse_number(target.attribute("pathLength").value()) : std::nullopt;
      if (author_length && std::isfinite(*author_length) && *author_length > 0.0 && !offset_text.ends_with('%')) {
        start_offsets[e] *= paths_[e]->length() / *author_length;
      }
    }
  }

  // Chunks (SVG 1.1 10.4): a new one at every absolute x or y, at the start of a textPath and after it.
  std::vector<Chunk> chunks;
  // The textPath each element is in (pre-order: a parent comes before its children).
  std::vector<std::size_t> in_text_path(c_.elements.size(), kNoElement);
  for (std::size_t e = 0; e < c_.elements.size(); ++e) {
    const std::size_t parent = c_.elements[e].parent;
    in_text_path[e] = c_.elements[e].text_path ? e : parent == kNoElement ? kNoElement : in_text_path[parent];
  }
  const auto text_path_of = [&](std::size_t character) { return in_text_path[character_element_[character]]; };
  std::size_t previous_path = kNoElement;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t path = text_path_of(i);
    const bool starts_path = path != previous_path;
    previous_path = path;
    // Inside a textPath an x or y does not start a chunk: positions there are along the path.
    const bool absolute = path == kNoElement && (abs_x_[i] || abs_y_[i]);
    if (i > 0 && !starts_path && !absolute) continue;
    if (!chunks.empty()) chunks.back().end = i;
    Chunk chunk;
    chunk.begin = i;
    chunk.text_path = path;
    chunks.push_back(chunk);
  }
  chunks.back().end = count;
  // The elements each chunk needs to look at: those with unicode-bidi or textLength over its characters.
  bidi_elements_.assign(chunks.size(), {});
  length_elements_.assign(chunks.size(), {});
  const auto chunk_of = [&](std::size_t character) {
    return static_cast<std::size_t>(std::upper_bound(chunks.begin(), chunks.end(), character,
                                                     [](std::size_t c, const Chunk& k) { return c < k.begin; }) -
                                    chunks.begin()) - 1;
  };
  for (std::size_t e = 0; e < c_.elements.size(); ++e) {
    if (element_begin_[e] >= element_end_[e]) continue;
    const bool bidi = c_.styles[c_.elements[e].style].text.unicode_bidi != UnicodeBidi::kNormal;
    const bool length = static_cast<bool>(c_.elements[e].node.attribute("textLength"));
    if (!bidi && !length) continue;
    for (std::size_t k = chunk_of(element_begin_[e]); k < chunks.size() && chunks[k].begin < element_end_[e]; ++k) {
      if (bidi) bidi_elements_[k].push_back(e);
      if (length) length_elements_[k].push_back(e);
    }
  }
  pen_ = {0.0, 0.0};
  for (chunk_index_ = 0; chunk_index_ < chunks.size(); ++chunk_index_) {
    Chunk& chunk = chunks[chunk_index_];
    if (chunk.text_path != kNoElement && (chunk.begin == element_begin_[chunk.text_path])) {
      pen_ = {start_offsets[chunk.text_path], 0.0};
    }
    if (abs_x_[chunk.begin] && chunk.text_path == kNoElement) pen_.x = *abs_x_[chunk.begin];
    if (abs_y_[chunk.begin] && chunk.text_path == kNoElement) pen_.y = *abs_y_[chunk.begin];
    // anchor_x is along the line, y across it: swapped on a vertical line.
    chunk.anchor_x = vertical_ && chunk.text_path == kNoElement ? pen_.y : pen_.x;
    chunk.y = vertical_ && chunk.text_path == kNoElement ? pen_.x : pen_.y;
    if (chunk.text_path != kNoElement && !paths_[chunk.text_path]) continue;  // nothing to draw on
    lay_out_chunk(chunk);
  }

  std::vector<TextPiece> pieces;
  emit_decorations(pieces, false);
  emit(pieces);
  emit_decorations(pieces, true);
  return pieces;
}

// The glyph outlines, consecutive glyphs of one style sharing a piece.
void TextLayoutJob::emit(std::vector<TextPiece>& pieces) {
  std::optional<PathBuilder> builder;
  std::size_t builder_style = 0;
  const auto flush = [&] {
    if (!builder) return;
    Result<Path> path = builder->build();
    builder.reset();
    if (!path) {
      diagnostics_.warnings.push_back("<text> outlines not drawn: " + path.error().message);
      return;
    }
    if (path->empty()) return;
    ComputedStyle piece_style = c_.styles[builder_style];
    piece_style.fill_rule = FillRule::kNonZero;
    pieces.push_back({std::move(path).value(), std::move(piece_style)});
  };
  bool warned = false;
  for (const PlacedGlyph& glyph : glyphs_) {
    if (glyph.hidden) continue;
    const std::size_t style = c_.elements[glyph.element].style;
    if (builder && builder_style != style) flush();
    if (!builder) {
      builder.emplace();
      builder_style = style;
    }
    const FontMetrics metrics = glyph.font->metrics();
    const double size = glyph.size;
    const double s = size / metrics.units_per_em;
    const Affine font_units{s, 0.0, 0.0, -s, 0.0, 0.0};
    const Affine rotate = Affine::rotate(glyph.rotate * std::numbers::pi / 180.0);
    Affine place;
    if (glyph.upright) {
      // Standing upright at the pen's point on the line, offset as the vertical shaping says (centred
      // across the line, its vertical origin at the pen), rotated about that point; spacingAndGlyphs
      // stretches it along the line.
      const Point pen = glyph.frame * Point{glyph.x, 0.0};
      place = Affine::translate(pen.x, pen.y) * rotate * Affine::translate(glyph.offset_y, glyph.offset_x) *
              Affine::scale(1.0, glyph.scale_x) * font_units;
    } else {
      // Font units (y up) -> the glyph's place: offset, baseline, rotate (about the glyph's origin, SVG
      // 1.1 10.5), the spacingAndGlyphs scale, then the glyph's frame on the line or the path.
      place = glyph.frame * Affine::translate(glyph.x + glyph.offset_x, glyph.offset_y + glyph.baseline_y) * rotate *
              Affine::scale(glyph.scale_x, 1.0) * font_units;
    }
    const Status appended = glyph.font->append_glyph(glyph.glyph, place, *builder);
    if (!appended && !warned) {
      warned = true;
      diagnostics_.warnings.push_back("<text> glyphs not drawn: " + appended.error().message);
    }
  }
  flush();
}

// text-decoration (SVG 1.1 10.12): each element that declares one draws it under (or over) the glyphs of
// all its characters, with its own fill and stroke, at positions and thicknesses from its own font (the
// post table's underline, OS/2's strikeout; overline at the ascender). One quadrilateral per glyph along
// the glyph's baseline, so decorations follow dx/dy and paths. Underline and overline are painted before
// the text, line-through after it (SVG 2 11.11.2).
void TextLayoutJob::emit_decorations(std::vector<TextPiece>& pieces, bool line_through) {
  // The glyphs in logical order, so that each element finds its own by binary search.
  std::vector<std::size_t> by_character;
  for (std::size_t e = 0; e < c_.elements.size(); ++e) {
    const ComputedStyle& style = c_.styles[c_.elements[e].style];
    const TextDecoration& decoration = style.text.decoration;
    if (!decoration.any() || (line_through && !decoration.line_through) ||
        (!line_through && !decoration.underline && !decoration.overline)) {
      continue;
    }
    FontFallback* fonts = fallback_for(c_.elements[e].style);
    if (fonts == nullptr) continue;
    const FontMetrics m = fonts->primary().metrics();
    const double scale = style.font_size / m.units_per_em;
    // The declaring element's own baseline: its alignment and shift, as its glyphs get them.
    Baseline baseline = style.text.alignment_baseline != Baseline::kAuto ? style.text.alignment_baseline
                                                                         : style.text.dominant_baseline;
    if (vertical_ && baseline == Baseline::kAuto) baseline = Baseline::kCentral;
    const double baseline_y = baseline_height(baseline, m) * scale + baseline_shift_[e];
    // Each line as (centre height above the baseline, thickness), in font units.
    std::vector<std::pair<double, double>> lines;
    if (line_through) lines.emplace_back(m.strikeout_position + 0.5 * m.strikeout_thickness, m.strikeout_thickness);
    if (!line_through && decoration.underline) lines.emplace_back(m.underline_position, m.underline_thickness);
    if (!line_through && decoration.overline) lines.emplace_back(m.ascender - 0.5 * m.underline_thickness, m.underline_thickness);
    if (by_character.empty()) {
      by_character.resize(glyphs_.size());
      for (std::size_t g = 0; g < glyphs_.size(); ++g) by_character[g] = g;
      std::stable_sort(by_character.begin(), by_character.end(),
                       [&](std::size_t a, std::size_t b) { return glyphs_[a].character < glyphs_[b].character; });
    }
    const auto first = std::lower_bound(by_character.begin(), by_character.end(), element_begin_[e],
                                        [&](std::size_t g, std::size_t c) { return glyphs_[g].character < c; });
    PathBuilder builder;
    for (auto it = first; it != by_character.end() && glyphs_[*it].character < element_end_[e]; ++it) {
      const PlacedGlyph& glyph = glyphs_[*it];
      if (glyph.hidden) continue;
      for (const auto& [centre, thickness] : lines) {
        const double top = baseline_y - (centre + 0.5 * thickness) * scale;
        const double bottom = baseline_y - (centre - 0.5 * thickness) * scale;
        const double x0 = glyph.x, x1 = glyph.x + glyph.advance;
        const Point corners[4] = {glyph.frame * Point{x0, top}, glyph.frame * Point{x1, top},
                                  glyph.frame * Point{x1, bottom}, glyph.frame * Point{x0, bottom}};
        builder.move_to(corners[0]);
        for (int k = 1; k < 4; ++k) builder.line_to(corners[k]);
        builder.close();
      }
    }
    Result<Path> path = builder.build();
    if (!path || path->empty()) continue;
    ComputedStyle piece_style = style;
    piece_style.fill_rule = FillRule::kNonZero;
    pieces.push_back({std::move(path).value(), std::move(piece_style)});
  }
}

}  // namespace

std::vector<TextPiece> text_pieces(const pugi::xml_node& text, const ComputedStyle& style,
                                   const ChildStyle& child_style, const TextContext& context,
                                   FontCache& fonts, Diagnostics& diagnostics) {
  TextCollector collector(child_style, context, diagnostics);
  collector.styles.push_back(style);
  collector.collect_element(text, 0, kNoElement, 0, false);
  apply_xml_space(collector.fragments);
  TextLayoutJob job(collector, context, fonts, diagnostics);
  return job.run();
}

}  // namespace curvescan::svg::detail
