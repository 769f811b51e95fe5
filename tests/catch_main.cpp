// The one Catch2 main, compiled once and shared by every test executable.
//
// Before any test runs it points fontconfig at the tests' own configuration (tests/fonts/fonts.conf.in,
// FONTCONFIG_FILE: fontconfig-user, "Environment variables"), which names only the fonts the tests rely
// on: the results must not depend on which other fonts the machine has installed. The variable is
// inherited by the programs the tests start (curvescan, rsvg-convert).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <cstdlib>

int main(int argc, char* argv[]) {
  setenv("FONTCONFIG_FILE", CURVESCAN_TEST_FONTCONFIG_FILE, /*overwrite=*/1);
  return Catch::Session().run(argc, argv);
}
