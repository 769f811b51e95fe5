// The layout of one <text> element (text_element.h) as a job over its gathered content (text_content.h),
// in the steps of SVG 2 11.8.3, one file per idea:
//  - text_positions.cpp: the characters and their x, y, dx, dy and rotate values, baseline shifts;
//  - text_chunk_layout.cpp: per text chunk, bidi, runs shaped by HarfBuzz, spacing, dx/dy, textLength,
//    anchoring, and each glyph's frame on its line or path;
//  - text_element.cpp: the chunks and textPaths of the whole element, and the glyph outlines;
//  - text_decoration.cpp: underline, overline and line-through.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "curvescan/curves/affine.h"
#include "curvescan/svg/length.h"
#include "curvescan/text/font.h"
#include "text_content.h"
#include "text_element.h"
#include "text_fonts.h"
#include "text_path_measure.h"

namespace curvescan::svg::detail {

/// A list of numbers or lengths (x, y, dx, dy: SVG 1.1 10.4; rotate: numbers) separated by comma-wsp.
/// nullopt with a warning when any entry is malformed (the attribute is then ignored).
[[nodiscard]] std::optional<std::vector<double>> length_list(const pugi::xml_node& node,
                                                             const char* attribute, LengthAxis axis,
                                                             double font_size, Diagnostics& diagnostics);

/// Height of `baseline` above the alphabetic baseline in font units (SVG 1.1 10.9.2; values from the
/// font's metrics, font.h; hanging and mathematical as fractions of the ascender, as resvg and Chrome
/// do without a BASE table).
[[nodiscard]] double baseline_height(Baseline baseline, const FontMetrics& m) noexcept;

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
  double spacing = 0.0;       // the letter- and word-spacing in `advance`, added after the glyph
  double size = 0.0;          // em size (the font size; smaller for synthesized small capitals)
  double scale_x = 1.0;       // lengthAdjust="spacingAndGlyphs"
  double shift_y = 0.0;       // dy accumulated, y down
  double baseline_y = 0.0;    // baseline-shift and alignment, y down
  double rotate = 0.0;        // degrees
  // The point the rotation turns about, along the line from the pen: its cluster's origin (the pen of
  // the cluster's first advancing glyph), so that a combining mark turns with its base, not about its own
  // pen, which follows the base's advance (set when the chunk is finished; 0 on a path).
  double pivot_dx = 0.0;
  bool hidden = false;        // off its path
  bool upright = false;       // vertical text: shaped vertically and drawn upright (CJK), not turned sideways
  Affine frame;               // chunk -> user space at this glyph (set when the chunk is finished)
  // textPath method="stretch" (SVG 1.1 10.13.2): the path whose shape the outline is bent to, and the
  // glyph's frame in the path's own coordinates (x the distance along it, y the offset across it, down
  // to the right of the direction of travel); `frame` stays the align placement, which colour glyphs keep;
  // the outline, the decorations and the glyph cell are placed by `stretch_frame` and bent onto the path
  // (text_path_bend.h). Null: not stretched.
  const PathMeasure* stretch_path = nullptr;
  Affine stretch_frame;
};

// The <text> element being laid out: its characters, their styles and positions.
class TextLayoutJob {
 public:
  TextLayoutJob(TextCollector& collector, const TextContext& context, FontCache& fonts,
                Diagnostics& diagnostics)
      : c_(collector), context_(context), fonts_(fonts), diagnostics_(diagnostics) {}

  std::vector<TextPiece> run();

 private:
  struct Chunk {
    std::size_t begin = 0, end = 0;  // characters
    std::size_t text_path = kNoElement;
    double anchor_x = 0.0, y = 0.0;
    std::size_t line = 0;   // forced line breaks before it (white-space, text_whitespace.h)
    bool new_line = false;  // the first chunk after a forced line break
  };

  void gather_characters();
  void gather_positions();
  [[nodiscard]] std::vector<Chunk> split_chunks();
  [[nodiscard]] std::vector<double> line_offsets(const std::vector<Chunk>& chunks);
  void lay_out_chunk(const Chunk& chunk);
  double set_tab_stops(std::size_t first_glyph);
  void apply_text_lengths(const Chunk& chunk, std::size_t first_glyph);
  void finish_chunk(const Chunk& chunk, std::size_t first_glyph);
  void emit(std::vector<TextPiece>& pieces);
  void emit_color_glyph(const PlacedGlyph& glyph, const Affine& place, const ComputedStyle& style,
                        std::vector<TextPiece>& pieces,
                        const std::function<void(const Status&)>& warn_not_drawn);
  void emit_bitmap_glyph(const PlacedGlyph& glyph, const Affine& place, const ComputedStyle& style,
                         std::vector<TextPiece>& pieces,
                         const std::function<void(const Status&)>& warn_not_drawn);
  void emit_svg_glyph(const PlacedGlyph& glyph, const Affine& place, const ComputedStyle& style,
                      std::vector<TextPiece>& pieces,
                      const std::function<void(const Status&)>& warn_not_drawn);
  void append_stretched_glyph(const PlacedGlyph& glyph, PathBuilder& builder,
                              const std::function<void(const Status&)>& warn_not_drawn);
  void emit_outline_stroke(const PlacedGlyph& glyph, const Affine& place, const ComputedStyle& style,
                           std::vector<TextPiece>& pieces,
                           const std::function<void(const Status&)>& warn_not_drawn);
  [[nodiscard]] Affine glyph_placement(const PlacedGlyph& glyph) const;
  [[nodiscard]] std::optional<Rect> glyph_cells_box() const;
  void emit_decorations(std::vector<TextPiece>& pieces, bool line_through);
  FontFallback* fallback_for(std::size_t style) {
    return fonts_.fallback_for(c_.styles[style], diagnostics_);
  }
  // A text property's length; a percentage is of the font size. Letter and word spacing run across
  // (physical units at the horizontal resolution, as librsvg 2.54's letter-spacing), baseline-shift
  // is neither across nor down (the diagonal resolution, as librsvg's).
  double resolve(const Length& length, std::size_t style, bool across = true) const {
    const double dpi = across ? context_.dpi.x : context_.dpi.diagonal();
    return length_to_pixels(length,
                            LengthContext{dpi, c_.styles[style].font_size, c_.styles[style].font_size});
  }

  TextCollector& c_;
  const TextContext& context_;
  FontCache& fonts_;
  Diagnostics& diagnostics_;

  std::u32string characters_;
  std::vector<std::size_t> offsets_;            // character offset of each fragment
  std::vector<std::size_t> character_element_;  // innermost element of each character
  std::vector<bool> middle_;  // added by text-transform after the character it came from (no position)
  std::vector<std::size_t> element_begin_, element_end_;
  std::vector<double> baseline_shift_;  // per element, accumulated from the ancestors, y down
  std::vector<std::optional<double>> abs_x_, abs_y_, rel_x_, rel_y_, rotate_;
  std::vector<PlacedGlyph> glyphs_;
  std::set<std::pair<const Font*, char32_t>> warned_missing_;
  Point pen_;
  // The advance of the chunks of the current line laid out so far, before x, y, dx, dy and textLength move
  // them: where the next chunk starts on the line box, from which its tab stops are measured.
  double line_advance_ = 0.0;
  std::vector<std::optional<PathMeasure>> paths_;  // per element: the measured path of a textPath
  // Per chunk, the elements (pre-order) over its characters with a unicode-bidi other than normal, and
  // those with a textLength: found once, so that many chunks and many elements stay linear.
  std::vector<std::vector<std::size_t>> bidi_elements_, length_elements_;
  std::size_t chunk_index_ = 0;
  // writing-mode of the <text> (SVG 1.1 10.7.2: it applies to <text> only): vertical lines run down the
  // page; each chunk is laid out along its line as horizontal text is and the line turned by 90 degrees.
  bool vertical_ = false;
  // writing-mode sideways-rl and sideways-lr (CSS Writing Modes 3 section 3.1): every glyph sideways, on
  // the alphabetic baseline (horizontal typographic mode); sideways-lr turns the line the other way, so
  // that it runs bottom to top with the glyphs' tops to the left. `line_turn` is +1 for a line down the
  // page, -1 for one up it: the sign of the quarter turn from the chunk's frame to user space.
  bool sideways_ = false;
  double line_turn_ = 1.0;
};

}  // namespace curvescan::svg::detail
