// Helpers shared by the tests of the filter primitive kernels (filter_*_test.cpp): a primitive element
// parsed from XML text, seeded random images, and an image comparison that reports the worst channel
// difference and where it is.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <memory>
#include <pugixml.hpp>
#include <random>
#include <string>

#include "svg/filter/filter_image.h"

namespace curvescan::svg::testing {

/// Owns the parsed document so that the returned element stays valid.
class PrimitiveXml {
 public:
  explicit PrimitiveXml(const std::string& text) {
    const pugi::xml_parse_result parsed = document_.load_string(text.c_str());
    INFO(text);
    REQUIRE(parsed);
  }
  [[nodiscard]] pugi::xml_node element() const { return document_.document_element(); }

 private:
  pugi::xml_document document_;
};

/// A premultiplied image of random pixels (alpha uniform in [0, 1], colour uniform in [0, alpha]), with a
/// share of fully transparent and fully opaque pixels so the edge cases of unpremultiplying are covered.
inline detail::filter::FilterImage random_image(int width, int height, std::uint32_t seed) {
  detail::filter::FilterImage image(width, height);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      float* p = image.pixel(x, y);
      const float pick = unit(rng);
      const float alpha = pick < 0.1f ? 0.0f : (pick < 0.2f ? 1.0f : unit(rng));
      for (int c = 0; c < 3; ++c) p[c] = alpha * unit(rng);
      p[3] = alpha;
    }
  }
  return image;
}

struct ImageDifference {
  double max_diff = 0.0;
  int x = -1, y = -1, channel = -1;
};

/// The largest absolute channel difference between two images of the same size (NaN counts as infinite).
inline ImageDifference compare_images(const detail::filter::FilterImage& a,
                                      const detail::filter::FilterImage& b) {
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  ImageDifference worst;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      for (int c = 0; c < 4; ++c) {
        double d = std::fabs(static_cast<double>(a.pixel(x, y)[c]) - b.pixel(x, y)[c]);
        if (std::isnan(d)) d = INFINITY;
        if (d > worst.max_diff) worst = {d, x, y, c};
      }
    }
  }
  return worst;
}

/// True when every pixel outside `rect` is transparent black.
inline bool transparent_outside(const detail::filter::FilterImage& image, detail::filter::PixelRect rect) {
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (!rect.contains(x, y))
        for (int c = 0; c < 4; ++c)
          if (image.pixel(x, y)[c] != 0.0f) return false;
  return true;
}

/// True when `part` equals `whole` exactly inside `rect` and is transparent black everywhere else: what a
/// kernel asked for only the pixels of `rect` must give.
inline bool same_inside_and_transparent_outside(const detail::filter::FilterImage& part,
                                                const detail::filter::FilterImage& whole,
                                                detail::filter::PixelRect rect) {
  if (!transparent_outside(part, rect)) return false;
  for (int y = rect.y0; y < rect.y1; ++y)
    for (int x = rect.x0; x < rect.x1; ++x)
      for (int c = 0; c < 4; ++c)
        if (part.pixel(x, y)[c] != whole.pixel(x, y)[c]) return false;
  return true;
}

}  // namespace curvescan::svg::testing
