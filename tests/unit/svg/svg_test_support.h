// Small helpers shared by the SVG feature tests (masks, patterns, markers, switch, images): a document
// from a body, a render that must succeed, and a message search.
#pragma once

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "curvescan/svg/document.h"

namespace curvescan::svg::testing {

inline std::string svg_document(const std::string& attributes, const std::string& body) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" " +
         attributes + ">" + body + "</svg>";
}

/// `bytes` in base64 (RFC 4648, with padding), for data: URIs.
inline std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char* const kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned n = (bytes[i] << 16) | ((i + 1 < bytes.size() ? bytes[i + 1] : 0) << 8) |
                       (i + 2 < bytes.size() ? bytes[i + 2] : 0);
    out += kAlphabet[(n >> 18) & 63];
    out += kAlphabet[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[n & 63] : '=';
  }
  return out;
}

inline RenderedDocument render(const std::string& text, const RenderOptions& options = {}) {
  Result<RenderedDocument> rendered = render_svg_document(text, options);
  INFO(text);
  if (!rendered) INFO(rendered.error().message);
  REQUIRE(rendered.is_ok());
  return std::move(rendered).value();
}

/// A 40 x 10 px document with `body` (`root_attributes` added to its <svg>): room for a row of four
/// `square`s.
inline std::string row_of_squares(const std::string& body, const std::string& root_attributes = "") {
  return svg_document("width=\"40\" height=\"10\" " + root_attributes, body);
}

/// The `i`-th 10 x 10 px square of a row starting at the origin, with `attributes`; `square_colour`
/// reads its colour back.
inline std::string square(int i, const std::string& attributes) {
  return "<rect x=\"" + std::to_string(10 * i) + "\" width=\"10\" height=\"10\" " + attributes + "/>";
}

/// A `size` x `size` px document with `body` (`root_attributes` added to its <svg>), rendered: the render
/// must succeed.
inline RenderedDocument render_square(int size, const std::string& body, const RenderOptions& options = {},
                                      const std::string& root_attributes = "") {
  const std::string side = "\"" + std::to_string(size) + "\"";
  return render(svg_document("width=" + side + " height=" + side + " " + root_attributes, body), options);
}

inline bool contains(const std::vector<std::string>& messages, const std::string& part) {
  for (const std::string& message : messages) {
    if (message.find(part) != std::string::npos) return true;
  }
  return false;
}

/// The colour at the centre of the i-th 10 x 10 square from the left, as "#rrggbb", or "none" where the
/// pixel is transparent (the style tests' row of squares).
inline std::string square_colour(const Image& image, int i) {
  const Rgba8 pixel = image.at(10 * i + 5, 5);
  if (pixel.a == 0) return "none";
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", pixel.r, pixel.g, pixel.b);
  return text;
}

/// The largest channel difference between two images of one size.
inline int max_delta(const Image& a, const Image& b) {
  REQUIRE(a.pixels().size() == b.pixels().size());
  int worst = 0;
  for (std::size_t i = 0; i < a.pixels().size(); ++i) {
    const Rgba8 p = a.pixels()[i], q = b.pixels()[i];
    worst =
        std::max({worst, std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b), std::abs(p.a - q.a)});
  }
  return worst;
}

/// How many pixels have any ink (alpha > 0).
inline int inked_pixels(const Image& image) {
  return static_cast<int>(
      std::count_if(image.pixels().begin(), image.pixels().end(), [](const Rgba8& p) { return p.a > 0; }));
}

// That `transform` maps `from` to `to`, to 1e-9: the transforms the render-tree tests read are exact in
// binary but for a rotation's cosine and sine (within 1e-16 of 0 and 1), times coordinates under 100.
inline void check_maps(const Affine& transform, Point from, Point to) {
  const Point mapped = transform.apply(from);
  CHECK(mapped.x == Approx(to.x).margin(1e-9));
  CHECK(mapped.y == Approx(to.y).margin(1e-9));
}

}  // namespace curvescan::svg::testing
