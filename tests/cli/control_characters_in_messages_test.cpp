// A file name or input text quoted in a message cannot write control characters to the terminal: an
// escape sequence (ESC [ ... m recolours or rewrites the screen) or a line break (a forged second message)
// is printed as \xNN, so every message stays one visible line.
#include <algorithm>
#include <catch2/catch.hpp>
#include <string>

#include "run_command.h"

namespace curvescan::test {

TEST_CASE("control characters in quoted names are printed as \\xNN", "[cli]") {
  const auto dir = scratch_directory("control-characters");
  // A name straight from the command line (one render), and one from a --files-from list (a batch).
  const CommandOutput render = run_curvescan("render " + shell_quote((dir / "x\ny\x1b[31m.svg").string()) +
                                                 " -o " + shell_quote((dir / "out.png").string()),
                                             dir);
  INFO(render.err);
  CHECK(render.exit_code == 3);
  CHECK_THAT(render.err, Catch::Contains("x\\x0Ay\\x1B[31m.svg' for reading"));
  CHECK(render.err.find('\x1b') == std::string::npos);
  CHECK(std::count(render.err.begin(), render.err.end(), '\n') == 1);

  write_text(dir / "list.txt", "a\x1b[2Jb.svg\n");
  const CommandOutput batch =
      run_curvescan("render --files-from " + shell_quote((dir / "list.txt").string()) + " --output-dir " +
                        shell_quote((dir / "out").string()),
                    dir);
  INFO(batch.err);
  CHECK(batch.exit_code == 3);
  CHECK_THAT(batch.err, Catch::Contains("'a\\x1B[2Jb.svg'"));
  CHECK(batch.err.find('\x1b') == std::string::npos);
}

}  // namespace curvescan::test
