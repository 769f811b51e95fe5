// The font properties that choose glyphs within a face, or a face's width — all applied through
// HarfBuzz features or fontconfig (CSS Fonts 4):
//  - font-variant (section 6.11, the shorthand; CSS 2.1's normal | small-caps is a case of it) and its
//    longhands font-variant-caps (6.6), -ligatures (6.4), -position (6.5), -numeric (6.7) and
//    -east-asian (6.10), each value the OpenType feature the section names;
//  - font-feature-settings (7.12): features by tag, applied after everything else (7.2);
//  - font-kerning (6.3): none switches 'kern' off; SVG 1.1's kerning (10.11): auto, or a length, which
//    switches kerning off and adds the length between characters like letter-spacing;
//  - font-stretch (2.3, "font-width" in later drafts): the width fontconfig selects the face by;
//  - font-variation-settings (7.13) and font-optical-sizing (7.12 of Fonts 4's later drafts): the
//    coordinates of a variable font (text_fonts.h adds those font-weight, font-stretch and font-style
//    imply, CSS Fonts 4 7.2).
// Every one is inherited. font-variant-alternates and font-variant-emoji are not handled (their values
// are invalid here, so a declaration using them is ignored with a warning).
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "curvescan/svg/length.h"
#include "curvescan/text/text_layout.h"

namespace curvescan::svg::detail {

struct FontVariants {
  /// font-variant-caps: small-caps and all-small-caps as the layout makes them (text_layout.h: the font's
  /// or synthesized); petite-caps and all-petite-caps are drawn as small-caps and all-small-caps (CSS
  /// Fonts 4 6.6: "if the font does not support petite capitals, [they] are rendered as small capitals"),
  /// unicase and titling-caps through 'unic' and 'titl' (in `caps_features`).
  CapsVariant caps = CapsVariant::kNormal;
  std::vector<FontFeature> caps_features;
  std::vector<FontFeature> ligatures;    ///< font-variant-ligatures
  std::vector<FontFeature> position;     ///< font-variant-position
  std::vector<FontFeature> numeric;      ///< font-variant-numeric
  std::vector<FontFeature> east_asian;   ///< font-variant-east-asian
  std::vector<FontFeature> settings;     ///< font-feature-settings
  bool kerning = true;                   ///< font-kerning: auto and normal on, none off
  std::optional<Length> kerning_length;  ///< SVG 1.1 kerning: <length>; nullopt for auto
  double stretch = 100.0;                ///< font-stretch as a percentage of the normal width
  std::vector<FontVariation> variation_settings;  ///< font-variation-settings, in the order written
  bool optical_sizing = true;            ///< font-optical-sizing: auto (true) or none
  /// font-style: oblique's angle in degrees, clockwise (CSS Fonts 4 2.4; 14 when no angle is given);
  /// nullopt for normal and italic. Set with font-style by the cascade (computed_style.cpp).
  std::optional<double> oblique_angle;

  /// Every feature in the order CSS Fonts 4 7.2 applies them, font-feature-settings last.
  [[nodiscard]] std::vector<FontFeature> features() const;
};

/// True for those of them SVG 2 gives no presentation attribute, so that they are set in CSS only (a
/// style attribute or a style sheet): SVG 2 section 6.6 lists, of the font properties, only font-family,
/// font-size, font-size-adjust, font-stretch, font-style, font-variant and font-weight as presentation
/// attributes, so the longhands font-variant-*, font-feature-settings, font-kerning,
/// font-variation-settings, font-optical-sizing and font-width are not (an attribute of that name is an
/// unknown attribute, ignored, as resvg and browsers do). SVG 1.1's kerning attribute stays one.
[[nodiscard]] bool is_css_only_font_property(std::string_view name) noexcept;

/// The appliers of the properties above, one per property, each a row of the cascade's property table
/// (computed_style.cpp, which also holds the keyword tables of font-kerning and font-optical-sizing):
/// `value` is trimmed, `inherit` says it is "inherit" (`parent` serves it, and font-stretch's wider and
/// narrower). Each returns false when the value is invalid (the caller warns and ignores it).
namespace font_variant {
using Applier = bool (*)(FontVariants& variants, const FontVariants& parent, std::string_view value,
                         bool inherit);
/// The font-variant shorthand (CSS Fonts 4 6.11).
bool font_variant(FontVariants&, const FontVariants&, std::string_view, bool);
bool font_variant_caps(FontVariants&, const FontVariants&, std::string_view, bool);
bool font_variant_ligatures(FontVariants&, const FontVariants&, std::string_view, bool);
bool font_variant_position(FontVariants&, const FontVariants&, std::string_view, bool);
bool font_variant_numeric(FontVariants&, const FontVariants&, std::string_view, bool);
bool font_variant_east_asian(FontVariants&, const FontVariants&, std::string_view, bool);
bool font_feature_settings(FontVariants&, const FontVariants&, std::string_view, bool);
bool font_variation_settings(FontVariants&, const FontVariants&, std::string_view, bool);
/// SVG 1.1's kerning: auto or a <length>.
bool kerning(FontVariants&, const FontVariants&, std::string_view, bool);
/// font-stretch, and font-width (its CSS Fonts 4 name), read alike.
bool font_stretch(FontVariants&, const FontVariants&, std::string_view, bool);
}  // namespace font_variant

/// The angle of a font-style value in degrees (CSS Fonts 4 2.4): 14 for "oblique", the angle of
/// "oblique <angle>" (deg, grad, rad or turn, within [-90deg, 90deg]); nullopt for anything else.
[[nodiscard]] std::optional<double> font_style_oblique_angle(std::string_view value) noexcept;

/// font-stretch keywords and percentages (CSS Fonts 4 2.3): the percentage, or nullopt.
[[nodiscard]] std::optional<double> parse_font_stretch(std::string_view value) noexcept;

}  // namespace curvescan::svg::detail
