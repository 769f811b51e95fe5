// `curvescan render` as a drop-in for rsvg-convert's PNG use: each flag run through both programs on the
// same documents, comparing the image size exactly and colours at sample points away from every edge
// (where exact-area coverage and Cairo's antialiasing agree to the byte). rsvg-convert comes from Debian's
// librsvg2-bin, which the build installs; where it is missing these cases say so and check nothing.
// Also: gzip input, batch rendering into a directory, and the format and name checks.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "curvescan/raster/png_io.h"
#include "render_cli.h"
#include "run_command.h"

using namespace curvescan;
using namespace curvescan::test;

namespace {

bool have_rsvg_convert() {
  if (std::system("command -v rsvg-convert >/dev/null 2>&1") == 0) return true;
  WARN("rsvg-convert is not installed: curvescan render is not compared with it");
  return false;
}

// 100 x 50 px: a red rectangle under a blue circle of radius 20 at its centre.
const std::string kWide =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100\" height=\"50\" viewBox=\"0 0 100 50\">"
    "<rect width=\"100\" height=\"50\" fill=\"#ff0000\"/><circle cx=\"50\" cy=\"25\" r=\"20\" "
    "fill=\"#0000ff\"/>"
    "</svg>";
// Physical units: 2in x 1cm, a green square in its top-left corner.
const std::string kPhysical =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"2in\" height=\"1cm\" viewBox=\"0 0 20 10\">"
    "<rect width=\"10\" height=\"10\" fill=\"#00ff00\"/></svg>";
// Physical units inside the drawing, no viewBox: with -d and -p different, x-like lengths follow -d,
// y-like ones -p, and r and stroke-width sqrt((d² + p²) / 2), as in librsvg 2.54.
const std::string kPhysicalInside =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"4in\" height=\"3in\">"
    "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>"
    "<rect x=\"0.5in\" y=\"0.25in\" width=\"1.5in\" height=\"1in\" fill=\"#ff0000\"/>"
    "<circle cx=\"3in\" cy=\"1.9cm\" r=\"2cm\" fill=\"#0000ff\" stroke=\"#00ff00\" stroke-width=\"18pt\"/>"
    "<ellipse cx=\"1.25in\" cy=\"2.25in\" rx=\"0.75in\" ry=\"12mm\" fill=\"#ffcc00\"/>"
    "<line x1=\"2.3in\" y1=\"2.6in\" x2=\"3.8in\" y2=\"2.6in\" stroke=\"#800080\" stroke-width=\"20pt\"/>"
    "</svg>";
// No viewBox, width or height: the natural size is the drawing's ink box (54 x 34 with the stroke),
// the drawing not moved.
const std::string kUnsized =
    "<svg xmlns=\"http://www.w3.org/2000/svg\"><rect x=\"10\" y=\"20\" width=\"50\" height=\"30\" "
    "fill=\"#ff0000\" stroke=\"#000000\" stroke-width=\"4\"/></svg>";
// Width or height missing or a percentage: rsvg-convert takes the size from the viewBox's aspect ratio
// when there is one, else from the ink box, and then fits the root's own width x height (as a viewBox it
// synthesizes) into that size, so that one axis may be scaled alone or the drawing centred.
const std::string kWidthOnly =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"80\"><rect x=\"10\" y=\"20\" width=\"40\" "
    "height=\"30\" fill=\"#00ff00\"/><rect x=\"30\" y=\"30\" width=\"20\" height=\"20\" "
    "fill=\"#0000ff\"/></svg>";
const std::string kHeightOnly =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" height=\"60\"><rect x=\"10\" y=\"20\" width=\"40\" "
    "height=\"30\" fill=\"#00ff00\"/><rect x=\"30\" y=\"30\" width=\"20\" height=\"20\" "
    "fill=\"#0000ff\"/></svg>";
const std::string kPercentages =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"50%\" height=\"100%\"><rect x=\"10\" y=\"20\" "
    "width=\"40\" height=\"30\" fill=\"#00ff00\"/><rect x=\"50%\" y=\"50%\" width=\"10\" height=\"10\" "
    "fill=\"#0000ff\"/></svg>";
const std::string kWidthAndViewBox =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"80\" viewBox=\"0 0 60 40\"><rect x=\"10\" y=\"20\" "
    "width=\"40\" height=\"30\" fill=\"#00ff00\"/></svg>";
const std::string kHeightAndViewBox =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"50%\" height=\"80\" viewBox=\"0 0 60 40\"><rect "
    "x=\"10\" y=\"20\" width=\"40\" height=\"30\" fill=\"#00ff00\"/></svg>";
// --export-id: a group moved by its transform (ignored for its children's export), a circle with a
// transform and a stroke of its own (its ink box 140 x 140), a rectangle that inherits its fill.
const std::string kExport =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"100\" viewBox=\"0 0 400 200\">"
    "<g id=\"g\" transform=\"translate(100 50)\" fill=\"#00ff00\">"
    "<circle id=\"c\" cx=\"40\" cy=\"40\" r=\"30\" transform=\"scale(2)\" stroke=\"#000000\" "
    "stroke-width=\"10\"/><rect id=\"r\" x=\"5\" y=\"5\" width=\"10\" height=\"20\"/></g></svg>";

/// The straight (unpremultiplied) colour at (x, y) as r, g, b, a.
std::array<int, 4> colour_at(const Image& image, int x, int y) {
  const auto p = image.at(x, y);
  if (p.a == 0) return {0, 0, 0, 0};
  const auto straight = [&](int c) { return (c * 255 + p.a / 2) / p.a; };
  return {straight(p.r), straight(p.g), straight(p.b), p.a};
}

/// gzip -c `from` > `to` (in a shell of its own: run_shell sends the command's standard output to a file).
bool gzip_file(const std::filesystem::path& from, const std::filesystem::path& to,
               const std::filesystem::path& scratch) {
  return run_shell("sh -c " + shell_quote("gzip -c " + shell_quote(from.string()) + " > " +
                                          shell_quote(to.string())),
                   scratch)
                 .exit_code == 0 &&
         std::filesystem::file_size(to) > 0;
}

/// Renders `input` (a path) with `curvescan render FLAGS` into dir/ours.png and with `rsvg-convert FLAGS`
/// into dir/theirs.png, both under `environment` (a prefix such as "env LANG=C ", or empty); both must
/// succeed. Gives {ours, theirs}.
std::pair<Image, Image> render_both(const std::filesystem::path& dir, const std::string& flags,
                                    const std::filesystem::path& input, const std::string& environment = "") {
  const std::string in = shell_quote(input.string());
  const CommandOutput ours = run_shell(environment + shell_quote(curvescan_binary()) + " render " + flags +
                                           " " + in + " -o " + shell_quote((dir / "ours.png").string()),
                                       dir);
  INFO(ours.err);
  REQUIRE(ours.exit_code == 0);
  REQUIRE(run_shell(environment + "rsvg-convert " + flags + " " + in + " -o " +
                        shell_quote((dir / "theirs.png").string()),
                    dir)
              .exit_code == 0);
  return {read_png_or_fail(dir / "ours.png"), read_png_or_fail(dir / "theirs.png")};
}

}  // namespace

TEST_CASE("curvescan render matches rsvg-convert's image size and placement flag for flag") {
  if (!have_render_binary() || !have_rsvg_convert()) return;
  const auto dir = scratch_directory("render-rsvg");
  write_text(dir / "wide.svg", kWide);
  write_text(dir / "physical.svg", kPhysical);
  write_text(dir / "physical-inside.svg", kPhysicalInside);
  write_text(dir / "export.svg", kExport);
  write_text(dir / "unsized.svg", kUnsized);
  write_text(dir / "width-only.svg", kWidthOnly);
  write_text(dir / "height-only.svg", kHeightOnly);
  write_text(dir / "percentages.svg", kPercentages);
  write_text(dir / "width-viewbox.svg", kWidthAndViewBox);
  write_text(dir / "height-viewbox.svg", kHeightAndViewBox);
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"unsized.svg", ""},
      {"unsized.svg", "-z 2"},
      {"unsized.svg", "-w 200"},
      {"unsized.svg", "-h 200"},
      {"width-only.svg", ""},
      {"width-only.svg", "-w 200"},
      {"width-only.svg", "-h 200"},
      {"width-only.svg", "-w 200 -h 100"},
      {"height-only.svg", ""},
      {"height-only.svg", "-w 200"},
      {"height-only.svg", "-h 200 -z 2"},
      {"percentages.svg", ""},
      {"percentages.svg", "-w 200"},
      {"percentages.svg", "-h 200"},
      {"width-viewbox.svg", ""},
      {"width-viewbox.svg", "-h 200"},
      {"height-viewbox.svg", "-w 200"},
      {"height-viewbox.svg", "-w 200 -h 100 -a"},
      {"export.svg", "-i c"},
      {"export.svg", "-i '#c' -z 0.5"},
      {"export.svg", "-i r"},
      {"export.svg", "-i g"},
      {"export.svg", "-i c -w 50 -h 20"},
      {"wide.svg", ""},
      {"wide.svg", "-w 200"},
      {"wide.svg", "-h 30"},
      {"wide.svg", "-w 200 -h 200"},
      {"wide.svg", "-w 200 -h 200 -a"},
      {"wide.svg", "-z 3 -w 200"},
      {"wide.svg", "-z 3 -w 200 -a"},
      {"wide.svg", "-x 3 -y 0.5"},
      {"wide.svg", "-x 3 -y 0.5 -h 20 -a"},
      {"wide.svg", "-w 3cm"},
      {"wide.svg", "-w 1in -h 72pt"},
      {"wide.svg", "--page-width 300 --page-height 200 --left 10 --top 20"},
      {"wide.svg", "--page-width 3in --page-height 100.5 --left 1cm"},
      {"wide.svg", "-b '#00ff00' -z 0.5"},
      // -b none: no background, as rsvg-convert reads it (it was refused as not a colour).
      {"wide.svg", "-b none --page-width 200 --page-height 100 --left 50"},
      {"wide.svg", "-b None -z 2"},
      {"physical.svg", ""},
      {"physical.svg", "-d 192 -p 48"},
      {"physical.svg", "--dpi-x 300 --dpi-y 300 -z 0.5"},
      {"physical-inside.svg", "-d 96 -p 192"},
      {"physical-inside.svg", "-d 192 -p 96"},
      {"physical-inside.svg", "-d 150 -p 150"},
  };
  for (const auto& [file, flags] : runs) {
    INFO(file << " " << flags);
    const auto [a, b] = render_both(dir, flags, dir / file);
    CHECK(a.width() == b.width());
    CHECK(a.height() == b.height());
    // Colours on a 9 x 9 grid of sample points, skipping any point whose 3 x 3 neighbourhood is not one
    // colour in rsvg-convert's image (an edge nearby, where two antialiasing methods may differ).
    const int w = std::min(a.width(), b.width()), h = std::min(a.height(), b.height());
    int compared = 0;
    for (int i = 1; i <= 9; ++i) {
      for (int j = 1; j <= 9; ++j) {
        const int x = w * i / 10, y = h * j / 10;
        if (x < 1 || y < 1 || x + 1 >= w || y + 1 >= h) continue;
        bool uniform = true;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx)
            uniform = uniform && colour_at(b, x + dx, y + dy) == colour_at(b, x, y);
        if (!uniform) continue;
        INFO("at " << x << ", " << y);
        CHECK(colour_at(a, x, y) == colour_at(b, x, y));
        ++compared;
      }
    }
    CHECK(compared > 0);
  }
}

TEST_CASE("curvescan render: usage errors as rsvg-convert refuses them, exit 64") {
  if (!have_render_binary()) return;
  const auto dir = scratch_directory("render-usage");
  write_text(dir / "wide.svg", kWide);
  const std::string in = shell_quote((dir / "wide.svg").string());
  const auto usage = [&](const std::string& arguments, const std::string& message) {
    const CommandOutput result = run_curvescan("render " + arguments, dir);
    INFO(arguments << "\n" << result.err);
    CHECK(result.exit_code == 64);
    CHECK(result.err.find(message) != std::string::npos);
  };
  usage("-w 10% " + in + " -o o.png", "supported units are px, in, cm, mm, pt, pc");
  usage("-w 10em " + in + " -o o.png", "supported units are px, in, cm, mm, pt, pc");
  usage("-w 0 " + in + " -o o.png", "must be positive");
  usage("-z 2 -x 3 " + in + " -o o.png", "--zoom cannot be combined");
  usage("--page-width 300 " + in + " -o o.png", "--page-width and --page-height together");
  usage("-f pdf " + in + " -o o.pdf", "PNG is the one format");
  usage(in + " -o out.jpg", "PNG is the one format");
  usage("-b notacolour " + in + " -o o.png", "--background-color");
  usage(in + " " + in, "--output-dir");
  // An empty value is refused, as rsvg-convert refuses it: -o "$UNSET" must not mean standard output.
  usage(in + " -o ''", "--output: an empty value names nothing");
  usage("-i '' " + in + " -o o.png", "--export-id: an empty value names nothing");
  usage("-s '' " + in + " -o o.png", "--stylesheet: an empty value names nothing");
  usage("-l '' " + in + " -o o.png", "--accept-language: an empty value names nothing");
  // The parser's own errors (an unknown option, a missing value) name the subcommand as ours do.
  usage("--no-such-option " + in, "curvescan render: usage error: ");
  usage("-w", "curvescan render: usage error: ");
  usage("-w", "(run 'curvescan render --help')");
  CHECK_FALSE(std::filesystem::exists(dir / "out.jpg"));
  CHECK_FALSE(std::filesystem::exists(dir / "o.png"));
  const CommandOutput version = run_curvescan("render -v", dir);
  CHECK(version.exit_code == 0);
  CHECK(version.out.find("curvescan ") == 0);
  const CommandOutput help = run_curvescan("render -?", dir);
  CHECK(help.exit_code == 0);
  CHECK(help.out.find("--keep-aspect-ratio") != std::string::npos);
  // -f PNG in any case, as rsvg-convert accepts it; no -o: the PNG goes to standard output.
  const CommandOutput piped = run_curvescan("render -f PNG " + in, dir);
  CHECK(piped.exit_code == 0);
  REQUIRE(piped.out.size() > 8);
  CHECK(piped.out.substr(1, 3) == "PNG");
}

TEST_CASE("curvescan render reads gzip-compressed SVG (.svgz, or gzip on standard input) within its limit") {
  if (!have_render_binary()) return;
  const auto dir = scratch_directory("render-gzip");
  write_text(dir / "wide.svg", kWide);
  REQUIRE(gzip_file(dir / "wide.svg", dir / "wide.svgz", dir));
  CHECK(run_curvescan("render " + shell_quote((dir / "wide.svgz").string()) + " -o " +
                          shell_quote((dir / "a.png").string()),
                      dir)
            .exit_code == 0);
  CHECK(read_png_or_fail(dir / "a.png").width() == 100);
  CHECK(run_shell(shell_quote(curvescan_binary()) + " render -o " + shell_quote((dir / "b.png").string()) +
                      " < " + shell_quote((dir / "wide.svgz").string()),
                  dir)
            .exit_code == 0);
  CHECK(read_png_or_fail(dir / "b.png").height() == 50);
  // Truncated: a clear error, exit 3, no output.
  const std::string whole = read_text(dir / "wide.svgz");
  write_text(dir / "cut.svgz", whole.substr(0, whole.size() / 2));
  const CommandOutput cut = run_curvescan(
      "render " + shell_quote((dir / "cut.svgz").string()) + " -o " + shell_quote((dir / "c.png").string()),
      dir);
  CHECK(cut.exit_code == 3);
  CHECK(cut.err.find("truncated") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "c.png"));
  // 3 MiB of spaces compress to a few KiB; uncompressed they pass --max-input-size 1 (MiB).
  write_text(dir / "big.svg", "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1\" height=\"1\">" +
                                  std::string(3 << 20, ' ') + "</svg>");
  REQUIRE(gzip_file(dir / "big.svg", dir / "big.svgz", dir));
  REQUIRE(std::filesystem::file_size(dir / "big.svgz") < (1u << 20));
  const CommandOutput bomb =
      run_curvescan("render --max-input-size 1 " + shell_quote((dir / "big.svgz").string()) + " -o " +
                        shell_quote((dir / "d.png").string()),
                    dir);
  CHECK(bomb.exit_code == 3);
  CHECK(bomb.err.find("--max-input-size") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "d.png"));
}

TEST_CASE("curvescan render FILE... --output-dir: a batch on a thread pool, failures reported, a manifest") {
  if (!have_render_binary()) return;
  const auto dir = scratch_directory("render-batch");
  std::filesystem::create_directories(dir / "in");
  for (int i = 0; i < 6; ++i) write_text(dir / "in" / ("icon" + std::to_string(i) + ".svg"), kWide);
  write_text(dir / "in" / "broken.svg", "<svg xmlns=\"http://www.w3.org/2000/svg\"><rect></svg>");
  std::string list;
  for (int i = 0; i < 6; ++i) list += (dir / "in" / ("icon" + std::to_string(i) + ".svg")).string() + "\n";
  list += (dir / "in" / "broken.svg").string() + "\n";
  write_text(dir / "list.txt", list);
  const CommandOutput batch =
      run_curvescan("render -j 2 -w 20 --files-from " + shell_quote((dir / "list.txt").string()) +
                        " --output-dir " + shell_quote((dir / "out").string()) + " --manifest " +
                        shell_quote((dir / "manifest.jsonl").string()),
                    dir);
  INFO(batch.err);
  CHECK(batch.exit_code == 3);  // one file failed
  CHECK(batch.err.find("broken.svg") != std::string::npos);
  CHECK(batch.err.find("1 of 7 files failed") != std::string::npos);
  for (int i = 0; i < 6; ++i) {
    const auto png = dir / "out" / ("icon" + std::to_string(i) + ".png");
    REQUIRE(std::filesystem::exists(png));
    CHECK(read_png_or_fail(png).width() == 20);
  }
  CHECK_FALSE(std::filesystem::exists(dir / "out" / "broken.png"));
  const std::string manifest = read_text(dir / "manifest.jsonl");
  CHECK(std::count(manifest.begin(), manifest.end(), '\n') == 7);
  CHECK(manifest.find("\"status\":\"error\"") != std::string::npos);
  CHECK(manifest.find("icon5.png") != std::string::npos);
  // A write that fails (the output name is taken by a directory) fails that file only; the others are
  // written (the files are written on writer threads, background_writer.h).
  std::filesystem::create_directories(dir / "out3" / "icon2.png");
  const CommandOutput blocked =
      run_curvescan("render -j 1 -w 20 --files-from " + shell_quote((dir / "list.txt").string()) +
                        " --output-dir " + shell_quote((dir / "out3").string()),
                    dir);
  INFO(blocked.err);
  CHECK(blocked.exit_code == 3);
  CHECK(blocked.err.find("2 of 7 files failed") != std::string::npos);
  CHECK(blocked.err.find("icon2.png") != std::string::npos);
  CHECK(std::filesystem::is_directory(dir / "out3" / "icon2.png"));
  for (const int i : {0, 1, 3, 4, 5}) {
    const auto png = dir / "out3" / ("icon" + std::to_string(i) + ".png");
    REQUIRE(std::filesystem::exists(png));
    CHECK(read_png_or_fail(png).width() == 20);
  }
  // The progress line: on a terminal (script(1), from util-linux, gives the program one) it shows the
  // count, the rate and the time left; -q turns it off, and without a terminal there is none (above:
  // batch.err holds only the failure's lines).
  const auto on_terminal = [&](const std::string& flags) {
    const std::string command = shell_quote(curvescan_binary()) + " render " + flags +
                                " -w 20 --files-from " + shell_quote((dir / "list.txt").string()) +
                                " --output-dir " + shell_quote((dir / "out4").string());
    return run_shell("script -qec " + shell_quote(command) + " /dev/null", dir);
  };
  if (std::system("command -v script >/dev/null 2>&1") == 0) {
    const CommandOutput shown = on_terminal("-j 1");
    CHECK_THAT(shown.out,
               Catch::Contains("rendered 7/7") && Catch::Contains("files/s") && Catch::Contains("s left"));
    const CommandOutput quiet = on_terminal("-j 1 -q");
    CHECK_THAT(quiet.out, !Catch::Contains("rendered") && !Catch::Contains("files/s"));
    CHECK_THAT(quiet.out, Catch::Contains("1 of 7 files failed"));  // -q keeps the errors
  } else {
    WARN("script(1) is not installed: the progress line on a terminal is not checked");
  }
  CHECK_THAT(batch.err, !Catch::Contains("files/s"));
  // Deterministic outputs (docs/scale-out.md): the same bytes at -j 1 and -j 2 as from a single render.
  const CommandOutput single =
      run_curvescan("render -w 20 " + shell_quote((dir / "in" / "icon3.svg").string()) + " -o " +
                        shell_quote((dir / "single.png").string()),
                    dir);
  REQUIRE(single.exit_code == 0);
  for (const char* out : {"out", "out3"}) {
    CHECK(read_text(dir / out / "icon3.png") == read_text(dir / "single.png"));
  }
  // Two inputs with the same name would write one output: refused before anything is written.
  std::filesystem::create_directories(dir / "other");
  write_text(dir / "other" / "icon0.svg", kWide);
  const CommandOutput clash = run_curvescan("render " + shell_quote((dir / "in" / "icon0.svg").string()) +
                                                " " + shell_quote((dir / "other" / "icon0.svg").string()) +
                                                " --output-dir " + shell_quote((dir / "o2").string()),
                                            dir);
  CHECK(clash.exit_code == 64);
  CHECK(clash.err.find("would both write") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "o2" / "icon0.png"));
}

TEST_CASE("curvescan render -s: a user style sheet applies after the document's own, as rsvg-convert's") {
  if (!have_render_binary()) return;
  const auto dir = scratch_directory("render-stylesheet");
  write_text(dir / "wide.svg", kWide);
  write_text(dir / "user.css", "circle { fill: #00ff00 }");
  const CommandOutput styled = run_curvescan("render -s " + shell_quote((dir / "user.css").string()) + " " +
                                                 shell_quote((dir / "wide.svg").string()) + " -o " +
                                                 shell_quote((dir / "o.png").string()),
                                             dir);
  INFO(styled.err);
  REQUIRE(styled.exit_code == 0);
  const Image image = read_png_or_fail(dir / "o.png");
  CHECK(colour_at(image, 50, 25) == std::array<int, 4>{0, 255, 0, 255});  // the circle's centre
  CHECK(colour_at(image, 5, 5) == std::array<int, 4>{255, 0, 0, 255});    // the rectangle, unstyled
  if (have_rsvg_convert()) {  // the same sheet through rsvg-convert: the same colours at both points
    REQUIRE(run_shell("rsvg-convert -s " + shell_quote((dir / "user.css").string()) + " " +
                          shell_quote((dir / "wide.svg").string()) + " -o " +
                          shell_quote((dir / "t.png").string()),
                      dir)
                .exit_code == 0);
    const Image theirs = read_png_or_fail(dir / "t.png");
    CHECK(colour_at(theirs, 50, 25) == colour_at(image, 50, 25));
    CHECK(colour_at(theirs, 5, 5) == colour_at(image, 5, 5));
  }
  // A problem in the sheet is reported with its file name, line and column.
  write_text(dir / "bad.css", "circle { fill: #00ff00 }\n  @import url(x.css);\n");
  const CommandOutput warned = run_curvescan("render -s " + shell_quote((dir / "bad.css").string()) + " " +
                                                 shell_quote((dir / "wide.svg").string()) + " -o " +
                                                 shell_quote((dir / "w.png").string()),
                                             dir);
  CHECK(warned.exit_code == 0);
  CHECK(warned.err.find("bad.css: line 2, column 3: @import") != std::string::npos);
  const CommandOutput missing = run_curvescan("render -s " + shell_quote((dir / "none.css").string()) + " " +
                                                  shell_quote((dir / "wide.svg").string()) + " -o " +
                                                  shell_quote((dir / "p.png").string()),
                                              dir);
  CHECK(missing.exit_code == 3);
  CHECK(missing.err.find("--stylesheet") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "p.png"));
}

TEST_CASE("curvescan render -l: the languages <switch> tests systemLanguage against, as rsvg-convert's") {
  if (!have_render_binary()) return;
  const auto dir = scratch_directory("render-language");
  write_text(dir / "switch.svg",
             "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"10\"><switch>"
             "<rect systemLanguage=\"de\" width=\"10\" height=\"10\" fill=\"#ff0000\"/>"
             "<rect width=\"10\" height=\"10\" fill=\"#0000ff\"/></switch></svg>");
  const auto centre_with = [&](const std::string& flags) {
    const CommandOutput run =
        run_curvescan("render " + flags + " " + shell_quote((dir / "switch.svg").string()) + " -o " +
                          shell_quote((dir / "o.png").string()),
                      dir);
    INFO(run.err);
    REQUIRE(run.exit_code == 0);
    return colour_at(read_png_or_fail(dir / "o.png"), 5, 5);
  };
  const std::array<int, 4> red{255, 0, 0, 255}, blue{0, 0, 255, 255};
  CHECK(centre_with("-l en") == blue);
  CHECK(centre_with("-l de") == red);
  CHECK(centre_with("-l 'fr, de;q=0.5'") == red);
  // SVG 1.1 5.8.5: a user's language matches a document's tag it equals or is a prefix of ("de" matches
  // "de-CH"), not the other way round.
  CHECK(centre_with("-l de-CH") == blue);
  CHECK(centre_with("--accept-language 'de;q=0, en'") == blue);  // weight 0: not acceptable
  const CommandOutput bad = run_curvescan("render -l 'de;q=x' " + shell_quote((dir / "switch.svg").string()) +
                                              " -o " + shell_quote((dir / "p.png").string()),
                                          dir);
  CHECK(bad.exit_code == 64);
  CHECK(bad.err.find("--accept-language") != std::string::npos);
}

TEST_CASE("curvescan render without -l takes the environment's languages, as rsvg-convert does") {
  if (!have_render_binary() || !have_rsvg_convert()) return;
  const auto dir = scratch_directory("render-language-environment");
  write_text(dir / "switch.svg",
             "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"10\"><switch>"
             "<rect systemLanguage=\"en\" width=\"10\" height=\"10\" fill=\"#ff0000\"/>"
             "<rect systemLanguage=\"de-DE\" width=\"10\" height=\"10\" fill=\"#00ff00\"/>"
             "<rect width=\"10\" height=\"10\" fill=\"#0000ff\"/></switch></svg>");
  // Each locale variable alone and in GLib's order of precedence (LANGUAGE, LC_ALL, LC_MESSAGES, LANG);
  // the C locale names no language, so only the <switch>'s last child, which tests nothing, passes.
  for (const std::string environment :
       {"LANG=C", "LANG=en_GB.UTF-8", "LANG=de_DE.UTF-8", "LANG=de_DE@euro", "LANG=fr_FR.UTF-8",
        "LANGUAGE=de:fr LANG=en_US.UTF-8", "LC_ALL=de_DE LANG=en_US", "LC_MESSAGES=en_US LANG=de_DE"}) {
    INFO(environment);
    const std::string env = "env -u LANGUAGE -u LC_ALL -u LC_MESSAGES -u LANG " + environment + " ";
    const auto [ours, theirs] = render_both(dir, "", dir / "switch.svg", env);
    CHECK(colour_at(ours, 5, 5) == colour_at(theirs, 5, 5));
  }
}

TEST_CASE("curvescan render -i on the root <svg>: its ink box through the viewBox, the whole drawing in it") {
  if (!have_render_binary() || !have_rsvg_convert()) return;
  const auto dir = scratch_directory("render-export-root");
  // The viewBox halves the drawing: a 140 x 140 green disc (its stroke included) from (110, 60) and a
  // 30 x 30 blue square at (300, 100), so an ink box of 220 x 140 user units from (110, 60), 110 x 70
  // pixels.
  write_text(dir / "root.svg",
             "<svg xmlns=\"http://www.w3.org/2000/svg\" id=\"root\" width=\"200\" height=\"100\" "
             "viewBox=\"0 0 400 200\"><circle cx=\"180\" cy=\"130\" r=\"65\" fill=\"#00ff00\" "
             "stroke=\"#000000\" stroke-width=\"10\"/><rect x=\"300\" y=\"100\" width=\"30\" "
             "height=\"30\" fill=\"#0000ff\"/></svg>");
  const auto [image, theirs] = render_both(dir, "-i root", dir / "root.svg");
  REQUIRE(image.width() == 110);
  REQUIRE(image.height() == 70);
  CHECK(theirs.width() == image.width());
  CHECK(theirs.height() == image.height());
  // rsvg-convert 2.54 leaves this image transparent (docs/svg.md), so the drawing is checked on its own:
  // the disc's centre (180, 130) -> ((180 - 110) / 2, (130 - 60) / 2), the square's centre (315, 115) ->
  // (102.5, 27.5), and the empty corner below the square, 76 pixels from the disc's centre.
  CHECK(colour_at(image, 35, 35) == std::array<int, 4>{0, 255, 0, 255});
  CHECK(colour_at(image, 102, 27) == std::array<int, 4>{0, 0, 255, 255});
  CHECK(colour_at(image, 105, 65) == std::array<int, 4>{0, 0, 0, 0});
}
