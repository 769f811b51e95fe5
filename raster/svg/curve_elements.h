// curvescan's own elements: the curve families of curves/ drawn natively, in the namespace
// kCurvescanNamespace (docs/svg.md shows an example). Each becomes an exact Path of Bézier or rational
// Bézier pieces, then is filled and stroked like any SVG shape.
//
//   <cs:bspline points="x y ..." degree="3" [knots="..."] [closed="true"]/>   Gallivan, *Parametric Curves*, (B-splines)
//   <cs:nurbs points="..." weights="..." knots="..." degree="2"/>            Umetani, *Parametric Curve*, section 4
//   <cs:catmull-rom points="..." alpha="0.5" [closed="true"]/>               centripetal for alpha = 0.5
//   <cs:hermite points="..." tangents="..."/>                                 one tangent per point
//   <cs:spline points="..." [ends="natural|closed"] [parameterization="chord|uniform"]/>  C2 cubic
//   <cs:explicit f="sin(x)" x="x0 x1" [y="ymin ymax"] [tolerance="0.1"]/>    y = f(x), certified polylines
//   <cs:implicit f="x^2+y^2-1" box="xmin ymin xmax ymax" [tolerance]/>        f(x, y) = 0, certified polylines
//   <cs:patch points="48 numbers per patch" [matrix="12"] [eye target up focal scale centre] [iso="4 4"]/>
//                                         Bézier surface patches: iso-curves as exact (rational) cubics
//   (Ince after Elias, *Lecture 11: Curves*: explicit, implicit representations; Bézier surfaces)
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "curvescan/raster/path.h"
#include "curvescan/status.h"

namespace curvescan::svg::detail {

inline constexpr std::string_view kCurvescanNamespace = "urn:curvescan:curves";

/// Attribute lookup for the element being converted (empty when absent).
struct CurveAttributes {
  std::string_view points, degree, knots, weights, closed, alpha, tangents, ends, parameterization;
  // cs:explicit, cs:implicit
  std::string_view f, x, y, box, tolerance;
  // cs:patch
  std::string_view matrix, eye, target, up, focal, scale, centre, iso;
};

/// The Path of the curve element `local_name` ("bspline", ...). Fails with a message naming the element
/// and the problem; kUnsupported for an unknown name.
[[nodiscard]] Result<Path> curve_element_path(std::string_view local_name, const CurveAttributes& attributes);

/// The Path of cs:explicit, cs:implicit or cs:patch (curve_family_elements.cpp); kUnsupported for other
/// names. Notes for the user (where a graph is split, singular points) are appended to `notes`.
[[nodiscard]] Result<Path> curve_family_element_path(std::string_view local_name, const CurveAttributes& attributes,
                                                     std::vector<std::string>& notes);

}  // namespace curvescan::svg::detail
