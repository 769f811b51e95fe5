// `curvescan render` end to end: options, standard input and output, exit codes, messages, and no output
// file on failure. Runs the built binary (tools/curvescan); in a build without the tools
// (CURVESCAN_BUILD_TOOLS=OFF) these cases say so and check nothing.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "curvescan/raster/png_io.h"
#include "render_cli.h"
#include "run_command.h"

using namespace curvescan;
using namespace curvescan::test;

namespace {

const std::string kSquare =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"20\" height=\"10\">"
    "<rect x=\"0\" y=\"0\" width=\"10\" height=\"10\" fill=\"#ff0000\"/></svg>";

}  // namespace

TEST_CASE("curvescan render: a document to a PNG, with -w, -h, -z, -b and --dpi") {
  if (!have_render_binary()) return;
  const auto dir = scratch_directory("render-cli");
  write_text(dir / "in.svg", kSquare);
  const auto run = [&](const std::string& options) {
    return run_curvescan("render " + shell_quote((dir / "in.svg").string()) + " -o " +
                             shell_quote((dir / "out.png").string()) + " " + options,
                         dir);
  };
  CHECK(run("").exit_code == 0);
  Image image = read_png_or_fail(dir / "out.png");
  CHECK(image.width() == 20);
  CHECK(image.at(5, 5).r == 255);
  CHECK(image.at(15, 5).a == 0);
  CHECK(run("-w 40").exit_code == 0);
  CHECK(read_png_or_fail(dir / "out.png").height() == 20);
  CHECK(run("-h 30").exit_code == 0);  // -h is the height here, not help
  CHECK(read_png_or_fail(dir / "out.png").width() == 60);
  CHECK(run("-w 10 -h 40").exit_code == 0);
  image = read_png_or_fail(dir / "out.png");
  CHECK(image.width() == 10);
  CHECK(image.height() == 40);
  CHECK(run("-z 0.5 -b 'rgb(0, 0, 255)'").exit_code == 0);
  image = read_png_or_fail(dir / "out.png");
  CHECK(image.width() == 10);
  CHECK(image.at(8, 2).b == 255);
  CHECK(run("--antialias none --tolerance 0.5 --dpi 72").exit_code == 0);
}

TEST_CASE("curvescan render: standard input and standard output with '-'") {
  if (!have_render_binary()) return;
  const auto dir = scratch_directory("render-stdio");
  write_text(dir / "in.svg", kSquare);
  const CommandOutput output = run_shell(
      shell_quote(curvescan_binary()) + " render - -o - < " + shell_quote((dir / "in.svg").string()), dir);
  CHECK(output.exit_code == 0);
  REQUIRE(output.out.size() > 8);
  CHECK(output.out.substr(1, 3) == "PNG");
}

TEST_CASE("curvescan render: errors are one line, exit 3, and leave no output file") {
  if (!have_render_binary()) return;
  const auto dir = scratch_directory("render-errors");
  const auto out = dir / "out.png";
  const auto fails = [&](const std::string& document, const std::string& options,
                         const std::string& message) {
    write_text(dir / "in.svg", document);
    const CommandOutput result = run_curvescan("render " + shell_quote((dir / "in.svg").string()) + " -o " +
                                                   shell_quote(out.string()) + " " + options,
                                               dir);
    INFO(result.err);
    CHECK(result.exit_code == 3);
    CHECK(result.err.find(message) != std::string::npos);
    CHECK(result.err.find("curvescan render: error: ") == 0);
    CHECK(std::count(result.err.begin(), result.err.end(), '\n') == 1);
    CHECK_FALSE(std::filesystem::exists(out));
  };
  fails("<svg xmlns=\"http://www.w3.org/2000/svg\"><rect></svg>", "", "not well-formed XML");
  fails("<html/>", "", "not <svg>");
  fails("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"9000\" height=\"9000\"/>", "",
        "give a smaller -w, -h or -z");
  fails(kSquare, "--max-elements 1", "--max-elements");
  const CommandOutput missing = run_curvescan(
      "render " + shell_quote((dir / "nope.svg").string()) + " -o " + shell_quote(out.string()), dir);
  CHECK(missing.exit_code == 3);
  CHECK_FALSE(std::filesystem::exists(out));
}

TEST_CASE("curvescan render: warnings unless -q, notes with --verbose — usage errors exit 64 — --help") {
  if (!have_render_binary()) return;
  const auto dir = scratch_directory("render-verbose");
  write_text(dir / "in.svg",
             "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"4\" height=\"4\"><blink/><use href=\"#x\"/>"
             "<animate/><rect width=\"4\" height=\"4\"><animate/><set/></rect><defs><script/></defs></svg>");
  const std::string base =
      "render " + shell_quote((dir / "in.svg").string()) + " -o " + shell_quote((dir / "o.png").string());
  const CommandOutput plain = run_curvescan(base, dir);
  CHECK(plain.exit_code == 0);
  CHECK(plain.err.find("'#x', which does not exist") != std::string::npos);
  // An unknown element name loses its content: a warning by default, once.
  const std::size_t blink = plain.err.find("<blink> is not a known SVG element");
  CHECK(blink != std::string::npos);
  CHECK(plain.err.find("<blink>", blink + 1) == std::string::npos);
  // An unsupported SVG element is named by default, once however often it occurs.
  const std::size_t animate = plain.err.find("<animate> is not supported, ignored");
  CHECK(animate != std::string::npos);
  CHECK(plain.err.find("<animate>", animate + 1) == std::string::npos);
  CHECK(plain.err.find("<set> is not supported, ignored") != std::string::npos);
  CHECK(plain.err.find("<script> is not supported, ignored") != std::string::npos);  // in <defs> too
  const CommandOutput quiet = run_curvescan(base + " -q", dir);
  CHECK(quiet.exit_code == 0);
  CHECK(quiet.err.empty());
  CHECK(std::filesystem::exists(dir / "o.png"));
  CHECK(run_curvescan(base + " -q --verbose", dir).exit_code == 64);  // contradictory
  const CommandOutput verbose = run_curvescan(base + " --verbose", dir);
  CHECK(verbose.err.find("<blink> is not a known SVG element") != std::string::npos);
  CHECK(run_curvescan(base + " --antialias fancy", dir).exit_code == 64);
  CHECK(run_curvescan(base + " -z -1", dir).exit_code == 64);
  // No -o: standard output, as rsvg-convert (here a file, so not a terminal).
  const CommandOutput piped = run_curvescan("render " + shell_quote((dir / "in.svg").string()), dir);
  CHECK(piped.exit_code == 0);
  CHECK(piped.out.substr(1, 3) == "PNG");
  const CommandOutput help = run_curvescan("render --help", dir);
  CHECK(help.exit_code == 0);
  CHECK(help.out.find("-h, --height LENGTH") != std::string::npos);
}
