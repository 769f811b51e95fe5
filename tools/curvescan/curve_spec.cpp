#include "curve_spec.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/bspline.h"
#include "curvescan/curves/catmull_rom.h"
#include "curvescan/curves/cubic_spline.h"
#include "curvescan/curves/flatten.h"
#include "curvescan/curves/hermite.h"
#include "curvescan/curves/knot_vector.h"
#include "curvescan/curves/nurbs.h"
#include "curvescan/curves/rational_bezier.h"
#include "spec_reader.h"

namespace curvescan::cli {
namespace {

using Segments = std::vector<CurveSegment>;

Segments from_beziers(const std::vector<Bezier>& beziers) {
  Segments segments;
  segments.reserve(beziers.size());
  for (const Bezier& bezier : beziers) {
    segments.push_back({std::vector<Point>(bezier.points().begin(), bezier.points().end()), {}});
  }
  return segments;
}

Segments from_rationals(const std::vector<RationalBezier>& rationals) {
  Segments segments;
  segments.reserve(rationals.size());
  for (const RationalBezier& rational : rationals) {
    segments.push_back({std::vector<Point>(rational.points().begin(), rational.points().end()),
                        std::vector<double>(rational.weights().begin(), rational.weights().end())});
  }
  return segments;
}

Result<Segments> from_result(Result<std::vector<Bezier>> beziers) {
  if (!beziers) return beziers.error();
  return from_beziers(*beziers);
}

Status check_degree(int degree, std::size_t point_count, const CurveSpecLimits& limits) {
  if (degree < 1 || degree > limits.max_degree) {
    if (degree > limits.max_degree) {
      return Error{ErrorKind::kLimitExceeded, "'degree' " + std::to_string(degree) +
                                                  " is above the degree limit of " +
                                                  std::to_string(limits.max_degree) + " (raise --max-degree)"};
    }
    return Status::invalid("'degree' must be at least 1, not " + std::to_string(degree));
  }
  if (static_cast<std::size_t>(degree) >= point_count) {
    return Status::invalid("'degree' " + std::to_string(degree) + " needs at least " +
                           std::to_string(degree + 1) + " points, got " + std::to_string(point_count));
  }
  return {};
}

Result<Segments> bezier_spec(SpecReader& reader, const CurveSpecLimits& limits) {
  reader.only({"type", "points"});
  std::vector<Point> points = reader.points("points", static_cast<std::size_t>(limits.max_degree) + 1);
  if (reader.failed()) return reader.error();
  if (points.size() < 2) return Status::invalid("a Bezier needs at least 2 points").error();
  return Segments{{std::move(points), {}}};
}

Status check_weights(const std::vector<double>& weights, std::size_t point_count) {
  if (weights.size() != point_count) {
    return Status::invalid("'weights' has " + std::to_string(weights.size()) + " entries but there are " +
                           std::to_string(point_count) + " points");
  }
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (!(weights[i] > 0.0)) return Status::invalid("'weights'[" + std::to_string(i) + "] must be > 0");
  }
  return {};
}

Result<Segments> rational_spec(SpecReader& reader, const CurveSpecLimits& limits) {
  reader.only({"type", "points", "weights"});
  const std::size_t max_points = static_cast<std::size_t>(limits.max_degree) + 1;
  std::vector<Point> points = reader.points("points", max_points);
  std::vector<double> weights = reader.numbers("weights", max_points);
  if (reader.failed()) return reader.error();
  if (points.size() < 2) return Status::invalid("a rational Bezier needs at least 2 points").error();
  CURVESCAN_PROPAGATE(check_weights(weights, points.size()));
  return Segments{{std::move(points), std::move(weights)}};
}

Result<Segments> bspline_spec(SpecReader& reader, const CurveSpecLimits& limits) {
  reader.only({"type", "degree", "points", "knots", "closed"});
  const int degree = reader.integer("degree");
  std::vector<Point> points = reader.points("points", limits.max_points);
  const bool closed = reader.boolean("closed", false);
  std::vector<double> knots;
  if (reader.has("knots")) knots = reader.numbers("knots", limits.max_points + 1025);
  if (reader.failed()) return reader.error();
  CURVESCAN_PROPAGATE(check_degree(degree, points.size() + (closed ? degree : 0), limits));
  if (closed && reader.has("knots")) return Status::invalid("give either 'knots' or 'closed', not both").error();
  Result<BSpline> spline = closed           ? BSpline::closed(std::move(points), degree)
                           : knots.empty()  ? BSpline::clamped(std::move(points), degree)
                                            : BSpline::create(std::move(points), std::move(knots), degree);
  if (!spline) return spline.error();
  return from_beziers(spline->to_beziers());
}

Result<Segments> nurbs_spec(SpecReader& reader, const CurveSpecLimits& limits) {
  reader.only({"type", "degree", "points", "weights", "knots", "closed"});
  const int degree = reader.integer("degree");
  std::vector<Point> points = reader.points("points", limits.max_points);
  std::vector<double> weights = reader.numbers("weights", limits.max_points);
  const bool closed = reader.boolean("closed", false);
  std::vector<double> knots;
  if (reader.has("knots")) knots = reader.numbers("knots", limits.max_points + 1025);
  if (reader.failed()) return reader.error();
  CURVESCAN_PROPAGATE(check_weights(weights, points.size()));
  CURVESCAN_PROPAGATE(check_degree(degree, points.size() + (closed ? degree : 0), limits));
  if (closed && reader.has("knots")) return Status::invalid("give either 'knots' or 'closed', not both").error();
  if (closed) {
    // Periodic as for BSpline::closed: wrap the first `degree` points (and their weights) to the end.
    for (int i = 0; i < degree; ++i) {
      points.push_back(points[static_cast<std::size_t>(i)]);
      weights.push_back(weights[static_cast<std::size_t>(i)]);
    }
  }
  if (knots.empty()) {
    Result<std::vector<double>> made =
        closed ? periodic_knots(points.size(), degree) : clamped_knots(points.size(), degree);
    if (!made) return made.error();
    knots = std::move(*made);
  }
  Result<Nurbs> nurbs = Nurbs::create(std::move(points), std::move(weights), std::move(knots), degree);
  if (!nurbs) return nurbs.error();
  return from_rationals(nurbs->to_rational_beziers());
}

Result<Segments> hermite_spec(SpecReader& reader, const CurveSpecLimits& limits) {
  reader.only({"type", "points", "tangents", "parameters"});
  const std::vector<Point> points = reader.points("points", limits.max_points);
  const std::vector<Point> tangent_points = reader.points("tangents", limits.max_points);
  std::vector<double> parameters;
  if (reader.has("parameters")) parameters = reader.numbers("parameters", limits.max_points);
  if (reader.failed()) return reader.error();
  std::vector<Vec2> tangents;
  tangents.reserve(tangent_points.size());
  for (Point t : tangent_points) tangents.push_back(t.to_vec());
  return from_result(reader.has("parameters") ? hermite_spline(points, tangents, parameters)
                                              : hermite_spline(points, tangents));
}

Result<Segments> catmull_rom_spec(SpecReader& reader, const CurveSpecLimits& limits) {
  reader.only({"type", "points", "alpha", "closed"});
  const std::vector<Point> points = reader.points("points", limits.max_points);
  const double alpha = reader.number("alpha", 0.5);
  const bool closed = reader.boolean("closed", false);
  if (reader.failed()) return reader.error();
  return from_result(catmull_rom(points, alpha, closed));
}

Result<Segments> interpolate_spec(SpecReader& reader, const CurveSpecLimits& limits) {
  reader.only({"type", "points", "parameterization", "ends", "start_tangent", "end_tangent", "closed"});
  const std::vector<Point> points = reader.points("points", limits.max_points);
  const std::string parameterization = reader.string("parameterization", "chord");
  const std::string ends = reader.string("ends", "natural");
  const bool closed = reader.boolean("closed", false);
  if (reader.failed()) return reader.error();
  CubicSplineOptions options;
  if (parameterization == "uniform") {
    options.parameterization = SplineParameterization::kUniform;
  } else if (parameterization == "chord") {
    options.parameterization = SplineParameterization::kChordLength;
  } else {
    return Status::invalid("'parameterization' must be \"uniform\" or \"chord\", not \"" + parameterization +
                           "\"").error();
  }
  if (closed) {
    if (reader.has("ends")) return Status::invalid("a closed spline takes no 'ends'").error();
    options.ends = SplineEnds::kClosed;
  } else if (ends == "natural") {
    options.ends = SplineEnds::kNatural;
  } else if (ends == "clamped") {
    options.ends = SplineEnds::kClamped;
    options.start_tangent = reader.point("start_tangent").to_vec();
    options.end_tangent = reader.point("end_tangent").to_vec();
    if (reader.failed()) return reader.error();
  } else {
    return Status::invalid("'ends' must be \"natural\" or \"clamped\", not \"" + ends + "\"").error();
  }
  if (options.ends != SplineEnds::kClamped && (reader.has("start_tangent") || reader.has("end_tangent"))) {
    return Status::invalid("'start_tangent' and 'end_tangent' need \"ends\": \"clamped\"").error();
  }
  return from_result(cubic_spline(points, options));
}

}  // namespace

Result<std::vector<CurveSegment>> build_curve_segments(const nlohmann::json& spec, const CurveSpecLimits& limits) {
  if (!spec.is_object()) return Status::invalid("the spec must be a JSON object").error();
  SpecReader reader(spec);
  const std::string type = reader.string("type");
  if (reader.failed()) return reader.error();
  if (type == "bezier") return bezier_spec(reader, limits);
  if (type == "rational") return rational_spec(reader, limits);
  if (type == "bspline") return bspline_spec(reader, limits);
  if (type == "nurbs") return nurbs_spec(reader, limits);
  if (type == "hermite") return hermite_spec(reader, limits);
  if (type == "catmull-rom") return catmull_rom_spec(reader, limits);
  if (type == "interpolate") return interpolate_spec(reader, limits);
  return Status::invalid("unknown curve type \"" + type +
                         "\" (expected bezier, rational, bspline, nurbs, hermite, catmull-rom, interpolate, explicit, implicit or "
                         "bezier-patch)")
      .error();
}

namespace {

std::string short_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

Error budget_error(std::size_t max_segments) {
  return Error{ErrorKind::kLimitExceeded,
               "the polyline needs more than " + std::to_string(max_segments) +
                   " segments at this tolerance, the segment limit (raise --max-segments or --tolerance)"};
}

}  // namespace

Result<std::vector<Point>> flatten_curve_segments(const std::vector<CurveSegment>& segments, double tolerance,
                                                  std::size_t max_segments) {
  std::vector<Point> polyline;
  if (segments.empty()) return polyline;
  polyline.push_back(segments.front().points.front());
  for (const CurveSegment& segment : segments) {
    if (polyline.back() != segment.points.front()) polyline.push_back(segment.points.front());
    const std::size_t used = polyline.size() - 1;
    if (used >= max_segments) return budget_error(max_segments);
    // Below the resolution of its coordinates (control points near ±1e308 at the default tolerance) a piece
    // is accepted only by the flattener's one-segment test (it is within tolerance of its chord); any other
    // is walked at the resolution and reported kSegmentLimit, an error here. One segment decides which, at
    // once: the walk used to take up to 2^22 segments to reach the same error (0.47 s per such input in the
    // sanitized fuzz target). Otherwise the cap is what is left of the budget, so a curve far too fine for
    // the budget costs at most the budget.
    const double resolution = flatten_resolution(segment.points);
    const bool unresolvable = tolerance < resolution;
    const std::size_t cap = unresolvable ? 1 : std::min(max_segments - used, kMaxFlattenSegments);
    const FlattenOutcome outcome =
        segment.weights.empty() ? flatten_bezier(segment.points, tolerance, polyline, cap)
                                : flatten_rational(segment.points, segment.weights, tolerance, polyline, cap);
    if (outcome == FlattenOutcome::kNonFinite) {
      return Error{
          ErrorKind::kInvalidArgument,
          "the curve cannot be flattened: its control points are further apart than the largest double "
          "(about 1.8e308)"};
    }
    if (outcome == FlattenOutcome::kSegmentLimit) {
      // Raising the budget does not help a tolerance below the coordinates' resolution: say so first.
      if (unresolvable) {
        double largest = 0.0;
        for (const Point p : segment.points) largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
        return Error{ErrorKind::kLimitExceeded,
                     "the tolerance " + short_number(tolerance) +
                         " is finer than doubles resolve at coordinates up to " + short_number(largest) +
                         " (about " + short_number(resolution) +
                         "), so the curve cannot be flattened to it (raise --tolerance)"};
      }
      if (cap < kMaxFlattenSegments) return budget_error(max_segments);
      return Error{ErrorKind::kLimitExceeded,
                   "one piece needs more than " + std::to_string(kMaxFlattenSegments) +
                       " segments at this tolerance, the flattener's limit per curve (raise --tolerance)"};
    }
    if (polyline.size() - 1 > max_segments) return budget_error(max_segments);
    if (outcome != FlattenOutcome::kOk) {
      return Error{ErrorKind::kInvalidArgument, "the curve cannot be flattened (degenerate data)"};
    }
  }
  return polyline;
}

}  // namespace curvescan::cli
