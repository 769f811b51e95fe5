// `curvescan text`: the canvas fits the text, margins stay background, lines stack, colours apply,
// missing glyphs warn, and every failure is one line on stderr, exit 3 (64 for usage) and no output file.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "curvescan/raster/png_io.h"
#include "curvescan/text/text_layout.h"
#include "run_command.h"

namespace curvescan::test {
namespace {

constexpr const char* kDejaVuSans = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

struct TextRun {
  CommandOutput output;
  Image image;  // empty unless the command succeeded
  bool output_exists = false;
};

TextRun run_text(const std::string& arguments, const std::string& stdin_text = "") {
  const auto dir = scratch_directory("text");
  const std::filesystem::path png = dir / "out.png";
  std::string command = "text " + arguments + " -o " + shell_quote(png.string());
  if (!stdin_text.empty()) {
    write_text(dir / "input.txt", stdin_text);
    command += " < " + shell_quote((dir / "input.txt").string());
  }
  TextRun run;
  run.output = run_curvescan(command, dir);
  run.output_exists = std::filesystem::exists(png);
  if (run.output.exit_code == 0 && run.output_exists) {
    Result<Image> image = read_png(png);
    REQUIRE(image.is_ok());
    run.image = std::move(image).value();
  }
  return run;
}

bool row_is_blank(const Image& image, int y) {
  for (int x = 0; x < image.width(); ++x)
    if (image.at(x, y).a != 0) return false;
  return true;
}
bool column_is_blank(const Image& image, int x) {
  for (int y = 0; y < image.height(); ++y)
    if (image.at(x, y).a != 0) return false;
  return true;
}

void check_one_line_error(const TextRun& run, const std::string& expected_part) {
  CHECK(run.output.exit_code == 3);
  CHECK_FALSE(run.output_exists);
  CHECK(run.output.err.find("curvescan text: error: ") == 0);
  CHECK(run.output.err.find(expected_part) != std::string::npos);
  CHECK(run.output.err.find('\n') == run.output.err.size() - 1);
}

}  // namespace

TEST_CASE("text: the canvas is the text's extent plus the margin, and the margin stays empty",
          "[cli][text]") {
  const TextRun run = run_text("'Hag' --font " + shell_quote(kDejaVuSans) + " --size 40 --margin 6");
  REQUIRE(run.output.exit_code == 0);
  CHECK(run.output.err.empty());
  // The same layout through the library: line box and outline bounds, rounded out, plus 6 px each side.
  Result<Font> font = Font::open(kDejaVuSans);
  REQUIRE(font.is_ok());
  TextStyle style;
  style.size = 40.0;
  const Result<TextLayout> layout = layout_text(*font, U"Hag", {0.0, 0.0}, style);
  const Result<Path> path = text_path(*font, "Hag", {0.0, 0.0}, style);
  REQUIRE(layout.is_ok());
  REQUIRE(path.is_ok());
  Rect extent = layout->line_box();
  extent.include({path->tight_bounds().x0, path->tight_bounds().y0});
  extent.include({path->tight_bounds().x1, path->tight_bounds().y1});
  CHECK(run.image.width() == static_cast<int>(std::ceil(extent.x1 + 6) - std::floor(extent.x0 - 6)));
  CHECK(run.image.height() == static_cast<int>(std::ceil(extent.y1 + 6) - std::floor(extent.y0 - 6)));
  // Ink never reaches into the 6-px margin (5 whole pixels after rounding out) on any side.
  for (int i = 0; i < 5; ++i) {
    CHECK(row_is_blank(run.image, i));
    CHECK(row_is_blank(run.image, run.image.height() - 1 - i));
    CHECK(column_is_blank(run.image, i));
    CHECK(column_is_blank(run.image, run.image.width() - 1 - i));
  }
  int inked = 0;
  for (const Rgba8& p : run.image.pixels()) inked += p.a == 255 ? 1 : 0;
  CHECK(inked > 100);  // 40-px letters have solid stems
}

TEST_CASE("text: lines from standard input stack one line height apart", "[cli][text]") {
  const std::string font = " --font " + shell_quote(kDejaVuSans) + " --size 30 --margin 0";
  const TextRun one = run_text("-i -" + font, "xx\n");
  const TextRun three = run_text("-i -" + font, "xx\nxx\nxx\n");
  REQUIRE(one.output.exit_code == 0);
  REQUIRE(three.output.exit_code == 0);
  Result<Font> dejavu = Font::open(kDejaVuSans);
  REQUIRE(dejavu.is_ok());
  const double line_height = dejavu->metrics().line_height * 30.0 / dejavu->metrics().units_per_em;
  // Two more lines; each image rounds its extent out to whole pixels, so +-1 px.
  CHECK(std::abs(three.image.height() - one.image.height() - 2.0 * line_height) <= 1.0);
  CHECK(three.image.width() == one.image.width());
}

TEST_CASE("text: colour and background", "[cli][text]") {
  const TextRun run =
      run_text("'I' --font " + shell_quote(kDejaVuSans) + " --size 60 --color '#ff0000' --background blue");
  REQUIRE(run.output.exit_code == 0);
  CHECK(run.image.at(0, 0) == Rgba8{0, 0, 255, 255});
  bool red = false;
  for (const Rgba8& p : run.image.pixels()) red = red || p == Rgba8{255, 0, 0, 255};
  CHECK(red);
}

TEST_CASE("text: a character the font lacks draws .notdef and warns", "[cli][text]") {
  const std::string cantarell = "/usr/share/fonts/opentype/cantarell/Cantarell-Regular.otf";
  const TextRun run = run_text(shell_quote("a\xE4\xB8\xAD") + " --font " + shell_quote(cantarell));
  CHECK(run.output.exit_code == 0);
  CHECK(run.output.err.find("warning") != std::string::npos);
  CHECK(run.output.err.find("U+4E2D") != std::string::npos);
  CHECK(run.output.err.find(".notdef") != std::string::npos);
}

TEST_CASE("text: a family name goes through fontconfig", "[cli][text]") {
  const TextRun run = run_text("'Bold' --font 'DejaVu Sans' --weight 700");
  CHECK(run.output.exit_code == 0);
  CHECK(run.output_exists);
}

TEST_CASE("text: errors are one line, exit 3, and leave no output", "[cli][text]") {
  // Each names where the text came from and what to do.
  check_one_line_error(
      run_text("-i -", "\n"),
      "error: the text on standard input is empty (a final line break is not drawn): nothing to "
      "draw\n");
  check_one_line_error(run_text("x --font /nonexistent/font.ttf"), "does not exist");
  check_one_line_error(run_text("x --font 'No Such Family 9876'"), "No Such Family 9876");
  check_one_line_error(
      run_text("-i -", "ok \xC3"),
      "error: the text on standard input is not valid UTF-8: byte 0xC3 at offset 3 (the 4th byte) "
      "starts a character that the text ends before completing; give the text in UTF-8 (iconv -f "
      "ENCODING -t UTF-8 converts it from another encoding)\n");
  check_one_line_error(
      run_text("-i -", std::string("\xFF\xFEh\0i\0", 6)),
      "error: the text on standard input is not valid UTF-8: byte 0xFF at offset 0 (the 1st byte) "
      "never occurs in UTF-8; it starts with a UTF-16 byte order mark: convert it with iconv -f "
      "UTF-16 -t UTF-8\n");
  // A --size outside (0, 32767] is a usage error (64), checked by CLI11 before anything is read.
  for (const char* size : {"0", "-20", "1e9"}) {
    const TextRun out_of_range = run_text(std::string("x --size ") + size);
    CHECK(out_of_range.output.exit_code == 64);
    CHECK_FALSE(out_of_range.output_exists);
    CHECK(out_of_range.output.err.find("--size: '" + std::string(size) +
                                      "' is out of range: give a number more than 0 and at most 32767") !=
          std::string::npos);
  }
  // A side beyond 32767 pixels: raising --max-pixels would not help, and the message does not say it would.
  // (The sizes depend on the font fontconfig picks: not checked here.)
  const TextRun huge = run_text("'x' --size 30000");
  check_one_line_error(huge, "error: the text at --size 30000 with margins of 7500 pixels needs ");
  CHECK(huge.output.err.find(
            " pixels, beyond the limit of 32767 pixels per side (use a smaller --size, --margin or "
            "--line-height, or fewer lines)\n") != std::string::npos);
  const TextRun over = run_text("Hello --max-pixels 100");
  check_one_line_error(over, "error: the text at --size 32 with margins of 8 pixels needs ");
  CHECK(over.output.err.find(
            " in all, beyond the limit of 100 pixels (raise --max-pixels, up to 67108864, or use a "
            "smaller --size or --margin)\n") != std::string::npos);
  {  // A colour that is not CSS is a wrong command line: usage error, nothing written.
    const TextRun bad_colour = run_text("x --color notacolour");
    CHECK(bad_colour.output.exit_code == 64);
    CHECK_FALSE(bad_colour.output_exists);
    CHECK(bad_colour.output.err.find("--color") != std::string::npos);
  }

  const auto dir = scratch_directory("text-corrupt");
  // "OTTO" claims an OpenType file, whose table directory the 30 bytes cannot hold: named as cut.
  write_text(dir / "corrupt.ttf", "OTTO this is not really a font");
  check_one_line_error(run_text("x --font " + shell_quote((dir / "corrupt.ttf").string())),
                       "is truncated or corrupt: the table directory is cut short");
  write_text(dir / "text.ttf", "this is not a font at all");
  check_one_line_error(run_text("x --font " + shell_quote((dir / "text.ttf").string())), "not a font file");
  // A symbolic link loop is a file the system cannot open, not a family name fontconfig lacks.
  std::filesystem::create_symlink(dir / "loop-b", dir / "loop-a");
  std::filesystem::create_symlink(dir / "loop-a", dir / "loop-b");
  const TextRun loop = run_text("x --font " + shell_quote((dir / "loop-a").string()));
  check_one_line_error(loop, "Too many levels of symbolic links");
  CHECK(loop.output.err.find("font family") == std::string::npos);
}

TEST_CASE("text: a bitmap colour glyph is drawn as its image", "[cli][text]") {
  // tests/fonts/CurvescanCbdtTest.ttf: a 30 x 30 image at 50 pixels per em, no outlines; its quadrants are
  // 13 x 13 pixels inside a 2-pixel transparent border. At --size 50 the strike is drawn one image pixel
  // to one canvas pixel, on whole pixels (the line box's top, -40, and the glyph origin, 0, are whole), so
  // the red quadrant is exactly 13 x 13 pure red pixels.
  const std::string font = std::string(CURVESCAN_SOURCE_DIR) + "/tests/fonts/CurvescanCbdtTest.ttf";
  const TextRun run = run_text("A --font " + shell_quote(font) + " --size 50 --margin 0 --background white");
  REQUIRE(run.output.exit_code == 0);
  CHECK(run.output.err.empty());
  const auto count = [](const Image& image, Rgba8 colour) {
    return std::count_if(image.pixels().begin(), image.pixels().end(),
                         [&](const Rgba8& p) { return p == colour; });
  };
  CHECK(count(run.image, Rgba8{255, 0, 0, 255}) == 13 * 13);
  CHECK(count(run.image, Rgba8{0, 0, 255, 255}) == 13 * 13);
  // A translucent text colour fades the image as it fades a palette layer: red at alpha 0.5 over white.
  const TextRun faded = run_text("A --font " + shell_quote(font) +
                                 " --size 50 --margin 0 --background white --color 'rgba(0,0,0,0.5)'");
  REQUIRE(faded.output.exit_code == 0);
  CHECK(count(faded.image, Rgba8{255, 0, 0, 255}) == 0);
  CHECK(count(faded.image, Rgba8{255, 127, 127, 255}) + count(faded.image, Rgba8{255, 128, 128, 255}) ==
        13 * 13);
}

TEST_CASE("text: an existing output file survives a failure", "[cli][text]") {
  const auto dir = scratch_directory("text-keep");
  const std::filesystem::path png = dir / "keep.png";
  write_text(png, "previous content");
  const CommandOutput output = run_curvescan("text '' -o " + shell_quote(png.string()), dir);
  CHECK(output.exit_code == 64);
  CHECK(read_text(png) == "previous content");
}

TEST_CASE("text: command-line mistakes are usage errors (64)", "[cli][text]") {
  const auto dir = scratch_directory("text-usage");
  CHECK(run_curvescan("text hello", dir).exit_code == 64);  // no -o
  CHECK(run_curvescan("text hello --size big -o x.png", dir).exit_code == 64);
  // No text at all, or an empty argument, is a command line without its operand; an empty file (above) is
  // an input that is not what it claims.
  const TextRun none = run_text("");
  CHECK(none.output.exit_code == 64);
  CHECK_FALSE(none.output_exists);
  CHECK(
      none.output.err.find(
          "usage error: no text to draw: give it as an argument, or with -i FILE (- for standard input)\n") !=
      std::string::npos);
  const TextRun empty = run_text("''");
  CHECK(empty.output.exit_code == 64);
  CHECK_FALSE(empty.output_exists);
  CHECK(empty.output.err.find("usage error: the text argument is empty: nothing to draw\n") !=
        std::string::npos);
}

TEST_CASE("text: -o - writes the PNG to standard output and no file", "[cli][text]") {
  const auto dir = scratch_directory("text-stdout");
  const CommandOutput output = run_curvescan("text Hi --font " + shell_quote(kDejaVuSans) + " --size 20 -o -", dir);
  REQUIRE(output.exit_code == 0);
  CHECK_FALSE(std::filesystem::exists(dir / "-"));
  const Result<Image> image = decode_png(
      std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(output.out.data()), output.out.size()));
  REQUIRE(image.is_ok());
  // The same image as with a file output.
  const TextRun file = run_text("Hi --font " + shell_quote(kDejaVuSans) + " --size 20");
  REQUIRE(file.output.exit_code == 0);
  CHECK(image->width() == file.image.width());
  CHECK(image->height() == file.image.height());
  CHECK(image->pixels() == file.image.pixels());
}

// Regression: `text -o -` on a terminal wrote the PNG's bytes to it. script(1) (util-linux, essential on
// Debian) gives the command a terminal for its standard output.
TEST_CASE("text: -o - refuses a terminal as standard output, as render does", "[cli][text]") {
  const auto dir = scratch_directory("text-stdout-terminal");
  const std::string command = shell_quote(curvescan_binary()) + " text Hi -o -; echo exit=$?";
  const CommandOutput output = run_shell("script -qec " + shell_quote(command) + " /dev/null", dir);
  CHECK(
      output.out.find("curvescan text: usage error: standard output is a terminal; name a PNG file with -o, "
                      "or redirect") != std::string::npos);
  CHECK(output.out.find("exit=64") != std::string::npos);
  CHECK(output.out.find("\x89PNG") == std::string::npos);  // no image: the PNG signature's first bytes
}

TEST_CASE("text: a line break in the argument starts a line one line height down", "[cli][text]") {
  const TextRun one = run_text("'Ag' --font " + shell_quote(kDejaVuSans) + " --size 30");
  const TextRun two = run_text(shell_quote("Ag\nAg") + " --font " + shell_quote(kDejaVuSans) + " --size 30");
  REQUIRE(one.output.exit_code == 0);
  REQUIRE(two.output.exit_code == 0);
  Result<Font> dejavu = Font::open(kDejaVuSans);
  REQUIRE(dejavu.is_ok());
  const double line_height = dejavu->metrics().line_height * 30.0 / dejavu->metrics().units_per_em;
  // Each image rounds its extent out to whole pixels, so +-1 px.
  CHECK(std::abs(two.image.height() - one.image.height() - line_height) <= 1.0);
}

TEST_CASE("text: each character no font has is named once", "[cli][text]") {
  // U+10FFFD (plane-16 private use) and U+10FFFC: no font of the tests' configuration maps them.
  const TextRun run = run_text(shell_quote("a\xF4\x8F\xBF\xBD b \xF4\x8F\xBF\xBD\xF4\x8F\xBF\xBC") +
                               " --font " + shell_quote(kDejaVuSans));
  REQUIRE(run.output.exit_code == 0);
  const auto occurrences = [&](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = run.output.err.find(what); at != std::string::npos; at = run.output.err.find(what, at + 1)) ++n;
    return n;
  };
  CHECK(occurrences("U+10FFFD") == 1);
  CHECK(occurrences("U+10FFFC") == 1);
  CHECK(occurrences("warning") == 2);
}

TEST_CASE("text: --direction rtl aligns lines on the right", "[cli][text]") {
  // "a\nabc" forced right to left: both lines end at the same x, so the short line's ink is at the right.
  const TextRun ltr = run_text(shell_quote("i\nmmmm") + " --font " + shell_quote(kDejaVuSans) + " --size 30");
  const TextRun rtl =
      run_text(shell_quote("i\nmmmm") + " --font " + shell_quote(kDejaVuSans) + " --size 30 --direction rtl");
  REQUIRE(ltr.output.exit_code == 0);
  REQUIRE(rtl.output.exit_code == 0);
  REQUIRE(ltr.image.width() == rtl.image.width());
  // The leftmost inked column of the first line (rows of the upper half).
  const auto first_ink_x = [](const Image& image) {
    for (int x = 0; x < image.width(); ++x)
      for (int y = 0; y < image.height() / 2; ++y)
        if (image.at(x, y).a != 0) return x;
    return -1;
  };
  // "i" is about 8 px wide and "mmmm" about 100 at 30 px: right-aligned, the i starts far right.
  CHECK(first_ink_x(rtl.image) - first_ink_x(ltr.image) > 50);
  CHECK(run_text("x --direction up").output.exit_code == 64);
}

TEST_CASE("text: every mandatory line break of Unicode starts a line", "[cli][text]") {
  const std::string font = " --font " + shell_quote(kDejaVuSans) + " --size 30";
  const TextRun reference = run_text(shell_quote("Ag\nAg") + font);
  REQUIRE(reference.output.exit_code == 0);
  // CR LF, a lone CR, NEL, VT, FF, LINE SEPARATOR and PARAGRAPH SEPARATOR (UAX #14 5.4): the same two
  // lines, pixel for pixel, and no warning (no .notdef for a control character).
  for (const std::string separator : {"\r\n", "\r", "\xC2\x85", "\v", "\f", "\xE2\x80\xA8", "\xE2\x80\xA9"}) {
    const TextRun run = run_text("-i -" + font, "Ag" + separator + "Ag\n");
    INFO("separator bytes: " << separator.size());
    REQUIRE(run.output.exit_code == 0);
    CHECK(run.output.err.empty());
    REQUIRE(run.image.width() == reference.image.width());
    REQUIRE(run.image.height() == reference.image.height());
    CHECK(run.image.pixels().size() == reference.image.pixels().size());
    CHECK(std::equal(run.image.pixels().begin(), run.image.pixels().end(), reference.image.pixels().begin()));
  }
}

TEST_CASE("text: --features turns OpenType features on and off", "[cli][text]") {
  const std::string dejavu = " --font " + shell_quote(kDejaVuSans) + " --size 40";
  // Two spellings of one feature setting draw the same pixels: -kern is --no-kerning ("AV" is a kerned
  // pair), -liga is --no-ligatures ("fi" is a ligature in DejaVu Sans).
  const TextRun kerned = run_text("AV" + dejavu);
  const TextRun unkerned = run_text("AV" + dejavu + " --no-kerning");
  const TextRun kern_off = run_text("AV" + dejavu + " --features=-kern");
  REQUIRE(kern_off.output.exit_code == 0);
  CHECK(kern_off.image.width() == unkerned.image.width());
  CHECK(kern_off.image.pixels() == unkerned.image.pixels());
  CHECK(kerned.image.width() < unkerned.image.width());  // the premise: kerning narrows "AV"
  const TextRun liga_off = run_text("fi" + dejavu + " --features=-liga");
  const TextRun no_ligatures = run_text("fi" + dejavu + " --no-ligatures");
  REQUIRE(liga_off.output.exit_code == 0);
  CHECK(liga_off.image.pixels() == no_ligatures.image.pixels());
  CHECK(liga_off.image.pixels() != run_text("fi" + dejavu).image.pixels());
  // smcp in a font that has it (Noto Sans Mono, fonts-noto-mono) changes the glyphs of "abc"; the mono
  // font keeps every advance, so the canvases are the same size and only the ink differs.
  const std::string mono = " --font /usr/share/fonts/truetype/noto/NotoSansMono-Regular.ttf --size 40";
  const TextRun plain = run_text("abc" + mono);
  const TextRun small_caps = run_text("abc" + mono + " --features smcp,salt=1");
  REQUIRE(small_caps.output.exit_code == 0);
  CHECK(small_caps.image.width() == plain.image.width());
  CHECK(small_caps.image.pixels() != plain.image.pixels());
  // A malformed list is a usage error, before anything is drawn.
  for (const char* bad : {"smc", "smcp=x", "smcp=70000", "smcp,,liga", "-"}) {
    INFO(bad);
    const TextRun run = run_text(std::string("abc") + dejavu + " --features=" + shell_quote(bad));
    CHECK(run.output.exit_code == 64);
    CHECK_FALSE(run.output_exists);
  }
}

TEST_CASE("text: --vertical runs lines top to bottom, the next one to the left", "[cli][text]") {
  const std::string font = " --font " + shell_quote(kDejaVuSans) + " --size 40 --margin 0";
  const TextRun horizontal = run_text("abcd" + font);
  const TextRun vertical = run_text("abcd" + font + " --vertical");
  REQUIRE(vertical.output.exit_code == 0);
  CHECK(horizontal.image.width() > horizontal.image.height());
  CHECK(vertical.image.height() > vertical.image.width());
  // Two lines: the first ("a") stands right of the second ("bbb"), which is longer.
  const TextRun two = run_text("-i -" + font + " --vertical", "a\nbbb\n");
  REQUIRE(two.output.exit_code == 0);
  CHECK(two.image.width() > vertical.image.width());
  const auto ink_rows = [](const Image& image, int x0, int x1) {
    int rows = 0;
    for (int y = 0; y < image.height(); ++y) {
      bool inked = false;
      for (int x = x0; x < x1; ++x) inked = inked || image.at(x, y).a != 0;
      rows += inked ? 1 : 0;
    }
    return rows;
  };
  const int half = two.image.width() / 2;
  CHECK(ink_rows(two.image, 0, half) > ink_rows(two.image, half, two.image.width()));
}

}  // namespace curvescan::test
