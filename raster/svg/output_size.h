// The size of the image a document renders to, from its natural size and the caller's request: the
// rules of rsvg-convert 2.54 (librsvg's command-line converter), so that `curvescan render` is a drop-in
// for it. They were read from rsvg-convert's documentation and checked flag by flag against the program
// itself; tests/unit/svg/output_size_test.cpp records the sizes it produced.
//
//   nothing asked            natural size × zoom (per axis)
//   -w and/or -h, no zoom    -w alone: the width, the height in proportion; -h alone likewise; both:
//                            exactly W × H (the drawing is stretched), or with --keep-aspect-ratio the
//                            natural size scaled uniformly to fit inside W × H
//   a zoom and -w/-h         the zoomed size, unless it is wider than -w or taller than -h: then -w/-h
//                            replace the zoomed dimensions they name (the other stays zoomed), or with
//                            --keep-aspect-ratio the zoom is scaled down uniformly until it fits
//
// The pixel size is that size rounded up (a partly covered last column is kept); the drawing is scaled
// by (size ÷ natural size) per axis.
#pragma once

#include <optional>

namespace curvescan::svg::detail {

struct OutputSizeRequest {
  double natural_width = 0.0;   ///< the document's size in px (its width and height at the resolution)
  double natural_height = 0.0;
  std::optional<double> width;  ///< -w, px
  std::optional<double> height; ///< -h, px
  double zoom_x = 1.0;          ///< -z, or -x / -y
  double zoom_y = 1.0;
  bool keep_aspect_ratio = false;  ///< -a
};

struct OutputSize {
  double width = 0.0;  ///< px, not rounded
  double height = 0.0;
};

/// The size the document is drawn at (see above); nullopt when the natural size is zero. A side beyond the
/// largest double is infinite, never NaN.
[[nodiscard]] std::optional<OutputSize> output_size(const OutputSizeRequest& request) noexcept;

/// The same size as `size` × 2^`exponent`, with every length scaled by 2^-exponent so that no product
/// overflows: the size of a request whose sides are beyond the largest double (for a message).
struct ScaledOutputSize {
  OutputSize size;
  int exponent = 0;
};
[[nodiscard]] std::optional<ScaledOutputSize> output_size_scaled(const OutputSizeRequest& request) noexcept;

}  // namespace curvescan::svg::detail
