// The Unicode Vertical_Orientation property (UAX #50, "Unicode Vertical Text Layout"), which CSS Writing
// Modes 3 section 5.1 (text-orientation: mixed) uses to decide which characters of vertical text stand
// upright and which are turned sideways.
#pragma once

namespace curvescan::svg::detail {

enum class VerticalOrientation {
  kRotated,               ///< R: turned 90 degrees clockwise, as Latin letters
  kUpright,               ///< U: upright, as CJK ideographs, kana and most emoji
  kTransformedOrUpright,  ///< Tu: a vertical alternate glyph (OpenType 'vert'), else upright
  kTransformedOrRotated,  ///< Tr: a vertical alternate glyph (OpenType 'vert'), else rotated
};

/// The Vertical_Orientation of `c` (Unicode 15.0 data); R for every code point the data does not list,
/// and for values outside the code space.
VerticalOrientation vertical_orientation(char32_t c) noexcept;

}  // namespace curvescan::svg::detail
