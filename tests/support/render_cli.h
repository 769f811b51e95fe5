// Helpers of the `curvescan render` end-to-end tests: whether the binary was built, and reading the PNG a
// run wrote (the test fails if it cannot be read).
#pragma once

#include <catch2/catch.hpp>
#include <filesystem>
#include <utility>

#include "curvescan/raster/png_io.h"
#include "run_command.h"

namespace curvescan::test {

/// True when tools/curvescan was built; otherwise says so (a build without tools checks nothing here).
inline bool have_render_binary() {
  if (std::filesystem::exists(curvescan_binary())) return true;
  WARN("built without tools/curvescan: the render CLI is not tested");
  return false;
}

inline Image read_png_or_fail(const std::filesystem::path& path) {
  Result<Image> image = read_png(path);
  REQUIRE(image.is_ok());
  return std::move(image).value();
}

}  // namespace curvescan::test
