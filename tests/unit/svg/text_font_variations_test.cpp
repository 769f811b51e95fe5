// Variable fonts in SVG text (raster/svg/text_fonts.h, text_font_variants.h): font-variation-settings
// and font-optical-sizing parsed to the grammar of CSS Fonts 4, the coordinates font-weight,
// font-stretch and font-style imply (CSS Fonts 4 7.2), and whole documents against an independent
// composition: the same text laid out by the library with a Font moved to the expected coordinates by
// Font::set_variations (tested against the font's named instances in tests/unit/font) and filled through
// Canvas.
//
// Tolerance of the pixel comparisons: max |Δ| <= 1/255 per channel, as text_font_variants_test.cpp
// (same curves, same rasterizer; only the order in which offsets are summed differs).
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/text/font_lookup.h"
#include "curvescan/text/text_layout.h"
#include "property_test_support.h"
#include "svg/computed_style.h"
#include "svg/text_fonts.h"
#include "text_oracle_support.h"

using namespace curvescan;
using curvescan::svg::detail::font_style_oblique_angle;
using curvescan::svg::detail::FontVariants;
using curvescan::svg::testing::apply_declaration;
using curvescan::svg::testing::check_same_text;
using curvescan::svg::testing::inked_pixels;

namespace {

constexpr const char* kInterFile = "/usr/share/fonts/truetype/inter-vf/Inter.var.ttf";

std::optional<FontVariants> parsed(std::string_view name, std::string_view value) {
  FontVariants variants;
  if (!apply_declaration(variants, FontVariants{}, name, value)) return std::nullopt;
  return variants;
}

svg::RenderedDocument render_text(const std::string& attributes) {
  return svg::testing::render(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"60\"><text x=\"10\" y=\"40\" "
      "font-family=\"Inter\" font-size=\"24\" " +
      attributes + ">Hamburg</text></svg>");
}

// The oracle: "Hamburg" in Inter at `variations`, 24 px, from (10, 40), filled black.
Image composed(const std::vector<FontVariation>& variations) {
  Result<Font> font = Font::open(kInterFile);
  REQUIRE(font.is_ok());
  REQUIRE(font->set_variations(variations).is_ok());
  TextStyle style;
  style.size = 24.0;
  return svg::testing::fill_text_layout(*font, U"Hamburg", style);
}

FontVariation axis(std::string_view tag, double value) {
  return {font_feature_tag(tag), value};
}

}  // namespace

TEST_CASE("font variations: font-variation-settings and font-optical-sizing follow CSS Fonts 4") {
  const auto settings = parsed("font-variation-settings", "'wght' 650.5, \"wdth\" 80");
  REQUIRE(settings);
  REQUIRE(settings->variation_settings.size() == 2);
  CHECK(settings->variation_settings[0] == axis("wght", 650.5));
  CHECK(settings->variation_settings[1] == axis("wdth", 80.0));
  CHECK(parsed("font-variation-settings", "normal")->variation_settings.empty());
  CHECK(parsed("font-variation-settings", "'slnt' -10")->variation_settings[0] == axis("slnt", -10.0));
  for (const char* bad : {"wght 700", "'wght'", "'wgh' 700", "'wght' bold", "'wght' 700,", "'wght' 1e999"})
    CHECK_FALSE(parsed("font-variation-settings", bad));
  CHECK_FALSE(parsed("font-optical-sizing", "none")->optical_sizing);
  CHECK(parsed("font-optical-sizing", "auto")->optical_sizing);
  CHECK_FALSE(parsed("font-optical-sizing", "yes"));

  CHECK(font_style_oblique_angle("oblique") == 14.0);  // CSS Fonts 4 2.4: the default angle
  CHECK(font_style_oblique_angle("oblique 10deg") == 10.0);
  CHECK(font_style_oblique_angle("oblique -0.25turn") == -90.0);
  CHECK_FALSE(font_style_oblique_angle("oblique 91deg"));
  CHECK_FALSE(font_style_oblique_angle("oblique 10"));
  CHECK_FALSE(font_style_oblique_angle("italic"));
  CHECK_FALSE(font_style_oblique_angle("obliquely"));
}

TEST_CASE("font variations: the coordinates of a style, only for the axes the face has") {
  Result<Font> inter = Font::open(kInterFile);
  REQUIRE(inter.is_ok());
  svg::detail::ComputedStyle style;
  style.font_weight = 700;
  style.font_size = 20.0;
  // Inter has wght and slnt: font-weight, and font-style: oblique 14deg as slnt -14 (set_variations
  // clamps it to the axis's -10); it has no wdth, ital or opsz, so font-stretch and the size
  // (font-optical-sizing: auto) add nothing.
  style.text.font_variants.stretch = 75.0;
  style.text.font_variants.oblique_angle = 14.0;
  style.font_italic = true;
  CHECK(svg::detail::variations_for(style, *inter) ==
        std::vector<FontVariation>{axis("slnt", -14.0), axis("wght", 700.0)});
  // Italic without an oblique angle asks for ital, which Inter lacks.
  style.text.font_variants.oblique_angle.reset();
  CHECK(svg::detail::variations_for(style, *inter) == std::vector<FontVariation>{axis("wght", 700.0)});
  // font-variation-settings wins over font-weight (CSS Fonts 4 7.2), the last of one axis over earlier.
  style.text.font_variants.variation_settings = {axis("wght", 300.0), axis("wght", 200.0), axis("opsz", 9.0)};
  CHECK(svg::detail::variations_for(style, *inter) == std::vector<FontVariation>{axis("wght", 200.0)});
  // A face without axes: none.
  Result<Font> dejavu = load_font(FontQuery{"DejaVu Sans", 400, false, 100.0}, false);
  REQUIRE(dejavu.is_ok());
  CHECK(svg::detail::variations_for(style, *dejavu).empty());
}

TEST_CASE("font variations: documents draw the variable font at the coordinates asked for") {
  check_same_text(composed({axis("wght", 700.0)}), render_text("font-weight=\"bold\""));
  check_same_text(composed({axis("wght", 400.0)}), render_text(""));
  check_same_text(composed({axis("wght", 250.0)}),
                  render_text("font-weight=\"bold\" style=\"font-variation-settings: 'wght' 250\""));
  check_same_text(composed({axis("wght", 400.0), axis("slnt", -10.0)}),
                  render_text("font-style=\"oblique 10deg\""));
  check_same_text(composed({axis("wght", 400.0), axis("slnt", -10.0)}),
                  render_text("font-style=\"oblique\""));
  // Bold really is different from regular: more ink.
  CHECK(inked_pixels(composed({axis("wght", 900.0)})) > inked_pixels(composed({axis("wght", 100.0)})));
}
