// A text specimen: DejaVu Sans through curvescan's text pipeline (FreeType outlines -> Paths, HarfBuzz
// shaping, text_layout.h) at several sizes, kerning on and off, text filled with a gradient, and one
// glyph magnified with its TrueType quadratic control points (on-curve discs, off-curve rings).
#include <array>
#include <string>
#include <vector>

#include "curvescan/raster/gradient.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/text/utf8.h"
#include "figure/figure.h"
#include "figure/figures.h"
#include "figure/palette.h"

namespace curvescan::figure {

namespace {

/// The outline of `text` in the figure's face at `size`, baseline at `origin`.
Result<Path> outline(Figure& figure, std::string_view text, Point origin, double size, bool kerning = true) {
  Result<std::u32string> decoded = decode_utf8(text);
  if (!decoded) return decoded.error();
  TextStyle style;
  style.size = size;
  style.kerning = kerning;
  Result<TextLayout> layout = layout_text(figure.font(), *decoded, origin, style);
  if (!layout) return layout.error();
  PathBuilder builder;
  CURVESCAN_PROPAGATE(append_text_outlines(figure.font(), *layout, builder));
  return builder.build();
}

void dot(Figure& figure, Point at, double radius, Color color, bool hollow) {
  const Result<Path> circle =
      PathBuilder().arc(at, radius, radius, 0.0, 0.0, 6.283185307179586).close().build();
  if (hollow) {
    figure.fill(circle, kPaper);
    StrokeStyle ring;
    ring.width = 1.5;
    figure.stroke(circle, color, ring);
  } else {
    figure.fill(circle, color);
  }
}

}  // namespace

Result<Image> render_text_specimen() {
  Result<Figure> made = Figure::create(960, 600);
  if (!made) return made.error();
  Figure& figure = *made;
  figure.text("DejaVu Sans, drawn by curvescan", {40.0, 52.0}, 30.0, kInk);
  figure.text(
      "FreeType outlines as exact quadratic B\xC3\xA9zier paths, HarfBuzz shaping, exact-area coverage",
      {40.0, 78.0}, 13.0, kMutedInk);

  const std::array<double, 6> sizes{9.0, 11.0, 14.0, 18.0, 24.0, 32.0};
  double y = 112.0;
  for (double size : sizes) {
    figure.text(std::to_string(static_cast<int>(size)) + " px", {40.0, y}, 10.0, kMutedInk);
    figure.text("Sphinx of black quartz, judge my vow", {95.0, y}, size, kInk);
    y += size * 1.25 + 8.0;
  }

  // Kerning: HarfBuzz applies the font's kern pairs (text_layout.h); without them "AV" and "To" gape.
  figure.text("kerning on", {40.0, 380.0}, 10.0, kMutedInk);
  figure.fill(outline(figure, "AVATAR To Wa", {110.0, 382.0}, 34.0, true), kBlue);
  figure.text("kerning off", {40.0, 430.0}, 10.0, kMutedInk);
  figure.fill(outline(figure, "AVATAR To Wa", {110.0, 432.0}, 34.0, false), kVermillion);

  figure.text(
      "B\xC3\xA9zier \xC2\xB7 Cox\xE2\x80\x93"
      "de Boor \xC2\xB7 \xE2\x88\x91 N\xE1\xB5\xA2(u) = 1 \xC2\xB7 "
      "\xCE\xB1\xCE\xB2\xCE\xB3 \xC2\xB7 \xC2\xBD \xE2\x85\x93 \xC2\xBC \xC2\xB7 fi fl",
      {40.0, 480.0}, 20.0, kInk);

  // A word filled with a linear gradient: glyph outlines are ordinary paths.
  const std::array<GradientStop, 3> stops{GradientStop{0.0, {0.0, 0.447, 0.698, 1.0}},
                                          GradientStop{0.5, {0.8, 0.475, 0.655, 1.0}},
                                          GradientStop{1.0, {0.835, 0.369, 0.0, 1.0}}};
  const Paint gradient = linear_gradient_paint({{40.0, 0.0}, {470.0, 0.0}}, stops, SpreadMethod::kPad);
  figure.fill_paint(outline(figure, "curvescan", {40.0, 560.0}, 64.0), gradient);

  // One glyph at 260 px with its control points: TrueType glyphs are quadratic splines (kQuad segments),
  // each off-curve point pulling the outline between two on-curve points.
  const Result<Path> glyph = outline(figure, "g", {720.0, 440.0}, 260.0);
  figure.fill(glyph, with_alpha(kSky, 70));
  StrokeStyle edge;
  edge.width = 1.5;
  figure.stroke(glyph, kBlue, edge);
  if (glyph) {
    StrokeStyle hull;
    hull.width = 1.0;
    hull.dash_array = {3.0, 3.0};
    for (const PathElement& element : *glyph) {
      if (element.verb == PathVerb::kQuad || element.verb == PathVerb::kCubic) {
        PathBuilder polygon;
        polygon.move_to(element.points.front());
        for (Point p : element.points.subspan(1)) polygon.line_to(p);
        figure.stroke(polygon.build(), kControl, hull);
      }
    }
    for (const PathElement& element : *glyph) {
      if (element.verb == PathVerb::kClose) continue;
      for (std::size_t i = 1; i + 1 < element.points.size(); ++i)
        dot(figure, element.points[i], 3.0, kVermillion, true);
      if (!element.points.empty()) dot(figure, element.points.back(), 3.0, kBlue, false);
    }
  }
  figure.text("\xE2\x97\x8F on-curve   \xE2\x97\x8B off-curve (quadratic control points)", {940.0, 560.0},
              12.0, kMutedInk, TextAnchor::kEnd);
  return std::move(figure).finish();
}

}  // namespace curvescan::figure
