// `curvescan text` with a colour font (tests/fonts/CurvescanColourTest.ttf): a COLR version 0 glyph is
// drawn as its layers, the foreground layer in --color; a COLR version 1 glyph is drawn as its plain
// outline with one warning per font; an SVG glyph as its document's element, as SVG text draws it. The oracle
// and its tolerance: tests/support/colour_glyph_oracle.h.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <string>

#include "colour_glyph_oracle.h"
#include "curvescan/raster/png_io.h"
#include "run_command.h"

namespace curvescan::test {
namespace {

const std::string kColourFont = std::string(CURVESCAN_SOURCE_DIR) + "/tests/fonts/CurvescanColourTest.ttf";

struct ColourRun {
  CommandOutput output;
  Image image;
};

// At --size 100 and --margin 0 the canvas is the line box: the advance (700 units, 70 px) wide, from the
// ascender (800 units) to the descender (200 units): the pen at x = 0, the baseline at y = 80.
ColourRun run_colour_text(const std::string& colour, const std::string& text) {
  const auto dir = scratch_directory("colour-text");
  const std::filesystem::path png = dir / "out.png";
  ColourRun run;
  run.output = run_curvescan("text --font " + shell_quote(kColourFont) + " --size 100 --margin 0 --color " +
                                 shell_quote(colour) + " --background white " + shell_quote(text) + " -o " +
                                 shell_quote(png.string()),
                             dir);
  if (run.output.exit_code == 0) {
    Result<Image> image = read_png(png);
    REQUIRE(image.is_ok());
    run.image = std::move(image).value();
  }
  return run;
}

}  // namespace

TEST_CASE("text command: a COLR v0 glyph draws its palette layers, the foreground layer in --color") {
  const ColourRun run = run_colour_text("#00ff00", "A");
  REQUIRE(run.output.exit_code == 0);
  CHECK(run.output.err.empty());
  REQUIRE(run.image.width() == 70);
  REQUIRE(run.image.height() == 100);
  CHECK(colour_glyph_max_delta(run.image, ColourGlyphScene{0, 80, Color{0, 1, 0, 1}}) <= 1);
  // A translucent --color fades the palette layers too.
  const ColourRun faded = run_colour_text("#00ff0080", "A");
  REQUIRE(faded.output.exit_code == 0);
  CHECK(colour_glyph_max_delta(faded.image, ColourGlyphScene{0, 80, Color{0, 1, 0, 128.0 / 255.0}}) <= 1);
}

TEST_CASE(
    "text command: COLR v1 glyphs are drawn as outlines with one warning, SVG glyphs as their document") {
  const ColourRun run = run_colour_text("black", "BCBC");
  REQUIRE(run.output.exit_code == 0);
  // One warning for COLR v1 however often its glyphs appear; none for the SVG glyph, whose document is drawn.
  CHECK(run.output.err ==
        "curvescan text: warning: COLR v1 colour glyphs in font 'Curvescan Colour Test' are "
        "drawn as plain outlines\n");
  REQUIRE(run.image.width() == 280);
  // B's outline (0,0)-(600,600) in black: x 0..60, y 20..80.
  CHECK(run.image.at(30, 50) == Rgba8{0, 0, 0, 255});
  // C's document: a green rect (0,-600)-(600,0) in font units with y down, its origin at the glyph's, so
  // the square x 70..130, y 20..80 (whole pixels: exact coverage, no tolerance), green, not --color.
  for (const int x : {70, 100, 129, 210, 249}) {
    INFO(x);
    CHECK(run.image.at(x, 20) == Rgba8{0, 128, 0, 255});
    CHECK(run.image.at(x, 79) == Rgba8{0, 128, 0, 255});
  }
  CHECK(run.image.at(69, 50) == Rgba8{255, 255, 255, 255});   // between B and C
  CHECK(run.image.at(130, 50) == Rgba8{255, 255, 255, 255});  // after C's square
  CHECK(run.image.at(100, 19) == Rgba8{255, 255, 255, 255});  // above it
}

// Regression: the canvas was sized from the glyphs' outlines, so an SVG glyph whose document draws beyond
// its outline was cropped to the outline's box (and the line box).
TEST_CASE("text command: the canvas holds an SVG glyph's document where it draws beyond the outline") {
  const ColourRun run = run_colour_text("black", "E");
  REQUIRE(run.output.exit_code == 0);
  CHECK(run.output.err.empty());
  // E's document is a green rect from (-200,-1000) to (900,300) font units, y down: at 100 px to the em,
  // x -20..90 and y -100..30 around the glyph's origin, beyond its outline (0..60, -60..0) and its line
  // box (0..70, -80..20) on every side. With --margin 0 the canvas is exactly that rect (its edges fall on
  // whole pixels, so no rounding), and every pixel of it is green.
  REQUIRE(run.image.width() == 110);
  REQUIRE(run.image.height() == 130);
  for (const int x : {0, 55, 109}) {
    for (const int y : {0, 65, 129}) {
      INFO(x << ", " << y);
      CHECK(run.image.at(x, y) == Rgba8{0, 128, 0, 255});
    }
  }
}

TEST_CASE("text command: a translucent --color fades an SVG glyph's document as a whole") {
  const ColourRun run = run_colour_text("#00000080", "C");
  REQUIRE(run.output.exit_code == 0);
  CHECK(run.output.err.empty());
  // Green (0, 128, 0) at alpha 128/255 over white: 255 (1 - a) and 128 a + 255 (1 - a) per channel, each
  // rounded once by the layer's composite (tolerance 1).
  const double a = 128.0 / 255.0;
  const Rgba8 centre = run.image.at(30, 50);
  CHECK(std::abs(centre.r - 255.0 * (1.0 - a)) <= 1.0);
  CHECK(std::abs(centre.g - (128.0 * a + 255.0 * (1.0 - a))) <= 1.0);
  CHECK(std::abs(centre.b - 255.0 * (1.0 - a)) <= 1.0);
  CHECK(centre.a == 255);
}

TEST_CASE("text command: an SVG glyph document that is not SVG draws the outline in --color, warned once") {
  const auto dir = scratch_directory("broken-svg-glyph");
  const std::filesystem::path png = dir / "out.png";
  const CommandOutput output = run_curvescan(
      "text --font " +
          shell_quote(std::string(CURVESCAN_SOURCE_DIR) + "/tests/fonts/CurvescanBrokenSvgTest.ttf") +
          " --size 100 --margin 0 --color blue --background white CC -o " + shell_quote(png.string()),
      dir);
  REQUIRE(output.exit_code == 0);
  CHECK(output.err ==
        "curvescan text: warning: an SVG glyph document is not a well-formed SVG document (the root element "
        "is <html>, not <svg>); its glyphs are drawn as plain outlines\n");
  Result<Image> image = read_png(png);
  REQUIRE(image.is_ok());
  CHECK(image->at(30, 50) == Rgba8{0, 0, 255, 255});   // the first C's outline (0,0)-(600,600) in blue
  CHECK(image->at(100, 50) == Rgba8{0, 0, 255, 255});  // the second's
  // -q silences the warning.
  const auto quiet_dir = scratch_directory("broken-svg-glyph-quiet");
  const CommandOutput quiet = run_curvescan(
      "text -q --font " +
          shell_quote(std::string(CURVESCAN_SOURCE_DIR) + "/tests/fonts/CurvescanBrokenSvgTest.ttf") +
          " --size 100 C -o " + shell_quote((quiet_dir / "out.png").string()),
      quiet_dir);
  CHECK(quiet.exit_code == 0);
  CHECK(quiet.err.empty());
}

}  // namespace curvescan::test
