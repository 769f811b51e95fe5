// Text layout through HarfBuzz. Each line goes into an hb_buffer as UTF-32 (so clusters are indices
// into the line), is shaped with the requested features, and the glyph positions, which HarfBuzz gives
// in font units because the hb_font keeps its default scale of units_per_em (font_face_p.h), are scaled
// to user units and flipped to y down: origin = pen + offset, pen += advance (HarfBuzz manual, "Shaping
// and shape plans": x_advance/x_offset are in the font's scale; offsets are y up).
#include "curvescan/raster/font/text_layout.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "curvescan/raster/font/utf8.h"
#include "font_face_p.h"

namespace curvescan {
namespace {

struct BufferDeleter {
  void operator()(hb_buffer_t* buffer) const noexcept { hb_buffer_destroy(buffer); }
};
using BufferPtr = std::unique_ptr<hb_buffer_t, BufferDeleter>;

hb_feature_t global_feature(const char tag[4], bool on) noexcept {
  return {HB_TAG(tag[0], tag[1], tag[2], tag[3]), on ? 1u : 0u, HB_FEATURE_GLOBAL_START,
          HB_FEATURE_GLOBAL_END};
}

// Shapes one line (no newline inside) and appends its glyphs with the pen starting at x = 0 on y = 0;
// returns the line's advance in font units.
double shape_line(const Font::Impl& impl, std::u32string_view line, std::size_t line_start,
                  const TextStyle& style, double scale, std::vector<PositionedGlyph>& glyphs,
                  std::u32string& missing, hb_buffer_t* buffer) {
  hb_buffer_clear_contents(buffer);
  static_assert(sizeof(char32_t) == sizeof(std::uint32_t));
  hb_buffer_add_utf32(buffer, reinterpret_cast<const std::uint32_t*>(line.data()),
                      static_cast<int>(line.size()), 0, static_cast<int>(line.size()));
  hb_buffer_guess_segment_properties(buffer);
  const hb_feature_t features[] = {global_feature("kern", style.kerning),
                                   global_feature("liga", style.ligatures),
                                   global_feature("clig", style.ligatures)};
  hb_shape(impl.hb_font, buffer, features, static_cast<unsigned>(std::size(features)));
  unsigned count = 0;
  const hb_glyph_info_t* infos = hb_buffer_get_glyph_infos(buffer, &count);
  const hb_glyph_position_t* positions = hb_buffer_get_glyph_positions(buffer, &count);
  double pen_x = 0.0, pen_y = 0.0;
  for (unsigned i = 0; i < count; ++i) {
    const std::size_t character_index = line_start + infos[i].cluster;
    if (infos[i].codepoint == kNotdefGlyph && infos[i].cluster < line.size()) {
      const char32_t character = line[infos[i].cluster];
      if (missing.find(character) == std::u32string::npos) missing.push_back(character);
    }
    const Point origin{(pen_x + positions[i].x_offset) * scale, -(pen_y + positions[i].y_offset) * scale};
    glyphs.push_back({infos[i].codepoint, origin, character_index});
    pen_x += positions[i].x_advance;
    pen_y += positions[i].y_advance;
  }
  return pen_x;
}

}  // namespace

Rect TextLayout::line_box() const noexcept {
  if (lines.empty()) return {};
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
  if (!(style.size > 0.0 && style.size <= kMaxTextSize)) {
    return Error{ErrorKind::kInvalidArgument, "the font size must be a number in (0, " +
                                                  std::to_string(static_cast<int>(kMaxTextSize)) +
                                                  "] (text_layout.h)"};
  }
  if (!origin.is_finite() || !std::isfinite(style.line_height) || style.line_height < 0.0) {
    return Error{ErrorKind::kInvalidArgument,
                 "the text origin and line height must be finite (line height >= 0)"};
  }
  if (text.size() > kMaxTextCharacters) {
    return Error{ErrorKind::kLimitExceeded, "the text has " + std::to_string(text.size()) +
                                                " characters, more than the limit of " +
                                                std::to_string(kMaxTextCharacters) + " (text_layout.h)"};
  }
  const FontMetrics metrics = font.metrics();
  TextLayout layout;
  layout.scale = style.size / metrics.units_per_em;
  layout.ascent = metrics.ascender * layout.scale;
  layout.descent = -metrics.descender * layout.scale;
  layout.line_height = style.line_height > 0.0 ? style.line_height : metrics.line_height * layout.scale;

  const BufferPtr buffer(hb_buffer_create());
  std::size_t line_start = 0;
  for (std::size_t line_index = 0;; ++line_index) {
    const std::size_t newline = std::min(text.find(U'\n', line_start), text.size());
    std::u32string_view line = text.substr(line_start, newline - line_start);
    if (!line.empty() && line.back() == U'\r') line.remove_suffix(1);
    TextLine placed;
    placed.first_glyph = layout.glyphs.size();
    const double advance_units = shape_line(font.impl(), line, line_start, style, layout.scale, layout.glyphs,
                                            layout.missing_characters, buffer.get());
    placed.glyph_count = layout.glyphs.size() - placed.first_glyph;
    placed.advance = advance_units * layout.scale;
    const double anchor_shift = style.anchor == TextAnchor::kStart    ? 0.0
                                : style.anchor == TextAnchor::kMiddle ? -0.5 * placed.advance
                                                                      : -placed.advance;
    placed.origin = {origin.x + anchor_shift,
                     origin.y + static_cast<double>(line_index) * layout.line_height};
    for (std::size_t g = placed.first_glyph; g < layout.glyphs.size(); ++g) {
      layout.glyphs[g].origin += placed.origin.to_vec();
    }
    layout.lines.push_back(placed);
    if (newline == text.size()) break;
    line_start = newline + 1;
  }
  return layout;
}

Status append_text_outlines(const Font& font, const TextLayout& layout, PathBuilder& builder) {
  const double s = layout.scale;
  for (const PositionedGlyph& glyph : layout.glyphs) {
    // Font units (y up) -> user units (y down) at the glyph's origin.
    const Affine font_to_user{s, 0.0, 0.0, -s, glyph.origin.x, glyph.origin.y};
    CURVESCAN_PROPAGATE(font.append_glyph(glyph.glyph, font_to_user, builder));
  }
  return Status::ok();
}

Result<Path> text_path(const Font& font, std::string_view utf8, Point origin, const TextStyle& style) {
  const Result<std::u32string> text = decode_utf8(utf8);
  if (!text) return text.error();
  const Result<TextLayout> layout = layout_text(font, *text, origin, style);
  if (!layout) return layout.error();
  PathBuilder builder;
  CURVESCAN_PROPAGATE(append_text_outlines(font, *layout, builder));
  return builder.build();
}

}  // namespace curvescan
