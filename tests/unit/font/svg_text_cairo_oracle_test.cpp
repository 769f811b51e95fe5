// SVG <text> against Cairo drawing the same glyph outlines at the same positions: the exact oracle of the
// text renderer (raster/svg/text_element.cpp), with no shaping or hinting difference left.
//
// Oracle: the font file fontconfig chose, opened by FreeType and handed to Cairo with
// cairo_ft_font_face_create_for_ft_face(face, FT_LOAD_NO_HINTING), font options hint style none and
// CAIRO_HINT_METRICS_OFF; the glyphs and their positions are the library's layout (layout_text, HarfBuzz:
// advances and kerning checked against FreeType in text_layout_test.cpp), placed where the SVG
// specification puts them (x, y, the anchor from the advance); cairo_glyph_path + cairo_fill on an A8
// surface under the document's transform. Cairo fills the outline as a path (no glyph cache, so no
// rounding of glyph positions to whole pixels).
//
// Both sides flatten within 0.01 px (cairo_set_tolerance; RenderOptions::tolerance), so what is left is
// Cairo's scan conversion (24.8 fixed point, 15 sub-rows per pixel: up to ~17/255 on an edge pixel, the
// fill oracle's figure, tests/oracle/cairo_oracle_test.cpp) and its 26.6 outline coordinates (1/128 px,
// ~2/255). Bounds, the fill oracle's:
//  - max |Δ| <= 20/255 per pixel (17 + the two 8-bit roundings);
//  - mean |Δ| over the pixels either side inks <= 4/255;
//  - total coverage within 0.5 % (Cairo's sub-row errors are unbiased along an edge and cancel).
// A misplaced glyph (a wrong advance, anchor, size or transform) breaks all three by far.
#include <cairo-ft.h>
#include <cairo.h>
#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "curvescan/svg/document.h"
#include "curvescan/text/font_lookup.h"
#include "curvescan/text/text_layout.h"
#include "curvescan/text/utf8.h"

using namespace curvescan;

namespace {

constexpr int kWidth = 240;
constexpr int kHeight = 90;
constexpr double kTolerance = 0.01;

struct Case {
  std::string name;
  std::string family;
  int weight;
  double size;
  std::string text;
  Point origin;
  TextAnchor anchor;
  std::string anchor_keyword;
  std::string transform;  // SVG transform attribute of the enclosing group
  Affine ctm;
};

// Coverage (alpha) of `text` drawn by Cairo from `file` at the positions of the library's layout.
std::vector<int> cairo_coverage(const Case& c, const std::filesystem::path& file, int face_index) {
  const Result<Font> font = Font::open(file, face_index);
  REQUIRE(font.is_ok());
  const Result<std::u32string> text = decode_utf8(c.text);
  REQUIRE(text.is_ok());
  TextStyle style;
  style.size = c.size;
  style.anchor = c.anchor;
  const Result<TextLayout> layout = layout_text(*font, *text, c.origin, style);
  REQUIRE(layout.is_ok());
  std::vector<cairo_glyph_t> glyphs;
  for (const PositionedGlyph& glyph : layout->glyphs)
    glyphs.push_back({glyph.glyph, glyph.origin.x, glyph.origin.y});

  // One FreeType library for the whole run (it must outlive every face Cairo may still cache); each face
  // is released by Cairo through the font face's user data when Cairo drops it (cairo-ft.h).
  static FT_Library library = [] {
    FT_Library created = nullptr;
    return FT_Init_FreeType(&created) == 0 ? created : nullptr;
  }();
  REQUIRE(library != nullptr);
  FT_Face face = nullptr;
  REQUIRE(FT_New_Face(library, file.c_str(), face_index, &face) == 0);
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_A8, kWidth, kHeight);
  cairo_t* cr = cairo_create(surface);
  cairo_font_face_t* font_face = cairo_ft_font_face_create_for_ft_face(face, FT_LOAD_NO_HINTING);
  static const cairo_user_data_key_t kFaceKey{};
  REQUIRE(cairo_font_face_set_user_data(font_face, &kFaceKey, face, [](void* owned) {
            FT_Done_Face(static_cast<FT_Face>(owned));
          }) == CAIRO_STATUS_SUCCESS);
  cairo_font_options_t* options = cairo_font_options_create();
  cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_NONE);
  cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
  cairo_set_font_options(cr, options);
  const cairo_matrix_t matrix{c.ctm.a, c.ctm.b, c.ctm.c, c.ctm.d, c.ctm.e, c.ctm.f};
  cairo_set_matrix(cr, &matrix);
  cairo_set_font_face(cr, font_face);
  cairo_set_font_size(cr, c.size);
  cairo_set_tolerance(cr, kTolerance);
  cairo_glyph_path(cr, glyphs.data(), static_cast<int>(glyphs.size()));
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
  cairo_set_source_rgba(cr, 0, 0, 0, 1);
  cairo_fill(cr);
  cairo_surface_flush(surface);
  std::vector<int> coverage(static_cast<std::size_t>(kWidth * kHeight));
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      coverage[static_cast<std::size_t>(y * kWidth + x)] = data[static_cast<std::size_t>(y * stride + x)];
    }
  }
  cairo_font_options_destroy(options);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  cairo_font_face_destroy(font_face);
  return coverage;
}

std::vector<int> svg_coverage(const Case& c) {
  const std::string number_x = std::to_string(c.origin.x), number_y = std::to_string(c.origin.y);
  const std::string document = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(kWidth) +
                               "\" height=\"" + std::to_string(kHeight) + "\"><g transform=\"" + c.transform +
                               "\"><text x=\"" + number_x + "\" y=\"" + number_y + "\" font-family=\"" +
                               c.family + "\" font-weight=\"" + std::to_string(c.weight) + "\" font-size=\"" +
                               std::to_string(c.size) + "\" text-anchor=\"" + c.anchor_keyword + "\">" +
                               c.text + "</text></g></svg>";
  svg::RenderOptions options;
  options.tolerance = kTolerance;
  const Result<svg::RenderedDocument> rendered = svg::render_svg_document(document, options);
  REQUIRE(rendered.is_ok());
  CHECK(rendered->warnings.empty());
  std::vector<int> coverage;
  for (const Rgba8& pixel : rendered->image.pixels()) coverage.push_back(pixel.a);
  return coverage;
}

}  // namespace

TEST_CASE("svg text: glyph outlines match Cairo drawing the same font at the same positions") {
  const double degrees = std::numbers::pi / 180.0;
  const std::vector<Case> cases{
      {"DejaVu Sans 24px, start",
       "DejaVu Sans",
       400,
       24.0,
       "Hello, AVA Wy!",
       {12.5, 40.0},
       TextAnchor::kStart,
       "start",
       "",
       Affine::identity()},
      {"Cantarell (CFF) 30px, middle",
       "Cantarell",
       400,
       30.0,
       "Cubic quail",
       {120.0, 50.0},
       TextAnchor::kMiddle,
       "middle",
       "",
       Affine::identity()},
      {"DejaVu Sans Bold 20px, end, rotated and scaled",
       "DejaVu Sans",
       700,
       20.0,
       "Tilt 42",
       {150.0, 40.0},
       TextAnchor::kEnd,
       "end",
       "translate(20 5) rotate(10) scale(1.3 1)",
       Affine::translate(20, 5) * Affine::rotate(10 * degrees) * Affine::scale(1.3, 1.0)},
      {"DejaVu Serif 9px, small text",
       "DejaVu Serif",
       400,
       9.0,
       "small text 0123456789",
       {4.25, 70.0},
       TextAnchor::kStart,
       "start",
       "",
       Affine::identity()},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    const Result<FontMatch> match = match_font(FontQuery{c.family, c.weight, false});
    REQUIRE(match.is_ok());
    REQUIRE(match->family_found);
    const std::vector<int> expected = cairo_coverage(c, match->file, match->face_index);
    const std::vector<int> actual = svg_coverage(c);
    int max_delta = 0, inked = 0;
    double sum_delta = 0.0, expected_total = 0.0, actual_total = 0.0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      const int delta = std::abs(expected[i] - actual[i]);
      max_delta = std::max(max_delta, delta);
      expected_total += expected[i];
      actual_total += actual[i];
      if (expected[i] > 0 || actual[i] > 0) {
        ++inked;
        sum_delta += delta;
      }
    }
    REQUIRE(inked > 200);
    const double mean = sum_delta / inked;
    const double total_error = std::abs(actual_total - expected_total) / expected_total;
    INFO("max |delta| " << max_delta << ", mean |delta| " << mean << "/255 over " << inked
                        << " inked pixels, total coverage error " << total_error * 100.0 << " %");
    CHECK(max_delta <= 20);
    CHECK(mean <= 4.0);
    CHECK(total_error <= 0.005);
    WARN(c.name << ": max |delta| " << max_delta << ", mean " << mean << "/255, total " << total_error * 100.0
                << " %");
  }
}
