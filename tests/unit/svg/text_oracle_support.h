// The oracle of the SVG text tests that compare a document with the library's own text path: `text` laid
// out with a given Font and style from (10, 40) and filled black on a 200 x 60 canvas, and the check that
// a rendered document draws the same.
//
// Tolerance: max |Δ| <= 1/255 per channel — same curves, same rasterizer; only the order in which offsets
// are summed differs (~1e-13 px).
#pragma once

#include <catch2/catch.hpp>
#include <string_view>
#include <utility>

#include "curvescan/raster/canvas.h"
#include "curvescan/text/font.h"
#include "curvescan/text/text_layout.h"
#include "svg_test_support.h"

namespace curvescan::svg::testing {

inline Image fill_text_layout(const Font& font, std::u32string_view text, const TextStyle& style) {
  Result<TextLayout> layout = layout_text(font, text, {10.0, 40.0}, style);
  REQUIRE(layout.is_ok());
  PathBuilder builder;
  REQUIRE(append_text_outlines(font, *layout, builder).is_ok());
  Result<Path> path = builder.build();
  REQUIRE(path.is_ok());
  Result<Canvas> canvas = Canvas::create(200, 60);
  REQUIRE(canvas.is_ok());
  REQUIRE(canvas->fill(*path, Paint::solid({0, 0, 0, 1}), FillRule::kNonZero, Affine::identity()).is_ok());
  return std::move(*canvas).take_image();
}

inline void check_same_text(const Image& expected, const RenderedDocument& actual) {
  CHECK(actual.warnings.empty());
  CHECK(inked_pixels(expected) > 100);  // the text must draw something, or "equal" proves nothing
  CHECK(max_delta(expected, actual.image) <= 1);
}

}  // namespace curvescan::svg::testing
