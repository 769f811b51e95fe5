// SVG lengths: a number and a unit (SVG 1.1 section 7.10 "Units"; CSS 2.1 section 4.3.2).
//
// Absolute units convert at the CSS ratios, fixed by the document resolution `dpi` (96 by default, as in
// CSS and rsvg-convert): 1in = dpi px, 1cm = dpi/2.54 px, 1mm = dpi/25.4 px, 1pt = dpi/72 px,
// 1pc = dpi/6 px. "em" is the font size and "ex" half of it (the value rsvg uses without font metrics).
// Percentages are of a reference length that depends on the attribute (SVG 1.1 section 7.10): the viewport
// width for x-like values, its height for y-like values, and sqrt((w² + h²) / 2) for others (radii,
// stroke-width) -- the caller chooses. The resolution may differ across and down (rsvg-convert's -d and
// -p): the caller chooses it the same way (Resolution), as librsvg 2.54 does.
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

/// The resolution of in, cm, mm, pt and pc, in pixels per inch, across (x) and down (y).
struct Resolution {
  double x = 96.0;
  double y = 96.0;
  /// For lengths that run neither across nor down (r, stroke-width, font-size, stroke-dasharray):
  /// sqrt((x² + y²) / 2), the rule SVG 1.1 7.10 gives for such percentages and the one librsvg 2.54
  /// applies to their physical units (its Length<Both>).
  [[nodiscard]] double diagonal() const noexcept;
};

/// What one length is resolved against, along its direction: what 100% means, and the resolution of
/// in, cm, mm, pt and pc (Resolution::x for x-like lengths, y for y-like, diagonal() for others).
struct LengthAxis {
  double percent_reference = 0.0;
  double dpi = 96.0;
};

/// What a length is resolved against.
struct LengthContext {
  double dpi = 96.0;               ///< the resolution along this length's direction (see LengthAxis)
  double font_size = 16.0;         ///< in px: the CSS initial "medium" font size
  double percent_reference = 0.0;  ///< in px: what 100% means for this attribute
};

/// The length in user units (px). NaN in, NaN out.
[[nodiscard]] double length_to_pixels(Length length, const LengthContext& context) noexcept;

}  // namespace curvescan::svg
