// Helpers shared by the SVG text layout tests: a document of a given size rendered (it must succeed), and
// DejaVu Sans as the tests' fontconfig configuration finds it, for measuring expected positions.
#pragma once

#include <catch2/catch.hpp>
#include <string>
#include <utility>

#include "curvescan/text/font_lookup.h"
#include "svg_test_support.h"

namespace curvescan::svg::testing {

/// `body` in an SVG root of `width` x `height` pixels, rendered with the default options.
inline RenderedDocument render_sized(int width, int height, const std::string& body) {
  return render(svg_document(
      "width=\"" + std::to_string(width) + "\" height=\"" + std::to_string(height) + "\"", body));
}

/// DejaVu Sans, regular, loaded once.
inline const Font& dejavu_sans() {
  static const Font font = [] {
    Result<Font> loaded = load_font(FontQuery{"DejaVu Sans", 400, false}, false);
    REQUIRE(loaded.is_ok());
    return std::move(loaded).value();
  }();
  return font;
}

}  // namespace curvescan::svg::testing
