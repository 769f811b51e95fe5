// `curvescan render|text|curve --help` in plain words, and the usage errors of a bad option value: each
// names the option and says what it expects. (diff's help has its own test in tests/unit/diff/.)
#include <catch2/catch.hpp>
#include <iterator>
#include <regex>
#include <string>

#include "run_command.h"

namespace curvescan::test {
namespace {

/// Parser type names and relations CLI11 prints when an option does not name its value in words.
const std::regex kParserWords(
    "\\b(TEXT|FLOAT|UINT|INT|FINITE|NONNEGATIVE|Excludes|Needs|REQUIRED)\\b|INT:|"
    "\\{false\\}|\\{true\\}| in \\[");

CommandOutput help_of(const std::string& command) {
  const auto dir = scratch_directory("help-" + command);
  const CommandOutput help = run_curvescan(command + " --help", dir);
  REQUIRE(help.exit_code == 0);
  REQUIRE(help.err.empty());
  return help;
}

std::ptrdiff_t examples_in(const std::string& help, const std::string& command) {
  const std::regex example("\n  curvescan " + command + " \\S");
  return std::distance(std::sregex_iterator(help.begin(), help.end(), example), std::sregex_iterator());
}

void check_mentions(const std::string& help, std::initializer_list<const char*> phrases) {
  for (const char* phrase : phrases) {
    INFO(phrase);
    CHECK_THAT(help, Catch::Contains(phrase));
  }
}

}  // namespace

TEST_CASE("render --help names every value in words, with units, ranges and defaults", "[cli][help]") {
  const CommandOutput help = help_of("render");
  INFO(help.out);
  std::smatch parser_word;
  CHECK_FALSE(std::regex_search(help.out, parser_word, kParserWords));
  check_mentions(help.out, {"-z, --zoom FACTOR",
                            "1e-9 to 1e9 (default 1",
                            "-w, --width LENGTH",
                            "px, in, cm, mm, pt or pc",
                            "-h, --height LENGTH",
                            "-d, --dpi-x DPI",
                            "pixels per inch, 0.001 to 1e6 (default 96)",
                            "-b, --background-color, --background COLOUR",
                            "(default: transparent)",
                            "-j, --jobs N",
                            "1 to 1024 (default: all cores)",
                            "--tolerance PIXELS",
                            "(default 0.1)",
                            "--antialias MODE",
                            "--max-memory MiB",
                            "in MiB",
                            "(default 1024)",
                            "--max-input-size MiB",
                            "1 to 4096 (default 64)",
                            "--max-depth N",
                            "1 to 4096 (default 256)",
                            "-f, --format FORMAT",
                            "(default png)",
                            "not with --verbose",
                            "--keep-image-data, --no-keep-image-data",
                            "docs/limits.md"});
  const std::ptrdiff_t examples = examples_in(help.out, "render");
  CHECK(examples >= 2);
  CHECK(examples <= 4);
}

TEST_CASE("text --help names every value in words, with units, ranges and defaults", "[cli][help]") {
  const CommandOutput help = help_of("text");
  INFO(help.out);
  CHECK_FALSE(std::regex_search(help.out, kParserWords));
  check_mentions(help.out, {"-o, --output FILE",
                            "(required)",
                            "--size PIXELS",
                            "more than 0 and at most 32767 (default 32)",
                            "--font FONT",
                            "(default sans-serif)",
                            "--weight WEIGHT",
                            "1 to 1000",
                            "(default 400)",
                            "--color COLOUR",
                            "(default black)",
                            "--background COLOUR",
                            "(default transparent)",
                            "--direction DIRECTION",
                            "auto",
                            "ltr or rtl",
                            "(default auto)",
                            "--margin PIXELS",
                            "(default: a quarter of --size)",
                            "--max-memory MiB",
                            "--max-text-length N",
                            "not with a text argument"});
  const std::ptrdiff_t examples = examples_in(help.out, "text");
  CHECK(examples >= 2);
  CHECK(examples <= 4);
}

TEST_CASE("curve --help names every value in words, with units, ranges and defaults", "[cli][help]") {
  const CommandOutput help = help_of("curve");
  INFO(help.out);
  CHECK_FALSE(std::regex_search(help.out, kParserWords));
  check_mentions(help.out,
                 {"curvescan curve [OPTIONS] SPEC", "-o, --output FILE", "(default: standard output)",
                  "--tolerance DISTANCE", "in curve units, 1e-9 to 1e9 (default 0.1)", "--max-degree N",
                  "1 to 1024 (default 64)", "--max-points N", "--max-segments N", "--max-memory MiB"});
  const std::ptrdiff_t examples = examples_in(help.out, "curve");
  CHECK(examples >= 2);
  CHECK(examples <= 4);
}

TEST_CASE("a bad option value is a usage error naming the option and what it expects", "[cli][errors]") {
  const auto dir = scratch_directory("usage-errors");
  write_text(dir / "in.svg", "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"4\" height=\"4\"/>");
  write_text(dir / "spec.json", R"({"type": "bezier", "points": [[0,0],[10,10]]})");
  const std::string svg =
      shell_quote((dir / "in.svg").string()) + " -o " + shell_quote((dir / "o.png").string());
  const std::string spec = shell_quote((dir / "spec.json").string());
  const std::string text = "x -o " + shell_quote((dir / "t.png").string());
  struct Case {
    std::string arguments;
    std::string message;
  };
  const Case cases[] = {
      {"render " + svg + " -z abc", "--zoom: 'abc' is not a number"},
      {"render " + svg + " -z 0", "--zoom: '0' is out of range: give a number from 1e-9 to 1e9"},
      {"render " + svg + " -d 1e7", "--dpi-x: '1e7' is out of range: give a number from 0.001 to 1e6"},
      {"render " + svg + " -j 0", "--jobs: '0' is out of range: give a whole number from 1 to 1024"},
      {"render " + svg + " -j two", "--jobs: 'two' is not a whole number: give one from 1 to 1024"},
      {"render " + svg + " --max-depth 1.5",
       "--max-depth: '1.5' is not a whole number: give one from 1 to 4096"},
      {"render " + svg + " --max-memory 0",
       "--max-memory: '0' is out of range: give a whole number from 1 to"},
      {"render " + svg + " --antialias fancy", "--antialias: 'fancy' is not one of none, default"},
      {"render " + svg + " -b nocolour", "--background-color: 'nocolour' is not a CSS colour"},
      {"render " + svg + " -w 10qq", "--width: invalid value '10qq': not a number with a unit"},
      {"render " + svg + " -z", "--zoom: 1 required FACTOR missing"},
      {"text " + text + " --weight 2000",
       "--weight: '2000' is out of range: give a whole number from 1 to 1000"},
      {"text " + text + " --size abc", "--size: 'abc' is not a number"},
      {"text " + text + " --direction up", "--direction: 'up' is not one of auto, ltr, rtl"},
      {"text " + text + " --margin -1", "--margin: '-1' is out of range: give a number from 0 to 1e6"},
      {"curve " + spec + " --tolerance -1",
       "--tolerance: '-1' is out of range: give a number from 1e-9 to 1e9"},
      {"curve " + spec + " --max-degree x",
       "--max-degree: 'x' is not a whole number: give one from 1 to 1024"},
      {"rendr " + svg, "'rendr' is not a curvescan command; the commands are curve, diff, render and text"},
  };
  for (const Case& c : cases) {
    INFO(c.arguments);
    const CommandOutput out = run_curvescan(c.arguments, dir);
    CHECK(out.exit_code == 64);
    CHECK_THAT(out.err, Catch::Contains(c.message));
    CHECK_FALSE(std::regex_search(out.err, kParserWords));
  }
}

TEST_CASE("every command's --help states its exit codes, the signal ones included", "[cli][help]") {
  for (const char* command : {"render", "text", "curve", "diff"}) {
    INFO(command);
    const CommandOutput help = help_of(command);
    check_mentions(help.out, {"Exit codes: 0 ", "3 an error", "64 a malformed command line",
                              "128+N stopped by signal N (130 SIGINT, 143 SIGTERM, 129 SIGHUP)"});
  }
}

}  // namespace curvescan::test
