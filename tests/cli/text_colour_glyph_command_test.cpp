// `curvescan text` with a colour font (tests/fonts/CurvescanColourTest.ttf): a COLR version 0 glyph is
// drawn as its layers, the foreground layer in --color; COLR version 1 and SVG glyphs are drawn as plain
// outlines with one warning per kind. The oracle and its tolerance: tests/support/colour_glyph_oracle.h.
#include <catch2/catch.hpp>
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
  std::filesystem::remove_all(dir);
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

TEST_CASE("text command: COLR v1 and SVG colour glyphs are drawn as outlines with one warning each") {
  const ColourRun run = run_colour_text("black", "BCBC");
  REQUIRE(run.output.exit_code == 0);
  const std::string& err = run.output.err;
  const std::string v1 =
      "curvescan text: warning: COLR v1 colour glyphs in font 'Curvescan Colour Test' are "
      "drawn as plain outlines\n";
  const std::string svg =
      "curvescan text: warning: SVG colour glyphs in font 'Curvescan Colour Test' are drawn "
      "as plain outlines\n";
  CHECK(err == v1 + svg);
  // B's outline (0,0)-(600,600) in black: x 0..60, y 20..80.
  CHECK(run.image.at(30, 50) == Rgba8{0, 0, 0, 255});
}

}  // namespace curvescan::test
