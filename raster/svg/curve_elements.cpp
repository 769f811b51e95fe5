// curvescan curve elements to Paths (curve_elements.h): every family converts exactly to (rational) Bézier
// pieces in curves/, which PathBuilder::append keeps exact.
#include "curve_elements.h"

#include <vector>

#include "curvescan/curves/bspline.h"
#include "curvescan/curves/catmull_rom.h"
#include "curvescan/curves/cubic_spline.h"
#include "curvescan/curves/hermite.h"
#include "curvescan/curves/nurbs.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/svg/number.h"

namespace curvescan::svg::detail {
namespace {

Error element_error(std::string_view element, const std::string& what) {
  return Error{ErrorKind::kInvalidArgument, "<" + std::string(element) + ">: " + what};
}

Result<std::vector<double>> numbers(std::string_view element, std::string_view attribute,
                                    std::string_view text) {
  const NumberList list = parse_number_list(text);
  if (!list.complete)
    return element_error(element, "attribute '" + std::string(attribute) + "' is not a number list");
  return list.values;
}

Result<std::vector<Point>> points(std::string_view element, std::string_view attribute,
                                  std::string_view text) {
  Result<std::vector<double>> values = numbers(element, attribute, text);
  if (!values) return values.error();
  if (values->size() % 2 != 0) {
    return element_error(element,
                         "attribute '" + std::string(attribute) + "' has an odd number of coordinates");
  }
  std::vector<Point> result;
  for (std::size_t i = 0; i < values->size(); i += 2) result.push_back({(*values)[i], (*values)[i + 1]});
  return result;
}

template <class Piece>
Result<Path> path_of(std::string_view element, const std::vector<Piece>& pieces, bool closed) {
  PathBuilder builder;
  for (const Piece& piece : pieces) builder.append(piece);
  if (closed) builder.close();
  Result<Path> path = builder.build();
  if (!path) return element_error(element, path.error().message);
  return path;
}

Result<int> degree_of(std::string_view element, std::string_view text, int fallback) {
  if (text.empty()) return fallback;
  const std::optional<double> value = parse_number(text);
  if (!value || *value != std::floor(*value) || *value < 1 || *value > 32) {
    return element_error(element, "degree '" + std::string(text) + "' is not an integer in 1..32");
  }
  return static_cast<int>(*value);
}

}  // namespace

Result<Path> curve_element_path(std::string_view name, const CurveAttributes& a) {
  Result<std::vector<Point>> control = points(name, "points", a.points);
  if (!control) return control.error();
  const bool closed = a.closed == "true" || a.closed == "1";
#define CURVESCAN_TRY_RESULT(variable, expr) \
  auto variable = (expr);                    \
  if (!variable) return element_error(name, variable.error().message)
  if (name == "bspline" || name == "nurbs") {
    CURVESCAN_TRY_RESULT(degree, degree_of(name, a.degree, name == "bspline" ? 3 : 2));
    if (name == "bspline") {
      Result<BSpline> spline = Error{};
      if (!a.knots.empty()) {
        CURVESCAN_TRY_RESULT(knots, numbers(name, "knots", a.knots));
        spline = BSpline::create(*control, *knots, *degree);
      } else {
        spline = closed ? BSpline::closed(*control, *degree) : BSpline::clamped(*control, *degree);
      }
      if (!spline) return element_error(name, spline.error().message);
      return path_of(name, spline->to_beziers(), closed);
    }
    CURVESCAN_TRY_RESULT(weights, numbers(name, "weights", a.weights));
    CURVESCAN_TRY_RESULT(knots, numbers(name, "knots", a.knots));
    CURVESCAN_TRY_RESULT(nurbs, Nurbs::create(*control, *weights, *knots, *degree));
    return path_of(name, nurbs->to_rational_beziers(), closed);
  }
  if (name == "catmull-rom") {
    double alpha = 0.5;  // centripetal: no cusps or self-intersections within a segment
    if (!a.alpha.empty()) {
      const std::optional<double> value = parse_number(a.alpha);
      if (!value) return element_error(name, "alpha '" + std::string(a.alpha) + "' is not a number");
      alpha = *value;
    }
    CURVESCAN_TRY_RESULT(pieces, catmull_rom(*control, alpha, closed));
    return path_of(name, *pieces, closed);
  }
  if (name == "hermite") {
    CURVESCAN_TRY_RESULT(tangent_points, points(name, "tangents", a.tangents));
    std::vector<Vec2> tangents;
    for (const Point& t : *tangent_points) tangents.push_back(t - Point{0, 0});
    CURVESCAN_TRY_RESULT(pieces, hermite_spline(*control, tangents));
    return path_of(name, *pieces, false);
  }
  if (name == "spline") {
    CubicSplineOptions options;
    if (a.ends == "closed")
      options.ends = SplineEnds::kClosed;
    else if (!a.ends.empty() && a.ends != "natural")
      return element_error(name, "ends must be natural or closed");
    if (a.parameterization == "uniform")
      options.parameterization = SplineParameterization::kUniform;
    else if (!a.parameterization.empty() && a.parameterization != "chord")
      return element_error(name, "parameterization must be chord or uniform");
    CURVESCAN_TRY_RESULT(pieces, cubic_spline(*control, options));
    return path_of(name, *pieces, options.ends == SplineEnds::kClosed);
  }
#undef CURVESCAN_TRY_RESULT
  return Error{ErrorKind::kUnsupported, "unknown curvescan element <" + std::string(name) + ">"};
}

}  // namespace curvescan::svg::detail
