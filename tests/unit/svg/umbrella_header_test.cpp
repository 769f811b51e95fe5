// The umbrella headers: <curvescan/curvescan.h> includes every public header of every library and
// <curvescan/raster.h> those of the core; both compile on their own, together, and name the core's types.
#include "curvescan/curvescan.h"
#include "curvescan/raster.h"

#include <catch2/catch.hpp>

TEST_CASE("umbrella headers: one include names the types of every library", "[umbrella]") {
  const auto path = curvescan::PathBuilder().move_to({0.0, 0.0}).line_to({1.0, 0.0}).line_to({0.0, 1.0}).close().build();
  REQUIRE(path);
  CHECK_FALSE(path->empty());
}
