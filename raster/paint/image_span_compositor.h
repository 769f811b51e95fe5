// ImageSpanCompositor: the SpanSink that paints an image paint (image_pattern.h), source-over, with each
// span's coverage. Each covered pixel's centre is mapped to image space by `device_to_image` (the inverse
// of device_from_user · image_to_user) and sampled there; the pattern's alpha multiplies the sample
// (MUL_UN8 per channel, as a constant mask would), then composite_source_over applies the coverage.
// Pixels are written at (x − origin_x, y − origin_y), for layers (as GradientSpanCompositor does).
//
// Fast path: a nearest-sampled image without extend, placed by a whole-pixel translation (a filter's
// result, an image drawn 1:1), maps the centre of device pixel x to x + 0.5 + e, in image pixel x + e: the
// span reads a run of one image row directly, without mapping and flooring each centre. The same pixels
// as the general path (tests/unit/paint/image_span_fast_path_test.cpp holds them to it).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
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
        device_to_image_(device_to_image) {
    // Whole numbers small enough that x + 0.5 + e is exact in double for every pixel column x.
    const auto whole = [](double v) { return std::fabs(v) < 1e12 && v == std::floor(v); };
    translated_ = pattern.filter == PatternFilter::kNearest && pattern.extend == PatternExtend::kNone &&
                  device_to_image.a == 1.0 && device_to_image.b == 0.0 && device_to_image.c == 0.0 &&
                  device_to_image.d == 1.0 && whole(device_to_image.e) && whole(device_to_image.f);
  }

  void blend(std::span<const Span> spans) override {
    if (translated_) {
      blend_translated(spans);
      return;
    }
    const unsigned alpha = pattern_.alpha;
    for (const Span& span : spans) {
      if (span.coverage == 0) continue;
      Rgba8* row = target_.row(span.y - origin_y_) + (span.x - origin_x_);
      for (int i = 0; i < span.len; ++i) {
        blend_pixel(row[i], pattern_.sample(device_to_image_.apply(Point{span.x + i + 0.5, span.y + 0.5})),
                    alpha, span.coverage);
      }
    }
  }

 private:
  // One image pixel onto the target: scaled by the paint's alpha, then source-over through the coverage
  // (a fully covered opaque pixel is a plain copy).
  static void blend_pixel(Rgba8& target, Rgba8 color, unsigned alpha, std::uint8_t coverage) noexcept {
    if (alpha != 255) {
      color = Rgba8{multiply_coverage(color.r, alpha), multiply_coverage(color.g, alpha),
                    multiply_coverage(color.b, alpha), multiply_coverage(color.a, alpha)};
    }
    if (color.a == 0) return;
    target = (color.a == 255 && coverage == 255) ? color : composite_source_over(target, color, coverage);
  }

  // The fast path (above): image pixel (x + e, y + f) for device pixel (x, y), transparent outside.
  void blend_translated(std::span<const Span> spans) {
    const unsigned alpha = pattern_.alpha;
    const Image& image = pattern_.image;
    const auto shift_x = static_cast<long long>(device_to_image_.e);
    const auto shift_y = static_cast<long long>(device_to_image_.f);
    for (const Span& span : spans) {
      if (span.coverage == 0) continue;
      const long long source_y = span.y + shift_y;
      if (source_y < 0 || source_y >= image.height()) continue;
      // The part of the span over the image: columns i with 0 <= span.x + i + shift_x < width.
      const long long first = std::max<long long>(0, -(span.x + shift_x));
      const long long last = std::min<long long>(span.len, image.width() - (span.x + shift_x));
      if (first >= last) continue;
      // Pointers to the first pixel used (a pointer before the row's start would not be valid C++).
      const Rgba8* source = image.row(static_cast<int>(source_y)) + (span.x + shift_x + first);
      Rgba8* row = target_.row(span.y - origin_y_) + (span.x - origin_x_ + first);
      for (long long i = 0; i < last - first; ++i) {
        blend_pixel(row[i], source[i], alpha, span.coverage);
      }
    }
  }

  Image& target_;
  int origin_x_, origin_y_;
  const ImagePattern& pattern_;
  Affine device_to_image_;
  bool translated_ = false;
};

}  // namespace curvescan::detail
