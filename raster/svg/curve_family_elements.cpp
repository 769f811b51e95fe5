// cs:explicit, cs:implicit and cs:patch (curve_elements.h): explicit and implicit curves become the
// certified polylines of curves/ (explicit_curve.h, implicit_curve.h), within `tolerance` user units of
// the curve; patches become their isoparametric curves projected exactly (bezier_patch.h,
// view_transform.h), cubic or rational cubic pieces. Each polyline or iso-curve is its own subpath;
// closed implicit components are closed subpaths.
#include <cmath>
#include <cstdio>
#include <optional>

#include "curve_elements.h"
#include "curvescan/curves/bezier_patch.h"
#include "curvescan/curves/explicit_curve.h"
#include "curvescan/curves/expression.h"
#include "curvescan/curves/implicit_curve.h"
#include "curvescan/curves/view_transform.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/svg/number.h"

namespace curvescan::svg::detail {
namespace {

// The work one element may ask for: quadtree cells or graph pieces examined (each costs a few evaluations
// of f), and iso-curves.
constexpr std::size_t kMaxElementPieces = std::size_t{1} << 20;
// ... and pieces times the terms of the expression: about a second for the longest expressions.
constexpr std::size_t kMaxElementWork = std::size_t{1} << 21;
constexpr std::size_t kMaxPatches = 4096;
constexpr int kMaxIsoCurves = 64;
constexpr double kDefaultTolerance = 0.1;

Error element_error(std::string_view element, const std::string& what,
                    ErrorKind kind = ErrorKind::kInvalidArgument) {
  return Error{kind, "<cs:" + std::string(element) + ">: " + what};
}

Result<std::vector<double>> numbers(std::string_view element, std::string_view attribute,
                                    std::string_view text, std::size_t count_multiple,
                                    std::size_t exact_count = 0) {
  const NumberList list = parse_number_list(text);
  if (!list.complete)
    return element_error(element, "attribute '" + std::string(attribute) + "' is not a number list");
  for (const double v : list.values) {
    if (!std::isfinite(v))
      return element_error(element, "attribute '" + std::string(attribute) + "' has a non-finite number");
  }
  if ((exact_count != 0 && list.values.size() != exact_count) || list.values.empty() ||
      list.values.size() % count_multiple != 0) {
    return element_error(element, "attribute '" + std::string(attribute) + "' needs " +
                                      (exact_count != 0 ? std::to_string(exact_count)
                                                        : "a multiple of " + std::to_string(count_multiple)) +
                                      " numbers");
  }
  return list.values;
}

Result<double> tolerance_of(std::string_view element, std::string_view text) {
  if (text.empty()) return kDefaultTolerance;
  const std::optional<double> value = parse_number(text);
  if (!value || !(*value >= 1e-6) || !(*value <= 1e6)) {
    return element_error(element, "tolerance '" + std::string(text) + "' is not a number from 1e-6 to 1e6");
  }
  return *value;
}

Result<Expression> expression_of(std::string_view element, std::string_view text,
                                 std::span<const ExpressionVariable> variables) {
  if (text.empty()) return element_error(element, "attribute 'f' is missing");
  Result<Expression> f = Expression::parse(text, variables);
  if (!f) return element_error(element, "f: " + f.error().message, f.error().kind);
  return f;
}

Result<Path> polylines_path(std::string_view element, const std::vector<std::vector<Point>>& polylines) {
  PathBuilder builder;
  for (const std::vector<Point>& line : polylines) {
    if (line.size() < 2) continue;
    const bool closed = line.size() > 2 && line.front() == line.back();
    builder.move_to(line.front());
    for (std::size_t i = 1; i + (closed ? 1 : 0) < line.size(); ++i) builder.line_to(line[i]);
    if (closed) builder.close();
  }
  Result<Path> path = builder.build();
  if (!path) return element_error(element, path.error().message);
  return path;
}

std::string short_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

Result<Path> explicit_path(const CurveAttributes& a, std::vector<std::string>& notes) {
  constexpr std::string_view kName = "explicit";
  constexpr ExpressionVariable kVariables[] = {ExpressionVariable::kX};
  Result<Expression> f = expression_of(kName, a.f, kVariables);
  if (!f) return f.error();
  Result<std::vector<double>> x = numbers(kName, "x", a.x, 2, 2);
  if (!x) return x.error();
  Result<double> tolerance = tolerance_of(kName, a.tolerance);
  if (!tolerance) return tolerance.error();
  ExplicitCurveOptions options;
  options.tolerance = *tolerance;
  options.max_pieces = kMaxElementPieces;
  options.max_work = kMaxElementWork;
  if (!a.y.empty()) {
    Result<std::vector<double>> y = numbers(kName, "y", a.y, 2, 2);
    if (!y) return y.error();
    options.y_min = (*y)[0];
    options.y_max = (*y)[1];
  }
  Result<ExplicitCurve> curve = flatten_explicit_curve(*f, (*x)[0], (*x)[1], options);
  if (!curve) return element_error(kName, curve.error().message, curve.error().kind);
  if (!curve->splits.empty()) {
    notes.push_back("<cs:explicit>: the graph of " + std::string(a.f) + " is split at " +
                    std::to_string(curve->splits.size()) +
                    " places (poles, jumps or where it is undefined), the " +
                    "first near x = " + short_number(curve->splits.front().first));
  }
  if (curve->clipped) {
    notes.push_back("<cs:explicit>: parts of the graph of " + std::string(a.f) + " outside y in [" +
                    short_number(options.y_min) + ", " + short_number(options.y_max) + "] are not drawn");
  }
  return polylines_path(kName, curve->polylines);
}

Result<Path> implicit_path(const CurveAttributes& a, std::vector<std::string>& notes) {
  constexpr std::string_view kName = "implicit";
  constexpr ExpressionVariable kVariables[] = {ExpressionVariable::kX, ExpressionVariable::kY};
  Result<Expression> f = expression_of(kName, a.f, kVariables);
  if (!f) return f.error();
  Result<std::vector<double>> box = numbers(kName, "box", a.box, 4, 4);
  if (!box) return box.error();
  Result<double> tolerance = tolerance_of(kName, a.tolerance);
  if (!tolerance) return tolerance.error();
  ImplicitCurveOptions options;
  options.tolerance = *tolerance;
  options.max_cells = kMaxElementPieces;
  options.max_work = kMaxElementWork;
  Result<ImplicitCurve> curve =
      contour_implicit_curve(*f, {(*box)[0], (*box)[1]}, {(*box)[2], (*box)[3]}, options);
  if (!curve) return element_error(kName, curve.error().message, curve.error().kind);
  for (const Point p : curve->singular_points) {
    notes.push_back("<cs:implicit>: " + std::string(a.f) + " = 0 has a singular point near (" +
                    short_number(p.x) + ", " + short_number(p.y) + ")");
  }
  if (curve->uncertified_cells > 0) {
    notes.push_back("<cs:implicit>: the topology of " + std::string(a.f) + " = 0 is not certified in " +
                    std::to_string(curve->uncertified_cells) + " small cells (drawn within the tolerance)");
  }
  return polylines_path(kName, curve->polylines);
}

Result<std::optional<Point3>> point3_of(std::string_view text, const char* attribute) {
  if (text.empty()) return std::optional<Point3>{};
  Result<std::vector<double>> v = numbers("patch", attribute, text, 3, 3);
  if (!v) return v.error();
  return std::optional<Point3>{Point3{(*v)[0], (*v)[1], (*v)[2]}};
}

Result<ViewTransform> view_of(const CurveAttributes& a) {
  constexpr std::string_view kName = "patch";
  const bool camera_given = !a.eye.empty() || !a.target.empty();
  if (!a.matrix.empty()) {
    if (camera_given)
      return element_error(kName, "give either 'matrix' or a camera ('eye', 'target'), not both");
    Result<std::vector<double>> m = numbers(kName, "matrix", a.matrix, 12, 12);
    if (!m) return m.error();
    ViewTransform view;
    for (std::size_t k = 0; k < 12; ++k) view.rows[k / 4][k % 4] = (*m)[k];
    return view;
  }
  if (!camera_given) return ViewTransform{};  // orthographic onto (x, y)
  Camera camera;
  Result<std::optional<Point3>> eye = point3_of(a.eye, "eye");
  Result<std::optional<Point3>> target = point3_of(a.target, "target");
  Result<std::optional<Point3>> up = point3_of(a.up, "up");
  if (!eye) return eye.error();
  if (!target) return target.error();
  if (!up) return up.error();
  if (!*eye || !*target) return element_error(kName, "a camera needs both 'eye' and 'target'");
  camera.eye = **eye;
  camera.target = **target;
  if (*up) camera.up = **up;
  if (!a.focal.empty() && !a.scale.empty()) return element_error(kName, "give 'focal' or 'scale', not both");
  if (!a.focal.empty()) {
    const std::optional<double> focal = parse_number(a.focal);
    if (!focal) return element_error(kName, "focal '" + std::string(a.focal) + "' is not a number");
    camera.focal = *focal;
  }
  if (!a.scale.empty()) {
    const std::optional<double> scale = parse_number(a.scale);
    if (!scale) return element_error(kName, "scale '" + std::string(a.scale) + "' is not a number");
    camera.scale = *scale;
  }
  if (!a.centre.empty()) {
    Result<std::vector<double>> centre = numbers(kName, "centre", a.centre, 2, 2);
    if (!centre) return centre.error();
    camera.centre = {(*centre)[0], (*centre)[1]};
  }
  Result<ViewTransform> view = ViewTransform::look_at(camera);
  if (!view) return element_error(kName, view.error().message);
  return view;
}

Result<Path> patch_path(const CurveAttributes& a) {
  constexpr std::string_view kName = "patch";
  Result<std::vector<double>> values = numbers(kName, "points", a.points, 48);
  if (!values) return values.error();
  const std::size_t patch_count = values->size() / 48;
  if (patch_count > kMaxPatches) {
    return element_error(kName, "more than " + std::to_string(kMaxPatches) + " patches",
                         ErrorKind::kLimitExceeded);
  }
  int iso_u = 4, iso_v = 4;
  if (!a.iso.empty()) {
    Result<std::vector<double>> iso = numbers(kName, "iso", a.iso, 2, 2);
    if (!iso) return iso.error();
    const double u = (*iso)[0], v = (*iso)[1];
    if (u != std::floor(u) || v != std::floor(v) || u < 0 || v < 0 || u > kMaxIsoCurves ||
        v > kMaxIsoCurves || u + v < 1) {
      return element_error(
          kName, "iso must be two integers from 0 to " + std::to_string(kMaxIsoCurves) + ", not both 0");
    }
    iso_u = static_cast<int>(u);
    iso_v = static_cast<int>(v);
  }
  Result<ViewTransform> view = view_of(a);
  if (!view) return view.error();
  auto parameter = [](int k, int n) { return n == 1 ? 0.5 : static_cast<double>(k) / (n - 1); };
  PathBuilder builder;
  for (std::size_t p = 0; p < patch_count; ++p) {
    BezierPatch patch;
    for (std::size_t k = 0; k < 16; ++k) {
      const double* c = values->data() + 48 * p + 3 * k;
      patch.points[k] = {c[0], c[1], c[2]};
    }
    for (int k = 0; k < iso_u + iso_v; ++k) {
      const std::array<Point3, 4> ctrl =
          k < iso_u ? patch.curve_at_u(parameter(k, iso_u)) : patch.curve_at_v(parameter(k - iso_u, iso_v));
      Result<ProjectedCubic> cubic = project_cubic(ctrl, *view);
      if (!cubic)
        return element_error(kName, "patch " + std::to_string(p + 1) + ": " + cubic.error().message);
      builder.move_to(cubic->points[0]);
      if (cubic->is_rational()) {
        builder.rational_bezier_to(std::span(cubic->points).subspan(1), cubic->weights);
      } else {
        builder.bezier_to(std::span(cubic->points).subspan(1));
      }
    }
  }
  Result<Path> path = builder.build();
  if (!path) return element_error(kName, path.error().message);
  return path;
}

}  // namespace

Result<Path> curve_family_element_path(std::string_view name, const CurveAttributes& attributes,
                                       std::vector<std::string>& notes) {
  if (name == "explicit") return explicit_path(attributes, notes);
  if (name == "implicit") return implicit_path(attributes, notes);
  if (name == "patch") return patch_path(attributes);
  return Error{ErrorKind::kUnsupported, "unknown curvescan element <" + std::string(name) + ">"};
}

}  // namespace curvescan::svg::detail
