// ImageSpanCompositor: the SpanSink that paints an image paint (image_pattern.h), source-over, with each
// span's coverage. Each covered pixel's centre is mapped to image space by `device_to_image` (the inverse
// of device_from_user · image_to_user) and sampled there; the pattern's alpha multiplies the sample
// (MUL_UN8 per channel, as a constant mask would), then composite_source_over applies the coverage.
// Pixels are written at (x − origin_x, y − origin_y), for layers (as GradientSpanCompositor does).
#pragma once

#include <span>

#include "curvescan/curves/affine.h"
#include "curvescan/raster/image.h"
#include "curvescan/raster/image_pattern.h"
#include "curvescan/raster/mask.h"
#include "curvescan/raster/paint.h"
#include "curvescan/raster/rasterizer.h"

namespace curvescan::detail {

class ImageSpanCompositor final : public SpanSink {
 public:
  ImageSpanCompositor(Image& target, int origin_x, int origin_y, const ImagePattern& pattern,
                      const Affine& device_to_image) noexcept
      : target_(target),
        origin_x_(origin_x),
        origin_y_(origin_y),
        pattern_(pattern),
        device_to_image_(device_to_image) {}

  void blend(std::span<const Span> spans) override {
    const unsigned alpha = pattern_.alpha;
    for (const Span& span : spans) {
      if (span.coverage == 0) continue;
      Rgba8* row = target_.row(span.y - origin_y_) + (span.x - origin_x_);
      for (int i = 0; i < span.len; ++i) {
        Rgba8 color = pattern_.sample(device_to_image_.apply(Point{span.x + i + 0.5, span.y + 0.5}));
        if (alpha != 255) {
          color = Rgba8{multiply_coverage(color.r, alpha), multiply_coverage(color.g, alpha),
                        multiply_coverage(color.b, alpha), multiply_coverage(color.a, alpha)};
        }
        if (color.a == 0) continue;
        row[i] = (color.a == 255 && span.coverage == 255)
                     ? color
                     : composite_source_over(row[i], color, span.coverage);
      }
    }
  }

 private:
  Image& target_;
  int origin_x_, origin_y_;
  const ImagePattern& pattern_;
  Affine device_to_image_;
};

}  // namespace curvescan::detail
