// viewBox and preserveAspectRatio: the mapping from a viewBox to a viewport (SVG 1.1 sections 7.7 and 7.8).
#pragma once

#include <string_view>

#include "curvescan/curves/affine.h"
#include "curvescan/status.h"

namespace curvescan::svg {

/// The rectangle of user space a viewport shows: min-x, min-y, width, height.
struct ViewBox {
  double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
};

/// Parses "min-x min-y width height" (comma-wsp separated). Fails on anything else, or a negative width or
/// height (an error in SVG 1.1 7.7). Zero is accepted: the caller must then not render the element.
[[nodiscard]] Result<ViewBox> parse_view_box(std::string_view text);

/// preserveAspectRatio as numbers: the alignment fractions (xMin = 0, xMid = 0.5, xMax = 1) and the
/// meet/slice choice; `none` stretches non-uniformly.
struct PreserveAspectRatio {
  bool none = false;
  double align_x = 0.5;  ///< default xMidYMid meet
  double align_y = 0.5;
  bool slice = false;
};

/// Parses "[defer] <align> [meet|slice]" (SVG 1.1 7.8). Fails with a message naming the text.
[[nodiscard]] Result<PreserveAspectRatio> parse_preserve_aspect_ratio(std::string_view text);

/// The transform that maps `view_box` onto the viewport (x, y, width, height) as SVG 1.1 7.8 prescribes:
/// scale (uniform unless `none`: the smaller ratio for meet, the larger for slice), then translate so the
/// chosen alignment points coincide. A zero-size view box gives a non-finite or singular transform;
/// callers check the view box first.
[[nodiscard]] Affine view_box_transform(const ViewBox& view_box, const PreserveAspectRatio& aspect, double x,
                                        double y, double width, double height) noexcept;

}  // namespace curvescan::svg
