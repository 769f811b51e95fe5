// Glyphs on a <textPath> with letter-spacing (SVG 1.1 10.13.3 and 10.11): each glyph's midpoint — half
// its own advance past its start — is put on the path, the glyph turned to the tangent there; the spacing
// is space after the glyph, so it moves the next glyph along the path but not this glyph's midpoint.
//
// The path runs 20 units right, then down: "T" (advance ~12 at 20 px) has its midpoint on the horizontal
// part and is drawn upright as plain text would be; with letter-spacing 40 counted into its advance its
// midpoint would fall past the corner and it would be turned by 90 degrees. "I", 40 units further on, is on
// the vertical part, turned by 90 degrees about its own midpoint.
//
// Oracle: the library's layout of "TI" (text_layout.h: the same advances HarfBuzz gives the SVG side),
// each glyph's outline filled through Canvas under the transform computed here from the path's geometry.
// Tolerance: max |Δ| <= 1/255 per channel — same curves, same rasterizer; only the composition of the
// transforms differs (~1e-13 px). A glyph turned the wrong way or moved by the spacing differs by ~255.
#include <catch2/catch.hpp>
#include <numbers>
#include <string>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/svg/document.h"
#include "curvescan/text/font_lookup.h"
#include "curvescan/text/text_layout.h"
#include "svg_test_support.h"

using namespace curvescan;
using curvescan::svg::testing::inked_pixels;
using curvescan::svg::testing::max_delta;

TEST_CASE("svg textPath: letter-spacing moves the next glyph, not a glyph's midpoint") {
  Result<Font> font = load_font(FontQuery{"DejaVu Sans", 400, false}, false);
  REQUIRE(font.is_ok());
  TextStyle style;
  style.size = 20.0;
  style.ligatures = false;  // as SVG text shapes letter-spaced text (docs/svg.md, letter-spacing)
  const Result<TextLayout> layout = layout_text(*font, U"TI", {0.0, 0.0}, style);
  REQUIRE(layout.is_ok());
  REQUIRE(layout->glyphs.size() == 2);
  const double t_advance = layout->glyphs[0].advance, i_advance = layout->glyphs[1].advance;
  REQUIRE(t_advance / 2.0 < 20.0);           // T's midpoint is before the corner...
  REQUIRE((t_advance + 40.0) / 2.0 > 20.0);  // ...and half its spaced advance would be past it
  // The path: (10, 40) right to (30, 40), then down to (30, 140).
  const Affine t_place = Affine::translate(10.0, 40.0);        // on the horizontal part, unturned
  const double i_middle = t_advance + 40.0 + i_advance / 2.0;  // distance along the path
  const Affine i_place = Affine::translate(30.0, 40.0 + (i_middle - 20.0)) *
                         Affine::rotate(std::numbers::pi / 2.0) * Affine::translate(-i_advance / 2.0, 0.0);
  Result<Canvas> canvas = Canvas::create(100, 160);
  REQUIRE(canvas.is_ok());
  for (const auto& [glyph, place] :
       {std::pair{layout->glyphs[0], t_place}, std::pair{layout->glyphs[1], i_place}}) {
    PathBuilder builder;
    REQUIRE(font->append_glyph(glyph.glyph,
                               place * Affine{20.0 / font->metrics().units_per_em, 0.0, 0.0,
                                              -20.0 / font->metrics().units_per_em, 0.0, 0.0},
                               builder)
                .is_ok());
    REQUIRE(canvas
                ->fill(builder.build().value(), Paint::solid({0, 0, 0, 1}), FillRule::kNonZero,
                       Affine::identity())
                .is_ok());
  }
  const Image expected = std::move(*canvas).take_image();
  CHECK(inked_pixels(expected) > 50);  // both glyphs draw something, or "equal" proves nothing

  const std::string document =
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="160"><defs><path id="p" d="M 10 40 H 30 V 140"/></defs>)"
      R"(<text font-family="DejaVu Sans" font-size="20" letter-spacing="40"><textPath href="#p">TI</textPath></text></svg>)";
  Result<svg::RenderedDocument> rendered = svg::render_svg_document(document, svg::RenderOptions{});
  REQUIRE(rendered.is_ok());
  CHECK(rendered->warnings.empty());
  CHECK(max_delta(expected, rendered->image) <= 1);
}
