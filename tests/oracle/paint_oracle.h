// Test support for the paint oracle tests (paint_*_test.cpp): our Image <-> Cairo ARGB32 surfaces, Affine
// -> cairo_matrix_t, and the image metric the tests state their thresholds in.
#pragma once

#include <cairo.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "curvescan/curves/affine.h"
#include "curvescan/raster/image.h"
#include "curvescan/raster/pixel_format.h"

namespace curvescan::testing {

// An ARGB32 Cairo surface holding `image` (premultiplied, native-endian words).
inline cairo_surface_t* argb_surface_of(const Image& image) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, image.width(), image.height());
  cairo_surface_flush(surface);
  unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const std::uint32_t word = to_argb32(image.at(x, y));
      std::memcpy(data + static_cast<std::ptrdiff_t>(y) * stride + 4 * x, &word, 4);
    }
  }
  cairo_surface_mark_dirty(surface);
  return surface;
}

inline Image image_of_surface(cairo_surface_t* surface) {
  cairo_surface_flush(surface);
  const int width = cairo_image_surface_get_width(surface), height = cairo_image_surface_get_height(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint32_t word = 0;
      std::memcpy(&word, data + static_cast<std::ptrdiff_t>(y) * stride + 4 * x, 4);
      image.at(x, y) = from_argb32(word);
    }
  }
  return image;
}

inline cairo_matrix_t cairo_matrix_of(const Affine& m) {
  cairo_matrix_t out;
  cairo_matrix_init(&out, m.a, m.b, m.c, m.d, m.e, m.f);
  return out;
}

/// Per-channel difference statistics of two same-sized images (levels of 255).
struct PixelDiff {
  int max_channel = 0;        // largest |Δ| of any channel of any pixel
  double mean_channel = 0.0;  // mean |Δ| over all channels of all pixels
  int pixels_over_one = 0;    // pixels with some channel |Δ| > 1
};

inline PixelDiff pixel_diff(const Image& ours, const Image& theirs) {
  PixelDiff diff;
  long long total = 0;
  for (std::size_t i = 0; i < ours.pixels().size(); ++i) {
    const Rgba8 p = ours.pixels()[i], q = theirs.pixels()[i];
    const int d[4] = {std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b), std::abs(p.a - q.a)};
    const int worst = std::max(std::max(d[0], d[1]), std::max(d[2], d[3]));
    diff.max_channel = std::max(diff.max_channel, worst);
    total += d[0] + d[1] + d[2] + d[3];
    if (worst > 1) ++diff.pixels_over_one;
  }
  diff.mean_channel = static_cast<double>(total) / (4.0 * static_cast<double>(ours.pixels().size()));
  return diff;
}

}  // namespace curvescan::testing
