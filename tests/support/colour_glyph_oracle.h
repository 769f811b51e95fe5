// The oracle of the colour-glyph tests: what glyph "A" of tests/fonts/CurvescanColourTest.ttf looks like,
// worked out from the rectangles tests/fonts/make_colour_test_font.py gives its COLR version 0 layers,
// with no font code at all. At a font size of 100 px (1000 units to the em: 10 units a pixel) and a
// baseline at a whole pixel, every layer edge lies on a pixel boundary, so each pixel is wholly inside or
// outside each layer, and its colour is the source-over composition (Porter and Duff, "Compositing
// Digital Images") of the layers covering it, bottom first, over an opaque white background:
//   red   (0,0)-(600,600)     palette entry 0, #ff0000
//   fg    (100,100)-(300,500) the text's own colour
//   blue  (200,200)-(500,400) palette entry 1, #0000ff at alpha 128/255
// A palette colour's alpha is multiplied by the alpha of the text's colour (color_glyph.h, text_ink.h).
//
// Tolerance of a comparison: 1/255 per channel — each composited channel is rounded to 8 bits once by
// the canvas and once here.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "curvescan/raster/image.h"
#include "curvescan/raster/paint.h"

namespace curvescan::test {

struct ColourGlyphScene {
  int origin_x = 0;        ///< the glyph origin (pen) in pixels
  int baseline = 0;        ///< the baseline's y in pixels
  Color text{0, 1, 0, 1};  ///< the text's fill, straight alpha
};

/// Straight colour of an opaque result, 0..255 per channel.
struct Rgb {
  double r = 255.0, g = 255.0, b = 255.0;
};

inline void composite(Rgb& under, const Color& over) {
  under.r = over.r * 255.0 * over.a + under.r * (1.0 - over.a);
  under.g = over.g * 255.0 * over.a + under.g * (1.0 - over.a);
  under.b = over.b * 255.0 * over.a + under.b * (1.0 - over.a);
}

/// The expected colour of pixel (x, y) of `scene` on white.
inline Rgb colour_glyph_pixel(const ColourGlyphScene& scene, int x, int y) {
  // Font units of the pixel's centre (y up from the baseline); 10 units a pixel.
  const double u = (x + 0.5 - scene.origin_x) * 10.0, v = (scene.baseline - (y + 0.5)) * 10.0;
  const auto inside = [&](double x0, double y0, double x1, double y1) {
    return u > x0 && u < x1 && v > y0 && v < y1;
  };
  Rgb result;
  const double fade = scene.text.a;
  if (inside(0, 0, 600, 600)) composite(result, Color{1, 0, 0, fade});
  if (inside(100, 100, 300, 500)) composite(result, scene.text);
  if (inside(200, 200, 500, 400)) composite(result, Color{0, 0, 1, 128.0 / 255.0 * fade});
  return result;
}

/// The largest difference, over every pixel and channel, between `image` (opaque, so premultiplied is
/// straight) and the oracle.
inline int colour_glyph_max_delta(const Image& image, const ColourGlyphScene& scene) {
  int worst = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const Rgb expected = colour_glyph_pixel(scene, x, y);
      const Rgba8 actual = image.at(x, y);
      worst = std::max({worst, std::abs(actual.r - static_cast<int>(std::lround(expected.r))),
                        std::abs(actual.g - static_cast<int>(std::lround(expected.g))),
                        std::abs(actual.b - static_cast<int>(std::lround(expected.b))), 255 - actual.a});
    }
  }
  return worst;
}

}  // namespace curvescan::test
