// PathBuilder: validation of user commands and the contour bookkeeping that gives Path its Guarantees
// (path.h, path_builder.h). Arcs live in svg_arc.cpp and path_arc.cpp.
#include "curvescan/raster/path_builder.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "curvescan/raster/limits.h"

namespace curvescan {
namespace {

std::string format_point(Point p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g)", p.x, p.y);
  return text;
}

}  // namespace

bool PathBuilder::begin_command() {
  ++command_count_;
  return !error_.has_value();
}

void PathBuilder::fail(const char* command, ErrorKind kind, const std::string& what) {
  if (error_) return;
  error_ = Error{kind, "path command " + std::to_string(command_count_ - 1) + " (" + command + "): " + what};
}

bool PathBuilder::check_points(const char* command, std::span<const Point> points) {
  for (const Point p : points) {
    if (!p.is_finite()) {
      fail(command, ErrorKind::kInvalidArgument, "the coordinates are not finite " + format_point(p));
      return false;
    }
  }
  return true;
}

bool PathBuilder::check_weights(const char* command, std::span<const double> weights) {
  for (const double w : weights) {
    if (!(std::isfinite(w) && w > 0.0)) {
      char text[64];
      std::snprintf(text, sizeof text, "%g", w);
      fail(command, ErrorKind::kInvalidArgument,
           std::string("weight ") + text + " is invalid: weights must be finite and > 0");
      return false;
    }
  }
  return true;
}

bool PathBuilder::check_degree(const char* command, std::size_t degree) {
  if (degree == 0) {
    fail(command, ErrorKind::kInvalidArgument, "a curve needs at least one point after its start");
    return false;
  }
  if (degree > static_cast<std::size_t>(kMaxPathCurveDegree)) {
    fail(command, ErrorKind::kLimitExceeded,
         "degree " + std::to_string(degree) + " exceeds the limit of " + std::to_string(kMaxPathCurveDegree));
    return false;
  }
  return true;
}

bool PathBuilder::ensure_contour(const char* command) {
  if (pending_move_) {
    path_.verbs_.push_back(PathVerb::kMove);
    path_.points_.push_back(*pending_move_);
    if (path_.verbs_.size() == 1) {
      path_.bounds_ = Rect::from_point(*pending_move_);
    } else {
      path_.bounds_.include(*pending_move_);
    }
    contour_start_ = *pending_move_;
    pending_move_.reset();
    contour_drawn_ = false;
    return true;
  }
  if (!current_) {
    fail(command, ErrorKind::kInvalidArgument, "there is no current point: start the path with move_to");
    return false;
  }
  return true;
}

void PathBuilder::push_segment(PathVerb verb, std::span<const Point> points,
                               std::span<const double> weights) {
  path_.verbs_.push_back(verb);
  for (const Point p : points) {
    path_.points_.push_back(p);
    path_.bounds_.include(p);
  }
  path_.weights_.insert(path_.weights_.end(), weights.begin(), weights.end());
  if (verb == PathVerb::kBezier || verb == PathVerb::kRationalBezier) {
    path_.degrees_.push_back(static_cast<std::uint16_t>(points.size()));
  }
  current_ = points.back();
  contour_drawn_ = true;
}

PathBuilder& PathBuilder::move_to(Point p) {
  if (!begin_command() || !check_points("move_to", {&p, 1})) return *this;
  pending_move_ = p;
  current_ = p;
  return *this;
}

PathBuilder& PathBuilder::line_to(Point p) {
  if (!begin_command() || !check_points("line_to", {&p, 1}) || !ensure_contour("line_to")) return *this;
  push_segment(PathVerb::kLine, {&p, 1}, {});
  return *this;
}

PathBuilder& PathBuilder::quad_to(Point c, Point p) {
  const Point points[] = {c, p};
  if (!begin_command() || !check_points("quad_to", points) || !ensure_contour("quad_to")) return *this;
  push_segment(PathVerb::kQuad, points, {});
  return *this;
}

PathBuilder& PathBuilder::cubic_to(Point c1, Point c2, Point p) {
  const Point points[] = {c1, c2, p};
  if (!begin_command() || !check_points("cubic_to", points) || !ensure_contour("cubic_to")) return *this;
  push_segment(PathVerb::kCubic, points, {});
  return *this;
}

PathBuilder& PathBuilder::conic_to(Point c, Point p, double weight) {
  const Point points[] = {c, p};
  const double weights[] = {1.0, weight, 1.0};
  if (!begin_command() || !check_points("conic_to", points) || !check_weights("conic_to", weights) ||
      !ensure_contour("conic_to")) {
    return *this;
  }
  push_segment(PathVerb::kConic, points, weights);
  return *this;
}

PathBuilder& PathBuilder::bezier_to(std::span<const Point> points) {
  if (!begin_command() || !check_degree("bezier_to", points.size()) || !check_points("bezier_to", points) ||
      !ensure_contour("bezier_to")) {
    return *this;
  }
  push_segment(PathVerb::kBezier, points, {});
  return *this;
}

PathBuilder& PathBuilder::rational_bezier_to(std::span<const Point> points, std::span<const double> weights) {
  constexpr const char* kName = "rational_bezier_to";
  if (!begin_command() || !check_degree(kName, points.size())) return *this;
  if (weights.size() != points.size() + 1) {
    fail(kName, ErrorKind::kInvalidArgument,
         std::to_string(weights.size()) + " weights given for " + std::to_string(points.size() + 1) +
             " control points (the current point has a weight too)");
    return *this;
  }
  if (!check_points(kName, points) || !check_weights(kName, weights) || !ensure_contour(kName)) return *this;
  push_segment(PathVerb::kRationalBezier, points, weights);
  return *this;
}

PathBuilder& PathBuilder::append(const Bezier& curve) {
  constexpr const char* kName = "append(Bezier)";
  const std::span<const Point> points = curve.points();
  if (!begin_command() || !check_degree(kName, points.empty() ? 0 : points.size() - 1) ||
      !check_points(kName, points)) {
    return *this;
  }
  // Continue the contour only from exactly the curve's start; anything else starts a new contour there.
  if (current_ != points.front()) {
    pending_move_ = points.front();
    current_ = points.front();
  }
  if (ensure_contour(kName)) push_segment(PathVerb::kBezier, points.subspan(1), {});
  return *this;
}

PathBuilder& PathBuilder::append(const RationalBezier& curve) {
  constexpr const char* kName = "append(RationalBezier)";
  const std::span<const Point> points = curve.points();
  if (!begin_command() || !check_degree(kName, points.empty() ? 0 : points.size() - 1)) return *this;
  if (curve.weights().size() != points.size()) {
    fail(
        kName, ErrorKind::kInvalidArgument,
        std::to_string(curve.weights().size()) + " weights for " + std::to_string(points.size()) + " points");
    return *this;
  }
  if (!check_points(kName, points) || !check_weights(kName, curve.weights())) return *this;
  if (current_ != points.front()) {
    pending_move_ = points.front();
    current_ = points.front();
  }
  if (ensure_contour(kName)) push_segment(PathVerb::kRationalBezier, points.subspan(1), curve.weights());
  return *this;
}

PathBuilder& PathBuilder::close() {
  if (!begin_command()) return *this;
  if (pending_move_ || !contour_drawn_) return *this;
  path_.verbs_.push_back(PathVerb::kClose);
  contour_drawn_ = false;
  current_ = contour_start_;
  pending_move_ = contour_start_;  // SVG 8.3.3: the next command starts from the closed contour's start
  return *this;
}

PathBuilder& PathBuilder::polygon(std::span<const Point> points) {
  if (!begin_command() || points.empty() || !check_points("polygon", points)) return *this;
  pending_move_ = points.front();
  current_ = points.front();
  if (points.size() == 1 || !ensure_contour("polygon")) return *this;
  const std::span<const Point> rest = points.subspan(1);
  path_.verbs_.insert(path_.verbs_.end(), rest.size(), PathVerb::kLine);
  path_.points_.insert(path_.points_.end(), rest.begin(), rest.end());
  for (const Point p : rest) path_.bounds_.include(p);
  // close(): the contour is drawn, so it gets its closing verb and the next command starts at its start.
  path_.verbs_.push_back(PathVerb::kClose);
  contour_drawn_ = false;
  current_ = contour_start_;
  pending_move_ = contour_start_;
  return *this;
}

std::optional<Point> PathBuilder::current_point() const noexcept {
  return current_;
}

Result<Path> PathBuilder::build() const& {
  if (error_) return *error_;
  return path_;
}

Result<Path> PathBuilder::build() && {
  if (error_) return *error_;
  return std::move(path_);
}

}  // namespace curvescan
