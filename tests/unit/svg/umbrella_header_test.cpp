// The umbrella headers: <curvescan/curvescan.h> includes every public header of every library and
// <curvescan/raster.h> those of the core; both compile on their own, together, and name the core's types.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "curvescan/curvescan.h"
#include "curvescan/raster.h"

TEST_CASE("umbrella headers: one include names the types of every library", "[umbrella]") {
  const auto path = curvescan::PathBuilder().move_to({0.0, 0.0}).line_to({1.0, 0.0}).line_to({0.0, 1.0}).close().build();
  REQUIRE(path);
  CHECK_FALSE(path->empty());
}

TEST_CASE("umbrella headers: every public header is in one of them", "[umbrella]") {
  // A header added under some include/curvescan/ folder and forgotten here would compile in no test that
  // uses the umbrellas: list the public headers of the source tree and look for each in the two files.
  namespace fs = std::filesystem;
  const fs::path root(CURVESCAN_SOURCE_DIR);
  std::string umbrellas;
  for (const char* name : {"raster/include/curvescan/curvescan.h", "raster/include/curvescan/raster.h"}) {
    std::ifstream file(root / name);
    REQUIRE(file);
    std::ostringstream text;
    text << file.rdbuf();
    umbrellas += text.str();
  }
  int headers = 0;
  for (const char* library : {"curves", "raster", "raster/text", "raster/svg", "raster/diff"}) {
    const fs::path include = root / library / "include";
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(include)) {
      if (!entry.is_regular_file() || entry.path().extension() != ".h") continue;
      const std::string name = entry.path().lexically_relative(include).generic_string();
      if (name == "curvescan/curvescan.h" || name == "curvescan/raster.h") continue;
      ++headers;
      INFO(name);
      CHECK(umbrellas.find("#include \"" + name + "\"") != std::string::npos);
    }
  }
  CHECK(headers > 40);  // the walk found the headers (about 60 today), not an empty tree
}
