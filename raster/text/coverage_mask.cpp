// MaskRenderer: Path -> edges (path_edges.h, the one flattener) -> Rasterizer::rasterize_mask, which writes
// the A8 buffer itself (densely for planar fills).
#include "curvescan/text/coverage_mask.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "curvescan/raster/limits.h"
#include "path_edges.h"

namespace curvescan {
namespace {

int clamped_int(double value) noexcept {
  constexpr double kLimit = 536870912.0;  // 2^29: box edges and their differences fit an int
  return static_cast<int>(std::clamp(value, -kLimit, kLimit));
}

}  // namespace

IntRect pixel_box(const Path& path) noexcept {
  if (path.empty()) return {};
  const Rect bounds = path.bounds();
  return {clamped_int(std::floor(bounds.x0)), clamped_int(std::floor(bounds.y0)),
          clamped_int(std::ceil(bounds.x1)), clamped_int(std::ceil(bounds.y1))};
}

Status MaskRenderer::render(const Path& device_path, IntRect box, FillRule rule, double tolerance,
                            CoverageMask& mask) {
  if (!(std::isfinite(tolerance) && tolerance > 0.0)) {
    return Status::invalid("the flattening tolerance must be a finite positive number of pixels");
  }
  if (box.empty()) {
    box = {};  // one canonical empty box
  } else if (!image_size_within_limits(std::int64_t{box.x1} - box.x0, std::int64_t{box.y1} - box.y0)) {
    return Error{ErrorKind::kLimitExceeded, "the coverage mask box exceeds the image size limit (" +
                                                std::to_string(kMaxImageDimension) + " pixels per side, " +
                                                std::to_string(kMaxImagePixels) + " in all)"};
  }
  const std::int64_t pixels = (std::int64_t{box.x1} - box.x0) * (std::int64_t{box.y1} - box.y0);
  mask.box = box;
  if (box.empty() || device_path.empty()) {
    mask.coverage.assign(static_cast<std::size_t>(pixels), 0);
    return Status::ok();
  }
  mask.coverage.resize(static_cast<std::size_t>(pixels));  // rasterize_mask writes every byte
  rasterizer_.reset(box);
  // Uniform quadratic steps: a glyph's quadratics cost one square root each and a de Casteljau point per
  // vertex instead of a step search per segment (path_edges.h QuadraticSteps).
  detail::add_path_edges(device_path, tolerance, rasterizer_, polyline_, SIZE_MAX,
                         detail::QuadraticSteps::kUniform);
  rasterizer_.rasterize_mask(rule, mask.coverage);
  return Status::ok();
}

}  // namespace curvescan
