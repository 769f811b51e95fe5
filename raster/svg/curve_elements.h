// curvescan's own elements: the curve families of curves/ drawn natively, in the namespace
// kCurvescanNamespace (docs/svg.md shows an example). Each becomes an exact Path of Bézier or rational
// Bézier pieces, then is filled and stroked like any SVG shape.
//
//   <cs:bspline points="x y ..." degree="3" [knots="..."] [closed="true"]/>   Gallivan, *Parametric Curves*, (B-splines)
//   <cs:nurbs points="..." weights="..." knots="..." degree="2"/>            Umetani, *Parametric Curve*, section 4
//   <cs:catmull-rom points="..." alpha="0.5" [closed="true"]/>               centripetal for alpha = 0.5
//   <cs:hermite points="..." tangents="..."/>                                 one tangent per point
//   <cs:spline points="..." [ends="natural|closed"] [parameterization="chord|uniform"]/>  C2 cubic
#pragma once

#include <string>
#include <string_view>

#include "curvescan/raster/path.h"
#include "curvescan/status.h"

namespace curvescan::svg::detail {

inline constexpr std::string_view kCurvescanNamespace = "urn:curvescan:curves";

/// Attribute lookup for the element being converted (empty when absent).
struct CurveAttributes {
  std::string_view points, degree, knots, weights, closed, alpha, tangents, ends, parameterization;
};

/// The Path of the curve element `local_name` ("bspline", ...). Fails with a message naming the element
/// and the problem; kUnsupported for an unknown name.
[[nodiscard]] Result<Path> curve_element_path(std::string_view local_name, const CurveAttributes& attributes);

}  // namespace curvescan::svg::detail
