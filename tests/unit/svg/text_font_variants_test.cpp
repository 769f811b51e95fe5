// font-variant and its longhands, font-feature-settings, font-kerning, kerning and font-stretch
// (raster/svg/text_font_variants.h): the parsers against the grammars of CSS Fonts 4, and whole
// documents against an independent composition — the glyphs the library's shaping gives for the same
// features (text_layout.h, tested against the fonts in tests/unit/font) placed by hand and filled through
// Canvas with the same paint.
//
// Tolerance of the pixel comparisons: max |Δ| <= 1/255 per channel, as in text_layout_features_test.cpp
// (same curves, same rasterizer; only the order in which offsets are summed differs, ~1e-13 px).
#include "svg/text_font_variants.h"

#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/text/font_lookup.h"
#include "curvescan/text/text_layout.h"
#include "property_test_support.h"
#include "svg/computed_style.h"
#include "text_oracle_support.h"

using namespace curvescan;
using curvescan::svg::detail::FontVariants;
using curvescan::svg::testing::apply_declaration;
using curvescan::svg::testing::check_same_text;
using curvescan::svg::testing::max_delta;

namespace {

constexpr double kSize = 24.0;

std::optional<FontVariants> parsed(std::string_view name, std::string_view value,
                                   const FontVariants& parent = {}) {
  FontVariants variants;
  if (!apply_declaration(variants, parent, name, value)) return std::nullopt;
  return variants;
}

bool has(const std::vector<FontFeature>& features, std::string_view tag, std::uint32_t value) {
  for (const FontFeature& feature : features)
    if (feature.tag == font_feature_tag(tag) && feature.value == value) return true;
  return false;
}

svg::RenderedDocument render_text(const std::string& attributes, const std::string& content) {
  return svg::testing::render(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"60\"><text x=\"10\" "
      "y=\"40\" font-size=\"24\" " +
      attributes + ">" + content + "</text></svg>");
}

// The oracle: `text` laid out by the library with `style` from (10, 40) in `family`, filled black.
Image composed(const std::string& family, std::u32string_view text, TextStyle style, double width = 100.0) {
  Result<Font> font = load_font(FontQuery{family, 400, false, width}, false);
  REQUIRE(font.is_ok());
  style.size = kSize;
  return svg::testing::fill_text_layout(*font, text, style);
}

}  // namespace

TEST_CASE("font variants: the longhands map to the OpenType features CSS Fonts 4 names") {
  CHECK(parsed("font-variant-caps", "small-caps")->caps == CapsVariant::kSmallCaps);
  CHECK(parsed("font-variant-caps", "all-petite-caps")->caps == CapsVariant::kAllSmallCaps);
  CHECK(has(parsed("font-variant-caps", "unicase")->caps_features, "unic", 1));
  CHECK_FALSE(parsed("font-variant-caps", "tiny-caps"));

  const auto ligatures = parsed("font-variant-ligatures", "no-common-ligatures discretionary-ligatures");
  REQUIRE(ligatures);
  CHECK(has(ligatures->ligatures, "liga", 0));
  CHECK(has(ligatures->ligatures, "clig", 0));
  CHECK(has(ligatures->ligatures, "dlig", 1));
  CHECK(has(parsed("font-variant-ligatures", "none")->ligatures, "calt", 0));
  CHECK_FALSE(parsed("font-variant-ligatures", "common-ligatures no-common-ligatures"));  // one group twice

  const auto numeric = parsed("font-variant-numeric", "oldstyle-nums tabular-nums slashed-zero");
  REQUIRE(numeric);
  CHECK(has(numeric->numeric, "onum", 1));
  CHECK(has(numeric->numeric, "tnum", 1));
  CHECK(has(numeric->numeric, "zero", 1));
  CHECK_FALSE(parsed("font-variant-numeric", "lining-nums oldstyle-nums"));
  CHECK(has(parsed("font-variant-position", "super")->position, "sups", 1));
  CHECK(has(parsed("font-variant-east-asian", "jis04 full-width")->east_asian, "fwid", 1));
  CHECK(parsed("font-variant-numeric", "normal")->numeric.empty());
}

TEST_CASE("font variants: the font-variant shorthand sets every longhand") {
  FontVariants parent;
  parent.numeric = {{font_feature_tag("onum"), 1}};
  FontVariants variants = parent;
  REQUIRE(apply_declaration(variants, parent, "font-variant", "small-caps ordinal no-contextual sub"));
  CHECK(variants.caps == CapsVariant::kSmallCaps);
  CHECK(has(variants.numeric, "ordn", 1));
  CHECK_FALSE(has(variants.numeric, "onum", 1));  // replaced, not added to
  CHECK(has(variants.ligatures, "calt", 0));
  CHECK(has(variants.position, "subs", 1));
  REQUIRE(apply_declaration(variants, parent, "font-variant", "normal"));
  CHECK(variants.caps == CapsVariant::kNormal);
  CHECK(variants.numeric.empty());
  REQUIRE(apply_declaration(variants, parent, "font-variant", "inherit"));
  CHECK(has(variants.numeric, "onum", 1));
  CHECK_FALSE(parsed("font-variant", "small-caps all-small-caps"));
  CHECK_FALSE(parsed("font-variant", "sub super"));
  CHECK_FALSE(parsed("font-variant", "bold"));
  CHECK_FALSE(parsed("font-variant", ""));
}

TEST_CASE("font variants: font-feature-settings, font-kerning, kerning and font-stretch") {
  const auto settings = parsed("font-feature-settings", "\"liga\" 0, 'ss01', \"salt\" 3, \"kern\" off");
  REQUIRE(settings);
  REQUIRE(settings->settings.size() == 4);
  CHECK(has(settings->settings, "liga", 0));
  CHECK(has(settings->settings, "ss01", 1));
  CHECK(has(settings->settings, "salt", 3));
  CHECK(has(settings->settings, "kern", 0));
  // The features come last, after the variants (CSS Fonts 4 7.2).
  FontVariants both = *settings;
  both.numeric = {{font_feature_tag("onum"), 1}};
  CHECK(both.features().back().tag == font_feature_tag("kern"));
  for (const char* bad :
       {"liga", "\"lig\"", "\"ligat\"", "\"liga\" -1", "\"liga\" 1.5", "\"liga\" 1,", "\"li\xc3\xa9\""})
    CHECK_FALSE(parsed("font-feature-settings", bad));
  CHECK(parsed("font-feature-settings", "normal")->settings.empty());

  CHECK_FALSE(parsed("font-kerning", "none")->kerning);
  CHECK(parsed("font-kerning", "auto")->kerning);
  CHECK_FALSE(parsed("font-kerning", "off"));
  CHECK(parsed("kerning", "2px")->kerning_length->value == 2.0);
  CHECK_FALSE(parsed("kerning", "auto")->kerning_length);
  CHECK_FALSE(parsed("kerning", "5%"));

  CHECK(parsed("font-stretch", "condensed")->stretch == 75.0);
  CHECK(parsed("font-stretch", "62.5%")->stretch == 62.5);
  CHECK_FALSE(parsed("font-stretch", "-10%"));
  CHECK_FALSE(parsed("font-stretch", "75"));
  FontVariants condensed;
  condensed.stretch = 75.0;
  CHECK(parsed("font-stretch", "wider", condensed)->stretch == 87.5);
  CHECK(parsed("font-stretch", "narrower", condensed)->stretch == 62.5);
}

TEST_CASE("font variants in documents: small caps, features, kerning and width draw as the layout says") {
  // DejaVu Sans has no small capitals: synthesized (lowercase as uppercase at 0.7 of the size).
  TextStyle small_caps;
  small_caps.caps = CapsVariant::kSmallCaps;
  const Image synthesized = composed("DejaVu Sans", U"Small Caps", small_caps);
  check_same_text(synthesized,
                  render_text("font-family=\"DejaVu Sans\" font-variant=\"small-caps\"", "Small Caps"));
  check_same_text(synthesized, render_text("style=\"font: small-caps 24px 'DejaVu Sans'\"", "Small Caps"));
  CHECK(max_delta(synthesized, composed("DejaVu Sans", U"Small Caps", {})) > 100);  // not the plain text
  // Noto Sans Mono has them: its 'smcp' glyphs.
  check_same_text(
      composed("Noto Sans Mono", U"Small Caps", small_caps),
      render_text("font-family=\"Noto Sans Mono\" style=\"font-variant-caps: small-caps\"", "Small Caps"));

  // "AV" kerned by default; font-kerning: none, kerning="0" and the 'kern' feature off all unkern it.
  TextStyle unkerned;
  unkerned.kerning = false;
  const Image apart = composed("DejaVu Sans", U"AVAV", unkerned);
  check_same_text(apart, render_text("font-family=\"DejaVu Sans\" style=\"font-kerning: none\"", "AVAV"));
  check_same_text(apart, render_text("font-family=\"DejaVu Sans\" kerning=\"0\"", "AVAV"));
  check_same_text(
      apart, render_text("font-family=\"DejaVu Sans\" style=\"font-feature-settings: 'kern' off\"", "AVAV"));
  CHECK(max_delta(apart, composed("DejaVu Sans", U"AVAV", {})) > 100);
  // SVG 2 6.6: font-kerning, font-feature-settings, the font-variant-* longhands and
  // font-variation-settings have no presentation attribute: as attributes they change nothing, and each
  // is named in a warning (nothing the document says is dropped silently).
  const Image kerned = composed("DejaVu Sans", U"AVAV", {});
  for (const char* attribute :
       {"font-kerning=\"none\"", "font-feature-settings=\"'kern' off\"", "font-variant-caps=\"small-caps\"",
        "font-variation-settings=\"'wght' 700\"", "font-variant-ligatures=\"none\""}) {
    INFO(attribute);
    const svg::RenderedDocument ignored =
        render_text(std::string("font-family=\"DejaVu Sans\" ") + attribute, "AVAV");
    CHECK(max_delta(kerned, ignored.image) <= 1);
    const std::string name = std::string(attribute).substr(0, std::string(attribute).find('='));
    REQUIRE(ignored.warnings.size() == 1);
    CHECK(ignored.warnings[0].find("the " + name + " attribute (a CSS property only") != std::string::npos);
  }
  // The shorthand font-variant is one (SVG 2 6.6 lists it), and so is SVG 1.1's kerning (above).
  TextStyle small_capitals;
  small_capitals.caps = CapsVariant::kSmallCaps;
  check_same_text(composed("DejaVu Sans", U"AVav", small_capitals),
                  render_text("font-family=\"DejaVu Sans\" font-variant=\"small-caps\"", "AVav"));

  // font-feature-settings: the "fi" ligature off.
  TextStyle no_ligature;
  no_ligature.features = {{font_feature_tag("liga"), 0}};
  check_same_text(
      composed("DejaVu Sans", U"fifi", no_ligature),
      render_text("font-family=\"DejaVu Sans\" style=\"font-feature-settings: 'liga' 0\"", "fifi"));

  // font-stretch: condensed selects the DejaVu Sans Condensed face of the family.
  const Image condensed = composed("DejaVu Sans", U"Wide", {}, 75.0);
  check_same_text(condensed, render_text("font-family=\"DejaVu Sans\" font-stretch=\"condensed\"", "Wide"));
  CHECK(max_delta(condensed, composed("DejaVu Sans", U"Wide", {})) > 100);
  Result<FontMatch> match = match_font(FontQuery{"DejaVu Sans", 400, false, 75.0});
  REQUIRE(match.is_ok());
  CHECK(match->file.filename() == "DejaVuSansCondensed.ttf");
}
