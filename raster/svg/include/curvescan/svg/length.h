// SVG lengths: a number and a unit (SVG 1.1 section 7.10 "Units"; CSS 2.1 section 4.3.2).
//
// Absolute units convert at the CSS ratios, fixed by the document resolution `dpi` (96 by default, as in
// CSS and rsvg-convert): 1in = dpi px, 1cm = dpi/2.54 px, 1mm = dpi/25.4 px, 1pt = dpi/72 px,
// 1pc = dpi/6 px. "em" is the font size and "ex" half of it (the value rsvg uses without font metrics).
// Percentages are of a reference length that depends on the attribute (SVG 1.1 section 7.10): the viewport
// width for x-like values, its height for y-like values, and sqrt((w² + h²) / 2) for others (radii,
// stroke-width) -- the caller chooses.
#pragma once

#include <string_view>

#include "curvescan/status.h"

namespace curvescan::svg {

enum class LengthUnit { kNone, kPx, kPt, kPc, kMm, kCm, kIn, kEm, kEx, kPercent };

struct Length {
  double value = 0.0;
  LengthUnit unit = LengthUnit::kNone;
};

/// Parses "<number><unit>?" with optional surrounding wsp. Units are case-sensitive lower case as in CSS
/// ("px", not "PX"). Fails with a message naming the text: not a number, or an unknown unit such as "3km".
[[nodiscard]] Result<Length> parse_length(std::string_view text);

/// What a length is resolved against.
struct LengthContext {
  double dpi = 96.0;
  double font_size = 16.0;         ///< in px: the CSS initial "medium" font size
  double percent_reference = 0.0;  ///< in px: what 100% means for this attribute
};

/// The length in user units (px). NaN in, NaN out.
[[nodiscard]] double length_to_pixels(Length length, const LengthContext& context) noexcept;

}  // namespace curvescan::svg
