// CoverageMask and MaskRenderer: a path rasterized to an 8-bit coverage mask, the A8 bitmap that
// FreeType's FT_Render_Glyph (FT_RENDER_MODE_NORMAL) produces for a glyph, by curvescan's exact-area
// rasterizer. For glyph caches, for comparing with FreeType, and for the glyph benchmark.
#pragma once

#include <cstdint>
#include <vector>

#include "curvescan/curves/flatten.h"
#include "curvescan/curves/point.h"
#include "curvescan/raster/path.h"
#include "curvescan/raster/rasterizer.h"
#include "curvescan/status.h"

namespace curvescan {

/// Coverage of the pixels of `box`, row-major, one byte per pixel: 0 outside, 255 fully covered,
/// round(255 · exact area) in between (rasterizer.h).
struct CoverageMask {
  IntRect box;
  std::vector<std::uint8_t> coverage;

  [[nodiscard]] int width() const noexcept { return box.x1 - box.x0; }
  [[nodiscard]] int height() const noexcept { return box.y1 - box.y0; }
  /// Coverage of device pixel (x, y), which must lie inside box.
  [[nodiscard]] std::uint8_t at(int x, int y) const noexcept {
    return coverage[static_cast<std::size_t>(y - box.y0) * static_cast<std::size_t>(width()) +
                    static_cast<std::size_t>(x - box.x0)];
  }
};

/// The smallest pixel box that holds every control point of `path` (so every curve, by the convex hull
/// property): floor of the minimum, ceiling of the maximum, as FreeType boxes a glyph bitmap. The zero
/// box for an empty path; coordinates are clamped to ±2^30 so the result always fits an int.
[[nodiscard]] IntRect pixel_box(const Path& path) noexcept;

/// Rasterizes paths into masks, reusing its rasterizer and flattening buffers between calls.
class MaskRenderer {
 public:
  /// Fills `device_path` (device pixels, y down) with `rule` into `mask`, whose box becomes `box`
  /// (coverage outside the box is clipped away). Curves are flattened within `tolerance` pixels
  /// (Hausdorff distance, flatten.h). kInvalidArgument when the tolerance is not finite and positive;
  /// kLimitExceeded when the box has more than kMaxImagePixels pixels (limits.h).
  [[nodiscard]] Status render(const Path& device_path, IntRect box, FillRule rule, double tolerance,
                              CoverageMask& mask);

 private:
  Rasterizer rasterizer_;
  std::vector<Point> polyline_;
};

}  // namespace curvescan
