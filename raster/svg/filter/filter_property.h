// The `filter` property (Filter Effects 1, section 11 "The filter property", and section 13 "Filter
// functions"): none, or a list of url(#id) references to <filter> elements and CSS filter functions, applied
// one after the other, each taking the previous one's result as its SourceGraphic.
//
// The functions are shorthands for filter primitives (section 13, "equivalent SVG filter"):
//   blur(σ)                         feGaussianBlur stdDeviation σ (a length, default 0)
//   drop-shadow(color? dx dy σ?)    feDropShadow (colour default currentColor, σ default 0)
//   brightness(n)                   feComponentTransfer linear slope n on R, G, B (default 1)
//   contrast(n)                     linear slope n, intercept 0.5 - 0.5 n (default 1)
//   grayscale(n), sepia(n)          feColorMatrix of section 13 (amount clamped to [0, 1], default 1)
//   hue-rotate(angle)               feColorMatrix hueRotate (deg, rad, grad, turn; default 0)
//   invert(n)                       table [n, 1 - n] on R, G, B (clamped, default 1)
//   opacity(n)                      table [0, n] on A (clamped, default 1)
//   saturate(n)                     feColorMatrix saturate n (default 1)
// Amounts accept a number or a percentage (50% = 0.5) and refuse negatives. Lengths may omit the unit (px):
// SVG 2 (6.8) lets presentation attributes write unitless lengths, and browsers accept filter="blur(4)".
// Lengths in em and ex depend on the element's font-size, known only once its style is computed: they are
// kept as a px part and an em part, and resolved_for(font_size) gives the lengths in user units.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "curvescan/svg/color.h"

namespace curvescan::svg::detail::filter {

struct FilterFunction {
  enum class Kind {
    kUrl,
    kBlur,
    kDropShadow,
    kBrightness,
    kContrast,
    kGrayscale,
    kHueRotate,
    kInvert,
    kOpacity,
    kSaturate,
    kSepia
  };
  Kind kind = Kind::kUrl;
  std::string url_id;          ///< kUrl: the referenced id without '#'
  double amount = 0.0;         ///< the function's argument: an amount, degrees, or σ in user units
  double dx = 0.0, dy = 0.0;   ///< drop-shadow offset in user units
  std::optional<Color> color;  ///< drop-shadow colour; nullopt means currentColor
  /// The font-relative parts of blur's σ (amount) and drop-shadow's dx, dy and σ: that many font sizes are
  /// added to amount, dx and dy by resolved_for.
  double amount_em = 0.0, dx_em = 0.0, dy_em = 0.0;
  bool operator==(const FilterFunction&) const = default;

  /// This function with its lengths in user units for an element of `font_size` (px).
  [[nodiscard]] FilterFunction resolved_for(double font_size) const {
    FilterFunction f = *this;
    f.amount += amount_em * font_size;
    f.dx += dx_em * font_size;
    f.dy += dy_em * font_size;
    f.amount_em = f.dx_em = f.dy_em = 0.0;
    return f;
  }
};

/// The list `text` declares ("none" gives an empty list), or nullopt when it is not a valid value.
[[nodiscard]] std::optional<std::vector<FilterFunction>> parse_filter_property(std::string_view text);

}  // namespace curvescan::svg::detail::filter
