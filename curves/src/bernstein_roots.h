// Roots in [0, 1] of a polynomial given by its Bernstein coefficients: the extrema of Bézier curves (the
// coordinates of the hodograph, bezier.cpp) and of rational Bézier curves (the numerator of the quotient
// rule's derivative, rational_bezier.cpp). Degree 1 and 2 by formula, higher degrees by subdivision.
#pragma once

#include <span>
#include <vector>

namespace curvescan::detail {

/// Appends to `roots` the roots in [0, 1] of the polynomial with Bernstein coefficients `coeffs` (its
/// degree is coeffs.size() - 1; a constant has none), and possibly a few just outside [0, 1] from the
/// formulas of degree 1 and 2, which callers filter. A cluster of roots closer than 2^-48 may be reported
/// as one point.
void bernstein_roots(std::span<const double> coeffs, std::vector<double>& roots);

}  // namespace curvescan::detail
