// SVG <text> layout (text_element.h): the chunks and textPaths of one element, and its glyph outlines.
#include "text_element.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "curvescan/curves/flatten.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/svg/number.h"
#include "curvescan/svg/path_data.h"
#include "curvescan/text/color_glyph.h"
#include "text_layout_job.h"
#include "text_path_bend.h"
#include "text_transform.h"
#include "text_whitespace.h"

namespace curvescan::svg::detail {

std::vector<TextPiece> TextLayoutJob::run() {
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
      // SVG 2 11.8.1: a textPath whose path is missing or invalid renders nothing. Its characters are
      // taken out before the layout, so the text around it stays one chunk, as if it were not there.
      diagnostics_.warnings.push_back("<textPath> refers to no path ('" + std::string(href.value()) +
                                      "'); its text is not drawn");
      for (std::size_t f = element.first_fragment; f < element.end_fragment; ++f) c_.fragments[f].text.clear();
      continue;
    }
    const std::string_view side = element.node.attribute("side").value();
    // Flattened within a fraction of the path's own size (its control box's diagonal / 20000: 0.01 for a
    // path across a 200-unit drawing), so that a path drawn small and scaled up (scale(100) on a path of
    // 2 units) is followed as closely on the screen as a large one; a fixed tolerance in user units would
    // put glyphs a pixel off there. A path with a zero box has no length anyway.
    const Rect box = path->bounds();
    const double diagonal = std::hypot(box.x1 - box.x0, box.y1 - box.y0);
    const double tolerance = diagonal > 0.0 && std::isfinite(diagonal) ? diagonal / 20000.0 : 0.01;
    paths_[e] = PathMeasure::measure(*path, tolerance, side == "right");
    if (paths_[e]) {
      const std::optional<std::vector<double>> offset =
          element.node.attribute("startOffset")
              ? length_list(element.node, "startOffset",
                            LengthAxis{paths_[e]->length(), context_.dpi.diagonal()},
                            c_.styles[element.style].font_size, diagnostics_)
              : std::nullopt;
      if (offset && !offset->empty()) start_offsets[e] = (*offset)[0];
      // SVG 2 9.4.5 / 11.8.1: with a pathLength on the referenced path, a startOffset that is not a
      // percentage is in the author's length units: scaled by the path's real length / pathLength. A
      // percentage is a fraction of the path, whatever pathLength says. pathLength 0 or invalid: ignored.
      const std::string_view offset_text = trim_whitespace(element.node.attribute("startOffset").value());
      const pugi::xml_node target =
          !data && href && std::string_view(href.value()).starts_with('#') && context_.element_for_id
              ? context_.element_for_id(std::string(href.value() + 1))
              : pugi::xml_node();
      const std::optional<double> author_length = target && target.attribute("pathLength")
                                                      ? parse_number(target.attribute("pathLength").value())
                                                      : std::nullopt;
      if (author_length && std::isfinite(*author_length) && *author_length > 0.0 &&
          !offset_text.ends_with('%')) {
        start_offsets[e] *= paths_[e]->length() / *author_length;
      }
    }
  }

  gather_characters();
  const std::size_t count = characters_.size();
  if (count == 0) return {};
  if (count > kMaxTextCharacters) {
    diagnostics_.warnings.push_back("<text> with " + std::to_string(count) +
                                    " characters, more than the limit of " +
                                    std::to_string(kMaxTextCharacters) + ", is not drawn");
    return {};
  }
  gather_positions();
  vertical_ = c_.styles[0].text.vertical;
  sideways_ = vertical_ && c_.styles[0].text.sideways;
  line_turn_ = vertical_ && c_.styles[0].text.bottom_to_top ? -1.0 : 1.0;

  std::vector<Chunk> chunks = split_chunks();
  if (chunks.empty()) return {};  // nothing but forced line breaks
  // The elements each chunk needs to look at: those with unicode-bidi or textLength over its characters.
  bidi_elements_.assign(chunks.size(), {});
  length_elements_.assign(chunks.size(), {});
  const auto chunk_of = [&](std::size_t character) {
    return static_cast<std::size_t>(
               std::upper_bound(chunks.begin(), chunks.end(), character,
                                [](std::size_t c, const Chunk& k) { return c < k.begin; }) -
               chunks.begin()) -
           1;
  };
  for (std::size_t e = 0; e < c_.elements.size(); ++e) {
    if (element_begin_[e] >= element_end_[e]) continue;
    const bool bidi = c_.styles[c_.elements[e].style].text.unicode_bidi != UnicodeBidi::kNormal;
    const bool length = static_cast<bool>(c_.elements[e].node.attribute("textLength"));
    if (!bidi && !length) continue;
    for (std::size_t k = chunk_of(element_begin_[e]); k < chunks.size() && chunks[k].begin < element_end_[e];
         ++k) {
      if (bidi) bidi_elements_[k].push_back(e);
      if (length) length_elements_[k].push_back(e);
    }
  }
  pen_ = {0.0, 0.0};
  // Forced line breaks (SVG 2 11.4, "Multi-line text via white-space"): each line starts where the first
  // did, one line box further in the block direction (line_offsets) — down, or across a vertical line to
  // the left (vertical-rl) or right (vertical-lr) — and is a chunk of its own, anchored by itself (SVG
  // 2 11.8.3: "chunks shifted by text-anchor do not span multiple lines"). An x or y of its first character
  // wins.
  const Point line_origin{abs_x_[0].value_or(0.0), abs_y_[0].value_or(0.0)};
  const std::vector<double> line_offset = line_offsets(chunks);
  for (chunk_index_ = 0; chunk_index_ < chunks.size(); ++chunk_index_) {
    Chunk& chunk = chunks[chunk_index_];
    if (chunk.text_path != kNoElement && (chunk.begin == element_begin_[chunk.text_path])) {
      pen_ = {start_offsets[chunk.text_path], 0.0};
    }
    if (chunk.new_line) line_advance_ = 0.0;
    if (chunk.new_line && chunk.text_path == kNoElement) {
      const double offset = line_offset[chunk.line];
      pen_ = !vertical_ ? Point{line_origin.x, line_origin.y + offset}
                        : Point{line_origin.x + (c_.styles[0].text.lines_left_to_right ? offset : -offset),
                                line_origin.y};
    }
    if (abs_x_[chunk.begin] && chunk.text_path == kNoElement) pen_.x = *abs_x_[chunk.begin];
    if (abs_y_[chunk.begin] && chunk.text_path == kNoElement) pen_.y = *abs_y_[chunk.begin];
    // anchor_x is along the line, y across it: swapped on a vertical line.
    chunk.anchor_x = vertical_ && chunk.text_path == kNoElement ? line_turn_ * pen_.y : pen_.x;
    chunk.y = vertical_ && chunk.text_path == kNoElement ? pen_.x : pen_.y;
    lay_out_chunk(chunk);
  }

  std::vector<TextPiece> pieces;
  emit_decorations(pieces, false);
  const std::size_t glyphs_begin = pieces.size();
  emit(pieces);
  const std::size_t glyphs_end = pieces.size();
  emit_decorations(pieces, true);
  // The glyph cells, and the decorations' own geometry.
  std::optional<Rect> box = glyph_cells_box();
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const TextPiece& piece = pieces[i];
    if ((i >= glyphs_begin && i < glyphs_end) || piece.path.empty()) continue;
    const Rect bounds = piece.path.tight_bounds();
    if (!box) {
      box = bounds;
    } else {
      box->include({bounds.x0, bounds.y0});
      box->include({bounds.x1, bounds.y1});
    }
  }
  if (box && !pieces.empty()) {
    for (TextPiece& piece : pieces) piece.object_box = box;
  }
  return pieces;
}

// Chunks (SVG 1.1 10.4): a new one at every absolute x or y, at the start of a textPath and after it, and
// after every forced line break (text_whitespace.h), which itself belongs to no chunk: it draws nothing.
// On a textPath, which is one line (SVG 2 11.8.1), a forced line break is drawn as a space, as
// xml:space="preserve" draws a newline.
std::vector<TextLayoutJob::Chunk> TextLayoutJob::split_chunks() {
  const std::size_t count = characters_.size();
  // The textPath each element is in (pre-order: a parent comes before its children).
  std::vector<std::size_t> in_text_path(c_.elements.size(), kNoElement);
  for (std::size_t e = 0; e < c_.elements.size(); ++e) {
    const std::size_t parent = c_.elements[e].parent;
    in_text_path[e] = c_.elements[e].text_path ? e : parent == kNoElement ? kNoElement : in_text_path[parent];
  }
  std::vector<Chunk> chunks;
  bool open = false;  // whether chunks.back() takes more characters
  std::size_t previous_path = kNoElement;
  std::size_t line = 0;
  bool after_break = false;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t path = in_text_path[character_element_[i]];
    if (characters_[i] == kForcedLineBreak) {
      if (path != kNoElement) {
        characters_[i] = U' ';
      } else {
        if (open) chunks.back().end = i;
        open = false;
        ++line;
        after_break = true;
        continue;
      }
    }
    const bool starts_path = path != previous_path;
    previous_path = path;
    // Inside a textPath an x or y does not start a chunk: positions there are along the path.
    const bool absolute = path == kNoElement && (abs_x_[i] || abs_y_[i]);
    if (open && !starts_path && !absolute && !after_break) continue;
    if (open) chunks.back().end = i;
    Chunk chunk;
    chunk.begin = i;
    chunk.text_path = path;
    chunk.line = line;
    chunk.new_line = after_break;
    chunks.push_back(chunk);
    open = true;
    after_break = false;
  }
  if (open) chunks.back().end = count;
  return chunks;
}

// Where each line's baseline is, from the first line's, in the block direction (SVG 2 11.4: a forced line
// break "creates a new line box"). Each line box is as tall as its inline boxes with `line-height: normal`
// need (CSS 2.1 10.8.1, as amended: "the height of the inline box encloses all glyphs, going from the
// highest A to the deepest D"; CSS Inline 3): every font on the line contributes its ascender and
// descender plus half its line gap on each side (the half-leading of `normal`, ascender - descender +
// line gap being the font's line height, font.h) — the first available font of every element that has
// characters on the line, at the element's font size, and each fallback face that draws some of them —
// and the <text>'s own first available font at its size is the strut of every line, empty ones too
// (CSS 2.1 10.8.1). Consecutive line boxes touch, so the next baseline is the deepest extent below this
// one plus the highest extent above the next. In vertical-rl and vertical-lr the glyphs sit on the
// central baseline, and each font reaches half its line height to either side. baseline-shift does not
// move a line box here. With one font throughout, lines are that font's line height apart.
std::vector<double> TextLayoutJob::line_offsets(const std::vector<Chunk>& chunks) {
  const std::size_t lines = chunks.back().line + 1;
  if (lines == 1) return {0.0};  // one line: nothing to measure
  struct Extent {
    double above = 0.0, below = 0.0;
  };
  std::vector<Extent> extents(lines);
  const bool centred = vertical_ && !sideways_;
  const auto include = [&](Extent& extent, const Font& font, double size) {
    const FontMetrics m = font.metrics();
    const double scale = size / m.units_per_em;
    if (!(scale > 0.0) || !std::isfinite(scale)) return;
    const double half_gap = 0.5 * (m.line_height - (m.ascender - m.descender));
    const double above = centred ? 0.5 * m.line_height : m.ascender + half_gap;
    const double below = centred ? 0.5 * m.line_height : -m.descender + half_gap;
    extent.above = std::max(extent.above, above * scale);
    extent.below = std::max(extent.below, below * scale);
  };
  // The strut.
  FontFallback* text_fonts = fonts_.fallback_for(c_.styles[0], diagnostics_);
  for (Extent& extent : extents) {
    if (text_fonts != nullptr) {
      include(extent, text_fonts->primary(), c_.styles[0].font_size);
    } else {
      extent.above = extent.below = 0.6 * c_.styles[0].font_size;  // CSS 2.1 10.8.2 suggests 1.0 to 1.2
    }
  }
  for (const Chunk& chunk : chunks) {
    Extent& extent = extents[chunk.line];
    std::size_t last_style = kNoElement;
    FontFallback* fonts = nullptr;  // last_style's
    for (std::size_t i = chunk.begin; i < chunk.end; ++i) {
      const std::size_t style = c_.elements[character_element_[i]].style;
      const double size = c_.styles[style].font_size;
      if (style != last_style) {
        last_style = style;
        fonts = fallback_for(style);
        if (fonts != nullptr) include(extent, fonts->primary(), size);
      }
      if (fonts == nullptr) continue;
      const Font* face = fonts->face_for(characters_[i]);
      if (face != nullptr && face != &fonts->primary()) include(extent, *face, size);
    }
  }
  std::vector<double> offsets(lines, 0.0);
  for (std::size_t k = 1; k < lines; ++k)
    offsets[k] = offsets[k - 1] + extents[k - 1].below + extents[k].above;
  return offsets;
}

// Font units (y up) -> user space for one glyph: its outline and its cell go through the same mapping.
Affine TextLayoutJob::glyph_placement(const PlacedGlyph& glyph) const {
  const double s = glyph.size / glyph.font->metrics().units_per_em;
  const Affine font_units{s, 0.0, 0.0, -s, 0.0, 0.0};
  const Affine rotate = Affine::rotate(glyph.rotate * std::numbers::pi / 180.0);
  if (glyph.upright) {
    // Standing upright at the pen's point on the line, offset as the vertical shaping says (centred
    // across the line, its vertical origin at the pen), rotated about that point; spacingAndGlyphs
    // stretches it along the line.
    // The glyph's own down runs along the line: the frame's turn undone by the vertical line's quarter
    // turn — no turn on a straight vertical line, the path's tangent on a textPath (glyphs upright to the
    // path, their tops on the side a vertical line's tops face, as sideways glyphs turn with it).
    const Point pen = glyph.frame * Point{glyph.x, 0.0};
    const Affine along_line = Affine{glyph.frame.a, glyph.frame.b, glyph.frame.c, glyph.frame.d, 0.0, 0.0} *
                              Affine{0.0, -1.0, 1.0, 0.0, 0.0, 0.0};
    return Affine::translate(pen.x, pen.y) * along_line * rotate *
           Affine::translate(glyph.offset_y, glyph.offset_x) * Affine::scale(1.0, glyph.scale_x) * font_units;
  }
  // Font units (y up) -> the glyph's place: offset, rotate (about its cluster's origin on the shifted
  // baseline, SVG 1.1 10.5, PlacedGlyph::pivot_dx), the spacingAndGlyphs scale, then the glyph's frame on
  // the line or the path.
  const double pivot = glyph.x + glyph.pivot_dx;
  return glyph.frame * Affine::translate(pivot, glyph.baseline_y) * rotate *
         Affine::translate(glyph.x + glyph.offset_x - pivot, glyph.offset_y) *
         Affine::scale(glyph.scale_x, 1.0) * font_units;
}

// The union of the drawn glyphs' cells (SVG 2 8.10): in font units the rectangle from the pen to its
// advance (letter- and word-spacing included: CSS Text 3 8 adds them to the advance) along the line, from
// the descender to the ascender across it; a glyph drawn upright in vertical text gets the same box about
// its own origin. Each cell is mapped as its glyph is, the box taken of the mapped corners; the cell of a
// glyph stretched along a textPath is bent as its outline is (text_path_bend.h), its box taken of the bent
// edges.
std::optional<Rect> TextLayoutJob::glyph_cells_box() const {
  std::optional<Rect> box;
  std::vector<Point> corners;
  for (const PlacedGlyph& glyph : glyphs_) {
    if (glyph.hidden || glyph.font == nullptr) continue;
    const FontMetrics m = glyph.font->metrics();
    const double s = glyph.size / m.units_per_em;
    if (!(s > 0.0) || !std::isfinite(s)) continue;
    const double scale_x = glyph.scale_x != 0.0 ? glyph.scale_x : 1.0;
    const double advance = glyph.upright ? glyph.font->advance(glyph.glyph) : glyph.advance / (s * scale_x);
    // A stretched glyph's cell is bent with its outline: placed in the path's coordinates, then bent.
    PlacedGlyph along = glyph;
    if (glyph.stretch_path != nullptr) along.frame = glyph.stretch_frame;
    const Affine place = glyph_placement(along);
    const Point cell[4] = {place.apply(Point{0.0, m.descender}), place.apply(Point{advance, m.descender}),
                           place.apply(Point{advance, m.ascender}), place.apply(Point{0.0, m.ascender})};
    corners.assign(std::begin(cell), std::end(cell));
    if (glyph.stretch_path != nullptr) {
      corners.clear();
      bend_polygon(*glyph.stretch_path, cell, bend_step(glyph.size), corners);
    }
    for (const Point mapped : corners) {
      if (!std::isfinite(mapped.x) || !std::isfinite(mapped.y)) continue;
      if (!box) {
        box = Rect::from_point(mapped);
      } else {
        box->include(mapped);
      }
    }
  }
  return box;
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
    pieces.push_back({std::move(path).value(), std::move(piece_style), std::nullopt, nullptr, Affine{}});
  };
  bool warned = false;
  const auto warn_not_drawn = [&](const Status& appended) {
    if (!appended && !warned) {
      warned = true;
      diagnostics_.warnings.push_back("<text> glyphs not drawn: " + appended.error().message);
    }
  };
  for (const PlacedGlyph& glyph : glyphs_) {
    if (glyph.hidden) continue;
    const std::size_t style = c_.elements[glyph.element].style;
    const Affine place = glyph_placement(glyph);
    const ColorGlyphKind kind = color_glyph_kind(*glyph.font, glyph.glyph);
    if (kind == ColorGlyphKind::kLayers) {
      flush();
      emit_color_glyph(glyph, place, c_.styles[style], pieces, warn_not_drawn);
      continue;
    }
    if (kind == ColorGlyphKind::kBitmap) {
      flush();
      emit_bitmap_glyph(glyph, place, c_.styles[style], pieces, warn_not_drawn);
      continue;
    }
    if (kind == ColorGlyphKind::kSvg) {
      flush();
      emit_svg_glyph(glyph, place, c_.styles[style], pieces, warn_not_drawn);
      continue;
    }
    if (kind == ColorGlyphKind::kPaintGraph) {
      fonts_.warn_outline_only(*glyph.font, kind, diagnostics_);
    }
    if (builder && builder_style != style) flush();
    if (!builder) {
      builder.emplace();
      builder_style = style;
    }
    if (glyph.stretch_path != nullptr) {
      append_stretched_glyph(glyph, *builder, warn_not_drawn);
    } else {
      warn_not_drawn(glyph.font->append_glyph(glyph.glyph, place, *builder));
    }
  }
  flush();
}

// textPath method="stretch" (SVG 1.1 10.13.2: "the glyph outlines will be converted into paths, and then
// all end points and control points will be adjusted to be along the perpendicular vectors from the path,
// thereby stretching and possibly warping the glyphs"). The outline is placed in the path's own
// coordinates (distance along it, offset across it), flattened finely, and bent onto the path
// (text_path_bend.h: cut into pieces no longer than a fortieth of the em, every point mapped to the point
// at its distance moved by its offset along the normal there).
void TextLayoutJob::append_stretched_glyph(const PlacedGlyph& glyph, PathBuilder& builder,
                                           const std::function<void(const Status&)>& warn_not_drawn) {
  PlacedGlyph along = glyph;
  along.frame = glyph.stretch_frame;
  PathBuilder flat;
  const Status appended = glyph.font->append_glyph(glyph.glyph, glyph_placement(along), flat);
  if (!appended) {
    warn_not_drawn(appended);
    return;
  }
  Result<Path> outline = flat.build();
  if (!outline) {
    warn_not_drawn(outline.error());
    return;
  }
  const PathMeasure& path = *glyph.stretch_path;
  const double tolerance = glyph.size / 2000.0;  // 0.01 user units at 20 px: far below a pixel at 1:1
  std::vector<Point> contour, bent;
  const auto flush = [&] {
    if (contour.size() >= 2 && contour.back() == contour.front()) contour.pop_back();
    if (contour.size() >= 2) {
      bent.clear();
      bend_polygon(path, contour, bend_step(glyph.size), bent);
      builder.polygon(bent);
    }
    contour.clear();
  };
  for (const PathElement& element : *outline) {
    if (element.verb == PathVerb::kMove) {
      flush();
      contour.push_back(element.start);
      continue;
    }
    if (contour.empty()) contour.push_back(element.start);
    if (element.verb == PathVerb::kClose || element.verb == PathVerb::kLine) {
      contour.push_back(element.end);
    } else if (element.is_rational()) {
      (void)flatten_rational(element.points, element.weights, tolerance, contour, kMaxPathMeasurePoints);
    } else {
      (void)flatten_bezier(element.points, tolerance, contour, kMaxPathMeasurePoints);
    }
  }
  flush();
}

// A COLR version 0 glyph (color_glyph.h): its layers in order, each a piece filled with its palette colour
// or, for the foreground index, with the text's own fill; then the stroke, if any, along the glyph's
// plain outline. With fill="none" there is no fill to draw the colours with (browsers paint colour glyphs
// in the fill pass), so only the stroke is drawn. A palette colour is modulated by the alpha of a colour
// fill (browsers fade a colour glyph with a translucent text colour) and, as any fill, by fill-opacity.
void TextLayoutJob::emit_color_glyph(const PlacedGlyph& glyph, const Affine& place,
                                     const ComputedStyle& style, std::vector<TextPiece>& pieces,
                                     const std::function<void(const Status&)>& warn_not_drawn) {
  // Each piece is filled non-zero (COLR layers and glyph outlines are non-zero outlines); a glyph the font
  // cannot give is named and skipped.
  const auto push = [&](Path path, ComputedStyle piece_style) {
    piece_style.fill_rule = FillRule::kNonZero;
    pieces.push_back({std::move(path), std::move(piece_style), std::nullopt, nullptr, Affine{}});
  };
  if (style.fill.kind != PaintSpec::Kind::kNone) {
    const double fill_alpha = style.fill.kind == PaintSpec::Kind::kColor          ? style.fill.color.a
                              : style.fill.kind == PaintSpec::Kind::kCurrentColor ? style.color.a
                                                                                  : 1.0;
    Result<std::vector<ColorLayerOutline>> layers =
        color_glyph_layer_outlines(*glyph.font, glyph.glyph, place);
    if (!layers) {
      warn_not_drawn(layers.error());
      layers = std::vector<ColorLayerOutline>{};
    }
    for (ColorLayerOutline& layer : *layers) {
      ComputedStyle layer_style = style;
      layer_style.stroke = PaintSpec{};
      if (!layer.foreground) {
        const Color c = layer.color;
        layer_style.fill = PaintSpec{
            PaintSpec::Kind::kColor, Color{c.r, c.g, c.b, c.a * fill_alpha}, {}, PaintSpec::Kind::kNone, {}};
      }
      push(std::move(layer.path), std::move(layer_style));
    }
  }
  if (style.stroke.kind != PaintSpec::Kind::kNone) {
    PathBuilder builder;
    const Status appended = glyph.font->append_glyph(glyph.glyph, place, builder);
    Result<Path> outline = appended ? builder.build() : Result<Path>(appended.error());
    if (!outline) {
      warn_not_drawn(outline.error());
    } else if (!outline->empty()) {
      ComputedStyle stroke_style = style;
      stroke_style.fill = PaintSpec{};
      push(std::move(outline).value(), std::move(stroke_style));
    }
  }
}

// A bitmap colour glyph (color_glyph.h): a piece over the image's rectangle that carries the image, from
// the strike nearest the glyph's em size in user units; then the stroke, if any, along the glyph's outline
// when the font has one (an sbix font with outlines), else none (a CBDT-only font has no outline to
// follow). With fill="none" no image is drawn, as no COLR layer is.
void TextLayoutJob::emit_bitmap_glyph(const PlacedGlyph& glyph, const Affine& place,
                                      const ComputedStyle& style, std::vector<TextPiece>& pieces,
                                      const std::function<void(const Status&)>& warn_not_drawn) {
  if (style.fill.kind != PaintSpec::Kind::kNone) {
    // The em size the glyph is drawn at in device pixels: the length of the em's vertical side placed and
    // mapped to the device, so that a zoomed or scaled text takes the strike of the size it covers, as
    // browsers choose it (a strike picked by the size in user units would be scaled up, blurred).
    const double em = glyph.font->metrics().units_per_em;
    const Affine device = context_.user_to_device * place;
    const double pixels_per_em = std::hypot(device.c, device.d) * em;
    Result<std::optional<ColorGlyphBitmap>> bitmap =
        color_glyph_bitmap(*glyph.font, glyph.glyph, pixels_per_em, context_.max_image_pixels);
    if (!bitmap || !*bitmap) {
      // An image FreeType cannot decode (a corrupt or cut PNG), or one beyond the pixel limit: the plain
      // outline where the font has one, with a warning.
      diagnostics_.warnings.push_back(
          "the colour bitmap of glyph " + std::to_string(glyph.glyph) + " of font '" +
          glyph.font->source_name() + "' is not drawn (" +
          (bitmap ? std::string("FreeType cannot decode it") : bitmap.error().message) +
          "); its outline is drawn where the font has one");
      PathBuilder builder;
      if (glyph.font->append_glyph(glyph.glyph, place, builder)) {
        Result<Path> outline = builder.build();
        if (outline && !outline->empty()) {
          ComputedStyle fill_style = style;
          fill_style.stroke = PaintSpec{};
          fill_style.fill_rule = FillRule::kNonZero;
          pieces.push_back(
              {std::move(outline).value(), std::move(fill_style), std::nullopt, nullptr, Affine{}});
        }
      }
    } else {
      const Affine image_to_user = place * (*bitmap)->image_to_font;
      Result<Path> rectangle = color_glyph_bitmap_rectangle(**bitmap, image_to_user);
      if (!rectangle) {
        warn_not_drawn(rectangle.error());
      } else {
        ComputedStyle image_style = style;
        image_style.stroke = PaintSpec{};
        image_style.fill_rule = FillRule::kNonZero;
        TextPiece piece{std::move(rectangle).value(), std::move(image_style), std::nullopt, nullptr,
                        Affine{}};
        piece.bitmap = std::make_shared<const ColorGlyphBitmap>(std::move(**bitmap));
        piece.image_to_user = image_to_user;
        pieces.push_back(std::move(piece));
      }
    }
  }
  emit_outline_stroke(glyph, place, style, pieces, warn_not_drawn);
}

// The stroke of a bitmap or SVG colour glyph, if any, along the glyph's outline where the font has one; no
// outline (a bitmap-only font) is no stroke, not an error.
void TextLayoutJob::emit_outline_stroke(const PlacedGlyph& glyph, const Affine& place,
                                        const ComputedStyle& style, std::vector<TextPiece>& pieces,
                                        const std::function<void(const Status&)>& warn_not_drawn) {
  if (style.stroke.kind == PaintSpec::Kind::kNone) return;
  PathBuilder builder;
  if (!glyph.font->append_glyph(glyph.glyph, place, builder)) return;
  Result<Path> outline = builder.build();
  if (!outline) {
    warn_not_drawn(outline.error());
  } else if (!outline->empty()) {
    ComputedStyle stroke_style = style;
    stroke_style.fill = PaintSpec{};
    stroke_style.fill_rule = FillRule::kNonZero;
    pieces.push_back({std::move(outline).value(), std::move(stroke_style), std::nullopt, nullptr, Affine{}});
  }
}

// An SVG-in-OpenType glyph (color_glyph.h): a piece carrying the document, over the glyph's outline (or its
// cell where it has none); then the stroke along the outline. The document maps font units with y down to
// the glyph's place: the placement of the y-up outline, flipped. With fill="none" nothing of the document is
// drawn, as no COLR layer is.
void TextLayoutJob::emit_svg_glyph(const PlacedGlyph& glyph, const Affine& place, const ComputedStyle& style,
                                   std::vector<TextPiece>& pieces,
                                   const std::function<void(const Status&)>& warn_not_drawn) {
  if (style.fill.kind != PaintSpec::Kind::kNone) {
    auto document = std::make_shared<SvgGlyphDocument>();
    document->font = glyph.font;
    document->document = color_glyph_svg_document(*glyph.font, glyph.glyph);
    document->glyph = glyph.glyph;
    document->units_per_em = glyph.font->metrics().units_per_em;
    Result<SvgGlyphArea> outline = svg_glyph_area(*glyph.font, glyph.glyph, place);
    document->path_is_outline = outline && outline->is_outline;
    if (!outline) {
      warn_not_drawn(outline.error());
    } else if (!document->document.empty()) {
      ComputedStyle svg_style = style;
      svg_style.stroke = PaintSpec{};
      svg_style.fill_rule = FillRule::kNonZero;
      TextPiece piece{std::move(outline->path), std::move(svg_style), std::nullopt, nullptr, Affine{}};
      piece.svg_glyph = std::move(document);
      piece.svg_to_user = place * Affine::scale(1.0, -1.0);
      pieces.push_back(std::move(piece));
    }
  }
  emit_outline_stroke(glyph, place, style, pieces, warn_not_drawn);
}

std::vector<TextPiece> text_pieces(const pugi::xml_node& text, const ComputedStyle& style,
                                   const ChildStyle& child_style, const TextContext& context,
                                   FontCache& fonts, Diagnostics& diagnostics) {
  TextCollector collector(child_style, context, diagnostics);
  collector.styles.push_back(style);
  collector.collect_element(text, 0, kNoElement, 0, false);
  apply_white_space(collector.fragments);
  apply_text_transform(collector.fragments);
  TextLayoutJob job(collector, context, fonts, diagnostics);
  return job.run();
}

}  // namespace curvescan::svg::detail
