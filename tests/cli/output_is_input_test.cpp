// An output that names one of the command's own inputs is refused (exit 64) before anything is read or
// written, and the input is left as it was: -o of every command, a symbolic link to the input, another
// spelling of its path, render's --stylesheet and --manifest (docs/limits.md, "Output files").
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "run_command.h"

namespace curvescan::test {
namespace {

namespace fs = std::filesystem;

const char* const kSvg =
    R"(<svg xmlns="http://www.w3.org/2000/svg" width="8" height="8"><rect width="4" height="4"/></svg>)";
const char* const kSpec = R"({"type": "bezier", "points": [[0,0],[10,30],[40,-20],[50,10]]})";

std::string q(const fs::path& path) {
  return shell_quote(path.string());
}

/// Runs `arguments`, expects the usage error naming `output`, and `input` to hold `before` still.
void check_refused(const std::string& arguments, const fs::path& scratch, const std::string& output,
                   const fs::path& input, const std::string& before) {
  INFO(arguments);
  const CommandOutput run = run_curvescan(arguments, scratch);
  INFO(run.err);
  CHECK(run.exit_code == 64);
  CHECK_THAT(run.err, Catch::Contains("the output '" + output + "'"));
  CHECK_THAT(run.err, Catch::Contains("would replace the input: name another output file"));
  CHECK(read_text(input) == before);
}

}  // namespace

TEST_CASE("every command refuses an output that is its input, and leaves the input alone", "[cli][output]") {
  const auto dir = scratch_directory("output-is-input");
  write_text(dir / "drawing.png", kSvg);  // an SVG document under a PNG name: render's -o check passes
  write_text(dir / "spec.json", kSpec);
  write_text(dir / "poem.txt", "hello");
  REQUIRE(run_curvescan("render " + q(dir / "drawing.png") + " -o " + q(dir / "a.png"), dir).exit_code == 0);
  REQUIRE(run_curvescan("render " + q(dir / "drawing.png") + " -o " + q(dir / "b.png"), dir).exit_code == 0);
  const std::string png = read_text(dir / "a.png");

  const std::string drawing = (dir / "drawing.png").string();
  check_refused("render " + q(drawing) + " -o " + q(drawing), dir, drawing, drawing, kSvg);
  const std::string spec = (dir / "spec.json").string();
  check_refused("curve " + q(spec) + " -o " + q(spec), dir, spec, spec, kSpec);
  const std::string poem = (dir / "poem.txt").string();
  check_refused("text -i " + q(poem) + " -o " + q(poem), dir, poem, poem, "hello");
  const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string();
  check_refused("diff " + q(a) + " " + q(b) + " -o " + q(a), dir, a, a, png);
  check_refused("diff " + q(a) + " " + q(b) + " -o " + q(b), dir, b, b, png);
}

TEST_CASE("a link to the input, another spelling of its path, a style sheet and a manifest count too",
          "[cli][output]") {
  const auto dir = scratch_directory("output-is-input-link");
  write_text(dir / "spec.json", kSpec);
  write_text(dir / "drawing.svg", kSvg);
  write_text(dir / "style.png", "rect { fill: red }");
  fs::create_symlink(dir / "spec.json", dir / "link.json");
  const std::string spec = (dir / "spec.json").string();
  check_refused("curve " + q(spec) + " -o " + q(dir / "link.json"), dir, (dir / "link.json").string(), spec,
                kSpec);
  const std::string dotted = (dir.path() / "." / "spec.json").string();
  check_refused("curve " + q(spec) + " -o " + q(dotted), dir, dotted, spec, kSpec);
  const std::string style = (dir / "style.png").string();
  check_refused("render " + q(dir / "drawing.svg") + " -s " + q(style) + " -o " + q(style), dir, style, style,
                "rect { fill: red }");
  const std::string drawing = (dir / "drawing.svg").string();
  check_refused("render " + q(drawing) + " --output-dir " + q(dir / "out") + " --manifest " + q(drawing), dir,
                drawing, drawing, kSvg);
  CHECK_FALSE(fs::exists(dir / "out"));
}

TEST_CASE("a device named as input and output is written through, not refused", "[cli][output]") {
  const auto dir = scratch_directory("output-is-input-device");
  const CommandOutput run = run_curvescan("curve /dev/null -o /dev/null", dir);
  // Empty input is not JSON (exit 3); what matters is that it is read, not refused as the output.
  CHECK(run.exit_code == 3);
  CHECK_THAT(run.err, !Catch::Contains("would replace the input"));
}

}  // namespace curvescan::test
