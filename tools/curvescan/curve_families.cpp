#include "curve_families.h"

#include <cmath>
#include <cstdio>

#include "curvescan/curves/bezier_patch.h"
#include "curvescan/curves/explicit_curve.h"
#include "curvescan/curves/expression.h"
#include "curvescan/curves/implicit_curve.h"
#include "curvescan/curves/view_transform.h"
#include "spec_reader.h"

namespace curvescan::cli {
namespace {

constexpr ExpressionVariable kJustX[] = {ExpressionVariable::kX};
constexpr ExpressionVariable kXAndY[] = {ExpressionVariable::kX, ExpressionVariable::kY};
// Notes listing places (splits of an explicit graph) stop after this many, with a count of the rest.
constexpr std::size_t kMaxListedPlaces = 10;
constexpr int kMaxIsoCurves = 1000;

std::string short_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

Result<Expression> read_expression(SpecReader& reader, std::span<const ExpressionVariable> variables) {
  const std::string text = reader.string("f");
  if (reader.failed()) return reader.error();
  Result<Expression> expression = Expression::parse(text, variables);
  if (!expression) return Error{expression.error().kind, "'f': " + expression.error().message};
  return expression;
}

Result<FamilyCurve> explicit_curve(SpecReader& reader, double tolerance, std::size_t max_segments,
                                   std::size_t max_work) {
  reader.only({"type", "f", "x", "y"});
  Result<Expression> f = read_expression(reader, kJustX);
  if (!f) return f.error();
  const std::vector<double> x = reader.numbers("x", 2);
  std::vector<double> y;
  if (reader.has("y")) y = reader.numbers("y", 2);
  if (reader.failed()) return reader.error();
  if (x.size() != 2 || !(x[0] < x[1])) return Status::invalid("'x' must be [x0, x1] with x0 < x1").error();
  ExplicitCurveOptions options;
  options.tolerance = tolerance;
  options.max_pieces = max_segments;
  options.max_work = max_work;
  if (reader.has("y")) {
    if (y.size() != 2 || !(y[0] < y[1]))
      return Status::invalid("'y' must be [ymin, ymax] with ymin < ymax").error();
    options.y_min = y[0];
    options.y_max = y[1];
  }
  Result<ExplicitCurve> curve = flatten_explicit_curve(*f, x[0], x[1], options);
  if (!curve) {
    if (curve.error().kind == ErrorKind::kLimitExceeded) {
      return Error{ErrorKind::kLimitExceeded, curve.error().message + " (or raise --max-segments)"};
    }
    return curve.error();
  }
  FamilyCurve result;
  result.polylines = std::move(curve->polylines);
  for (std::size_t i = 0; i < curve->splits.size() && i < kMaxListedPlaces; ++i) {
    result.notes.push_back("the graph is split for x in [" + short_number(curve->splits[i].first) + ", " +
                           short_number(curve->splits[i].second) +
                           "]: a pole, a jump, or where f is undefined (no bound could be proven there)");
  }
  if (curve->splits.size() > kMaxListedPlaces) {
    result.notes.push_back("and " + std::to_string(curve->splits.size() - kMaxListedPlaces) + " more splits");
  }
  if (curve->clipped) {
    result.notes.push_back("parts of the graph outside y in [" + short_number(options.y_min) + ", " +
                           short_number(options.y_max) + "] are not drawn (set \"y\" to change the band)");
  }
  return result;
}

Result<FamilyCurve> implicit_curve(SpecReader& reader, double tolerance, std::size_t max_segments,
                                   std::size_t max_work) {
  reader.only({"type", "f", "box"});
  Result<Expression> f = read_expression(reader, kXAndY);
  if (!f) return f.error();
  const std::vector<Point> box = reader.points("box", 2);
  if (reader.failed()) return reader.error();
  if (box.size() != 2 || !(box[0].x < box[1].x) || !(box[0].y < box[1].y)) {
    return Status::invalid("'box' must be [[xmin, ymin], [xmax, ymax]] with xmin < xmax and ymin < ymax")
        .error();
  }
  ImplicitCurveOptions options;
  options.tolerance = tolerance;
  options.max_cells = max_segments;
  options.max_work = max_work;
  Result<ImplicitCurve> curve = contour_implicit_curve(*f, box[0], box[1], options);
  if (!curve) {
    if (curve.error().kind == ErrorKind::kLimitExceeded) {
      return Error{ErrorKind::kLimitExceeded, curve.error().message + " (or raise --max-segments)"};
    }
    return curve.error();
  }
  FamilyCurve result;
  result.polylines = std::move(curve->polylines);
  for (const Point p : curve->singular_points) {
    result.notes.push_back(
        "singular point near (" + short_number(p.x) + ", " + short_number(p.y) +
        "): the gradient of f may vanish there; the branches meeting there are joined at it");
  }
  if (curve->uncertified_cells > 0) {
    result.notes.push_back(
        std::to_string(curve->uncertified_cells) +
        " cells were contoured without a topology certificate (f undefined in part of them, "
        "or branches closer than the tolerance): the polylines are within the tolerance "
        "there but may join or split branches differently from the curve");
  }
  return result;
}

// [x, y, z] of finite numbers.
std::optional<Point3> point3(const nlohmann::json& value) {
  if (!value.is_array() || value.size() != 3) return std::nullopt;
  double c[3];
  for (int k = 0; k < 3; ++k) {
    if (!value[k].is_number()) return std::nullopt;
    c[k] = value[k].get<double>();
    if (!std::isfinite(c[k])) return std::nullopt;
  }
  return Point3{c[0], c[1], c[2]};
}

Result<std::vector<BezierPatch>> read_patches(const nlohmann::json& spec, const CurveSpecLimits& limits) {
  const auto patches = spec.find("patches");
  if (patches == spec.end() || !patches->is_array() || patches->empty()) {
    return Status::invalid("'patches' must be a non-empty list of patches").error();
  }
  if (patches->size() > limits.max_points / 16) {
    return Error{ErrorKind::kLimitExceeded, "'patches' lists more than " +
                                                std::to_string(limits.max_points / 16) +
                                                " patches (raise --max-points)"};
  }
  std::vector<Point3> vertices;
  const auto vertex_list = spec.find("vertices");
  if (vertex_list != spec.end()) {
    if (!vertex_list->is_array() || vertex_list->size() > limits.max_points) {
      return Status::invalid("'vertices' must be a list of at most " + std::to_string(limits.max_points) +
                             " [x, y, z] points")
          .error();
    }
    for (std::size_t k = 0; k < vertex_list->size(); ++k) {
      const std::optional<Point3> p = point3((*vertex_list)[k]);
      if (!p)
        return Status::invalid("'vertices'[" + std::to_string(k) + "] must be [x, y, z] of finite numbers")
            .error();
      vertices.push_back(*p);
    }
  }
  std::vector<BezierPatch> result;
  for (std::size_t n = 0; n < patches->size(); ++n) {
    const nlohmann::json& patch = (*patches)[n];
    const std::string where = "'patches'[" + std::to_string(n) + "]";
    if (!patch.is_array() || patch.size() != 16) {
      return Status::invalid(where + " must list 16 control points (4 rows of 4)").error();
    }
    BezierPatch bezier;
    for (std::size_t k = 0; k < 16; ++k) {
      if (vertex_list != spec.end()) {
        if (!patch[k].is_number_unsigned() || patch[k].get<std::size_t>() >= vertices.size()) {
          return Status::invalid(where + "[" + std::to_string(k) +
                                 "] must be an index into 'vertices' (0 to " +
                                 std::to_string(vertices.size() - 1) + ")")
              .error();
        }
        bezier.points[k] = vertices[patch[k].get<std::size_t>()];
      } else {
        const std::optional<Point3> p = point3(patch[k]);
        if (!p)
          return Status::invalid(where + "[" + std::to_string(k) + "] must be [x, y, z] of finite numbers")
              .error();
        bezier.points[k] = *p;
      }
    }
    result.push_back(bezier);
  }
  return result;
}

Result<ViewTransform> read_view(const nlohmann::json& spec) {
  const auto view = spec.find("view");
  if (view == spec.end()) return ViewTransform{};  // the default: orthographic onto (x, y)
  if (!view->is_object()) return Status::invalid("'view' must be an object").error();
  if (view->contains("matrix")) {
    const nlohmann::json& matrix = view->at("matrix");
    if (view->size() != 1)
      return Status::invalid("'view' takes either 'matrix' or a camera, not both").error();
    ViewTransform transform;
    if (!matrix.is_array() || matrix.size() != 3)
      return Status::invalid("'view'.'matrix' must be 3 rows of 4 numbers").error();
    for (std::size_t r = 0; r < 3; ++r) {
      if (!matrix[r].is_array() || matrix[r].size() != 4) {
        return Status::invalid("'view'.'matrix' must be 3 rows of 4 numbers").error();
      }
      for (std::size_t c = 0; c < 4; ++c) {
        if (!matrix[r][c].is_number() || !std::isfinite(matrix[r][c].get<double>())) {
          return Status::invalid("'view'.'matrix' must hold finite numbers").error();
        }
        transform.rows[r][c] = matrix[r][c].get<double>();
      }
    }
    return transform;
  }
  SpecReader reader(*view);
  reader.only({"eye", "target", "up", "focal", "scale", "centre"});
  if (reader.failed()) return Error{reader.error().kind, "'view': " + reader.error().message};
  Camera camera;
  const char* names[] = {"eye", "target", "up"};
  Point3* fields[] = {&camera.eye, &camera.target, &camera.up};
  for (int k = 0; k < 3; ++k) {
    if (!view->contains(names[k])) {
      if (k < 2)
        return Status::invalid(std::string("'view' needs '") + names[k] + "' (or a 'matrix')").error();
      continue;
    }
    const std::optional<Point3> p = point3(view->at(names[k]));
    if (!p)
      return Status::invalid(std::string("'view'.'") + names[k] + "' must be [x, y, z] of finite numbers")
          .error();
    *fields[k] = *p;
  }
  if (reader.has("focal") && reader.has("scale")) {
    return Status::invalid("'view' takes 'focal' (perspective) or 'scale' (orthographic), not both").error();
  }
  if (reader.has("focal")) camera.focal = reader.number("focal");
  if (reader.has("scale")) camera.scale = reader.number("scale");
  if (reader.has("centre")) camera.centre = reader.point("centre");
  if (reader.failed()) return Error{reader.error().kind, "'view': " + reader.error().message};
  Result<ViewTransform> transform = ViewTransform::look_at(camera);
  if (!transform) return Error{transform.error().kind, "'view': " + transform.error().message};
  return transform;
}

Result<FamilyCurve> patch_curve(SpecReader& reader, const nlohmann::json& spec, double tolerance,
                                std::size_t max_segments, const CurveSpecLimits& limits) {
  reader.only({"type", "patches", "vertices", "view", "iso"});
  int iso_u = 5, iso_v = 5;
  if (reader.has("iso")) {
    const std::vector<double> iso = reader.numbers("iso", 2);
    if (reader.failed()) return reader.error();
    if (iso.size() != 2 || iso[0] != std::floor(iso[0]) || iso[1] != std::floor(iso[1]) || iso[0] < 0 ||
        iso[1] < 0 || iso[0] > kMaxIsoCurves || iso[1] > kMaxIsoCurves || iso[0] + iso[1] < 1) {
      return Status::invalid("'iso' must be [curves along u, curves along v], integers from 0 to " +
                             std::to_string(kMaxIsoCurves) + ", not both 0")
          .error();
    }
    iso_u = static_cast<int>(iso[0]);
    iso_v = static_cast<int>(iso[1]);
  }
  if (reader.failed()) return reader.error();
  Result<std::vector<BezierPatch>> patches = read_patches(spec, limits);
  if (!patches) return patches.error();
  Result<ViewTransform> view = read_view(spec);
  if (!view) return view.error();
  const std::size_t curve_count = patches->size() * static_cast<std::size_t>(iso_u + iso_v);
  if (curve_count > limits.max_points) {
    return Error{ErrorKind::kLimitExceeded,
                 "the patches have " + std::to_string(curve_count) +
                     " iso-curves, more than --max-points allows (raise it or lower 'iso')"};
  }
  FamilyCurve result;
  // n iso-curves at parameters k / (n − 1): the patch boundaries and n − 2 between; one is the middle.
  auto parameter = [](int k, int n) { return n == 1 ? 0.5 : static_cast<double>(k) / (n - 1); };
  for (std::size_t p = 0; p < patches->size(); ++p) {
    for (int k = 0; k < iso_u + iso_v; ++k) {
      const bool along_v = k < iso_u;  // u fixed
      const std::array<Point3, 4> ctrl = along_v ? (*patches)[p].curve_at_u(parameter(k, iso_u))
                                                 : (*patches)[p].curve_at_v(parameter(k - iso_u, iso_v));
      Result<ProjectedCubic> cubic = project_cubic(ctrl, *view);
      if (!cubic)
        return Error{cubic.error().kind, "'patches'[" + std::to_string(p) + "]: " + cubic.error().message};
      CurveSegment segment{{cubic->points.begin(), cubic->points.end()}, {}};
      if (cubic->is_rational()) segment.weights.assign(cubic->weights.begin(), cubic->weights.end());
      result.segments.push_back(std::move(segment));
    }
  }
  std::size_t used = 0;
  for (const CurveSegment& segment : result.segments) {
    if (used >= max_segments) {
      return Error{ErrorKind::kLimitExceeded,
                   "the iso-curves need more than " + std::to_string(max_segments) +
                       " segments at this tolerance (raise --max-segments or --tolerance)"};
    }
    Result<std::vector<Point>> polyline = flatten_curve_segments({segment}, tolerance, max_segments - used);
    if (!polyline) return polyline.error();
    used += polyline->size() - 1;
    result.polylines.push_back(std::move(*polyline));
  }
  return result;
}

}  // namespace

bool is_family_type(std::string_view type) {
  return type == "explicit" || type == "implicit" || type == "bezier-patch";
}

Result<FamilyCurve> build_family_curve(const nlohmann::json& spec, double tolerance, std::size_t max_segments,
                                       const CurveSpecLimits& limits) {
  if (!spec.is_object()) return Status::invalid("the spec must be a JSON object").error();
  SpecReader reader(spec);
  const std::string type = reader.string("type");
  if (reader.failed()) return reader.error();
  if (type == "explicit") return explicit_curve(reader, tolerance, max_segments, limits.max_work);
  if (type == "implicit") return implicit_curve(reader, tolerance, max_segments, limits.max_work);
  if (type == "bezier-patch") return patch_curve(reader, spec, tolerance, max_segments, limits);
  return Status::invalid("not a curve family of this kind: \"" + type + "\"").error();
}

}  // namespace curvescan::cli
