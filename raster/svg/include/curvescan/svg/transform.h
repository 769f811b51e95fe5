// SVG transform lists (SVG 1.1 section 7.6 "The 'transform' attribute"):
//   matrix(a b c d e f), translate(tx [ty]), scale(sx [sy]), rotate(angle [cx cy]), skewX(angle),
//   skewY(angle), separated by comma-wsp; arguments separated by comma-wsp. Angles are in degrees.
// The list applies right to left to a point: transform="A B" means A · B, B first (section 7.5).
#pragma once

#include <string_view>

#include "curvescan/curves/affine.h"
#include "curvescan/status.h"

namespace curvescan::svg {

/// Parses a transform list; the empty (or all-whitespace) list is the identity. Fails with a message
/// naming the first malformed item (unknown function, wrong argument count, missing parenthesis).
[[nodiscard]] Result<Affine> parse_transform(std::string_view text);

}  // namespace curvescan::svg
