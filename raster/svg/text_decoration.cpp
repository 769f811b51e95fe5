// text-decoration of <text> (text_layout_job.h).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "text_layout_job.h"
#include "text_path_bend.h"

namespace curvescan::svg::detail {

// text-decoration (SVG 1.1 10.12): each element that declares one draws it under (or over) the glyphs of
// all its characters, with its own fill and stroke, at positions and thicknesses from its own font (the
// post table's underline, OS/2's strikeout; overline at the ascender). One quadrilateral per glyph along
// the glyph's baseline, so decorations follow dx/dy and paths (bent with the glyphs on a textPath with
// method="stretch"). Underline and overline are painted before
// the text, line-through after it (SVG 2 11.11.2).
void TextLayoutJob::emit_decorations(std::vector<TextPiece>& pieces, bool line_through) {
  // The glyphs in logical order, so that each element finds its own by binary search.
  std::vector<std::size_t> by_character;
  for (std::size_t e = 0; e < c_.elements.size(); ++e) {
    const ComputedStyle& style = c_.styles[c_.elements[e].style];
    TextDecoration decoration = style.text.decoration;
    if (c_.elements[e].parent == kNoElement) {
      // The <text> draws its ancestors' decorations too, with its own paint and font (as resvg and
      // browsers draw text-decoration set on a group).
      decoration.underline |= style.text.ancestor_decoration.underline;
      decoration.overline |= style.text.ancestor_decoration.overline;
      decoration.line_through |= style.text.ancestor_decoration.line_through;
    }
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
    if (vertical_ && !sideways_ && baseline == Baseline::kAuto) baseline = Baseline::kCentral;
    const double baseline_y = baseline_height(baseline, m) * scale + baseline_shift_[e];
    // Each line as (centre height above the baseline, thickness), in font units.
    std::vector<std::pair<double, double>> lines;
    if (line_through)
      lines.emplace_back(m.strikeout_position - 0.5 * m.strikeout_thickness, m.strikeout_thickness);
    if (!line_through && decoration.underline)
      lines.emplace_back(m.underline_position, m.underline_thickness);
    if (!line_through && decoration.overline)
      lines.emplace_back(m.ascender - 0.5 * m.underline_thickness, m.underline_thickness);
    if (by_character.empty()) {
      by_character.resize(glyphs_.size());
      for (std::size_t g = 0; g < glyphs_.size(); ++g) by_character[g] = g;
      std::stable_sort(by_character.begin(), by_character.end(), [&](std::size_t a, std::size_t b) {
        return glyphs_[a].character < glyphs_[b].character;
      });
    }
    const auto first =
        std::lower_bound(by_character.begin(), by_character.end(), element_begin_[e],
                         [&](std::size_t g, std::size_t c) { return glyphs_[g].character < c; });
    PathBuilder builder;
    // Consecutive glyphs on one straight frame whose cells touch share one quadrilateral per line, so a
    // stroked decoration is one line, not a row of boxes; a new frame (a path, a rotation) or a gap (dx,
    // an absolute x) starts another.
    // On a textPath with method="stretch" the span is in the path's own coordinates and bent onto the path
    // with the glyphs' outlines (text_path_bend.h), so the line follows the bent glyphs.
    struct Span {
      Affine frame;
      double x0, x1;
      const PathMeasure* bend = nullptr;
    };
    std::optional<Span> span;
    std::vector<Point> bent;
    const auto flush = [&] {
      if (!span) return;
      for (const auto& [centre, thickness] : lines) {
        const double top = baseline_y - (centre + 0.5 * thickness) * scale;
        const double bottom = baseline_y - (centre - 0.5 * thickness) * scale;
        const Point corners[4] = {span->frame * Point{span->x0, top}, span->frame * Point{span->x1, top},
                                  span->frame * Point{span->x1, bottom}, span->frame * Point{span->x0, bottom}};
        if (span->bend != nullptr) {
          bent.clear();
          bend_polygon(*span->bend, corners, bend_step(style.font_size), bent);
          builder.polygon(bent);
          continue;
        }
        builder.move_to(corners[0]);
        for (int k = 1; k < 4; ++k) builder.line_to(corners[k]);
        builder.close();
      }
      span.reset();
    };
    const auto same_frame = [](const Affine& a, const Affine& b) {
      for (const Point p : {Point{0.0, 0.0}, Point{1.0, 0.0}, Point{0.0, 1.0}})
        if (!(a * p == b * p)) return false;
      return true;
    };
    for (auto it = first; it != by_character.end() && glyphs_[*it].character < element_end_[e]; ++it) {
      const PlacedGlyph& glyph = glyphs_[*it];
      if (glyph.hidden) continue;
      double x0 = glyph.x, x1 = glyph.x + glyph.advance;
      // A stretched glyph's frame in the path's coordinates is a translation along and across the path:
      // taken as the glyph's position along it, so that the pieces of consecutive glyphs join into one.
      Affine frame = glyph.frame;
      const PathMeasure* bend = glyph.stretch_path;
      if (bend != nullptr) {
        frame = glyph.stretch_frame;
        if (glyph.rotate == 0.0) {
          x0 += frame.e;
          x1 += frame.e;
          frame = Affine::translate(0.0, frame.f);
        }
      }
      // A glyph turned by `rotate` takes its piece of the line with it, turned about the same point
      // (glyph_placement): its origin on its baseline, or for an upright glyph of vertical text the pen's
      // point on the line. The decoration stays under the glyph, as browsers draw the decoration of each
      // rotated character with the character's own transform.
      if (glyph.rotate != 0.0) {
        const double pivot_y = glyph.upright ? 0.0 : glyph.baseline_y;
        frame = frame * Affine::translate(glyph.x, pivot_y) *
                Affine::rotate(glyph.rotate * std::numbers::pi / 180.0) *
                Affine::translate(-glyph.x, -pivot_y);
      }
      if (span && span->bend == bend && same_frame(span->frame, frame) &&
          std::abs(span->x1 - x0) <= 1e-9 * (1.0 + std::abs(x0))) {
        span->x1 = x1;
        continue;
      }
      flush();
      span = Span{frame, x0, x1, bend};
    }
    flush();
    Result<Path> path = builder.build();
    if (!path || path->empty()) continue;
    ComputedStyle piece_style = style;
    piece_style.fill_rule = FillRule::kNonZero;
    pieces.push_back({std::move(path).value(), std::move(piece_style), std::nullopt, nullptr, Affine{}});
  }
}

}  // namespace curvescan::svg::detail
