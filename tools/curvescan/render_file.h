// One SVG file to one image, as `curvescan render` does it for a single file and for each file of a batch:
// read (bounded, gzip recognised), parse, render on a stack sized for the nesting limit.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "curvescan/raster/image.h"
#include "curvescan/status.h"
#include "curvescan/svg/document.h"

namespace curvescan::cli {

struct RenderSettings {
  svg::RenderOptions render;
  std::size_t max_input_bytes = 0;  ///< compressed and uncompressed alike
  /// --allow-files: <image> may read files beside each document and below (never for standard input).
  bool allow_files = false;
};

struct RenderedFile {
  Result<Image> image = Error{ErrorKind::kInvalidArgument, "not rendered"};
  std::vector<std::string> warnings;  ///< problems with the input the user should see
  std::vector<std::string> notes;     ///< shown with --verbose
};

/// Renders the SVG (or gzip-compressed SVG) file `input` ("-" = standard input). Error messages name it.
[[nodiscard]] RenderedFile render_svg_file(const std::string& input, const RenderSettings& settings);

}  // namespace curvescan::cli
