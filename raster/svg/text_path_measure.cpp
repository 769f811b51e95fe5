// PathMeasure (text_path_measure.h).
#include "text_path_measure.h"

#include <algorithm>
#include <cmath>

#include "curvescan/curves/flatten.h"

namespace curvescan::svg::detail {

std::optional<PathMeasure> PathMeasure::measure(const Path& path, double tolerance, bool reverse) {
  // Each subpath as a polyline.
  std::vector<std::vector<Point>> pieces;
  bool all_closed = true;
  std::size_t subpaths = 0;
  std::size_t points = 0;
  for (const PathElement& element : path) {
    // A budget of vertices for the whole path: a hostile path of many huge curves is followed up to it.
    if (points >= kMaxPathMeasurePoints) break;
    if (element.verb == PathVerb::kMove) {
      pieces.push_back({element.start});
      ++subpaths;
      continue;
    }
    if (pieces.empty()) pieces.push_back({element.start});
    std::vector<Point>& polyline = pieces.back();
    if (element.verb == PathVerb::kClose) {
      polyline.push_back(element.end);
      continue;
    }
    const std::size_t before = polyline.size();
    const std::size_t budget = kMaxPathMeasurePoints - points;
    if (element.verb == PathVerb::kLine) {
      polyline.push_back(element.end);
    } else if (element.is_rational()) {
      (void)flatten_rational(element.points, element.weights, tolerance, polyline, budget);
    } else {
      (void)flatten_bezier(element.points, tolerance, polyline, budget);
    }
    points += polyline.size() - before;
  }
  // Closed when every subpath ends where it starts (a single closed contour is the usual case).
  for (const std::vector<Point>& polyline : pieces) {
    if (polyline.size() < 2 || !(polyline.front() == polyline.back())) all_closed = false;
  }
  if (reverse) {
    std::reverse(pieces.begin(), pieces.end());
    for (std::vector<Point>& polyline : pieces) std::reverse(polyline.begin(), polyline.end());
  }
  PathMeasure measure;
  measure.closed_ = all_closed && subpaths <= 1;
  for (const std::vector<Point>& polyline : pieces) {
    for (std::size_t i = 0; i < polyline.size(); ++i) {
      const bool first = i == 0;
      const double before = measure.lengths_.empty() ? 0.0 : measure.lengths_.back();
      const double step =
          first || measure.points_.empty() ? 0.0 : (polyline[i] - measure.points_.back()).length();
      measure.points_.push_back(polyline[i]);
      measure.lengths_.push_back(before + (std::isfinite(step) ? step : 0.0));
      measure.starts_piece_.push_back(first);
    }
  }
  if (measure.points_.size() < 2 || !(measure.length() > 0.0) || !std::isfinite(measure.length()))
    return std::nullopt;
  return measure;
}

std::size_t PathMeasure::segment_at(double distance) const noexcept {
  // The first segment whose end is at or past `distance` and that has a length (skipping the joints of moves
  // and zero-length segments, whose tangent is undefined).
  std::size_t end = static_cast<std::size_t>(std::lower_bound(lengths_.begin(), lengths_.end(), distance) -
                                             lengths_.begin());
  end = std::clamp<std::size_t>(end, 1, points_.size() - 1);
  while (end + 1 < points_.size() && (starts_piece_[end] || lengths_[end] - lengths_[end - 1] <= 0.0)) ++end;
  while (end > 1 && (starts_piece_[end] || lengths_[end] - lengths_[end - 1] <= 0.0)) --end;
  return end;
}

std::optional<Vec2> PathMeasure::direction(std::size_t end) const noexcept {
  if (end < 1 || end >= points_.size() || starts_piece_[end]) return std::nullopt;
  const Vec2 d = points_[end] - points_[end - 1];
  const double norm = d.length();
  if (!(norm > 0.0) || !std::isfinite(norm)) return std::nullopt;
  return d / norm;
}

PathMeasure::Sample PathMeasure::at(double distance) const noexcept {
  distance = std::clamp(distance, 0.0, length());
  const std::size_t end = segment_at(distance);
  const Point a = points_[end - 1], b = points_[end];
  const double segment = lengths_[end] - lengths_[end - 1];
  const Vec2 direction = b - a;
  const double t = segment > 0.0 ? std::clamp((distance - lengths_[end - 1]) / segment, 0.0, 1.0) : 0.0;
  const double norm = direction.length();
  const Vec2 tangent = norm > 0.0 ? direction / norm : Vec2{1.0, 0.0};
  return {a + direction * t, tangent};
}

PathMeasure::Sample PathMeasure::at_smooth(double distance) const noexcept {
  Sample sample = at(distance);
  const std::size_t end = segment_at(std::clamp(distance, 0.0, length()));
  const double segment = lengths_[end] - lengths_[end - 1];
  if (!(segment > 0.0)) return sample;
  const double t = std::clamp((std::clamp(distance, 0.0, length()) - lengths_[end - 1]) / segment, 0.0, 1.0);
  // The neighbour on the side of the segment's middle the point is on: weight 1/2 at the shared vertex,
  // 0 at the middle. The first and last segments, and those beside a move, keep their own tangent there.
  const std::optional<Vec2> neighbour = t < 0.5 ? direction(end - 1) : direction(end + 1);
  if (!neighbour) return sample;
  const double w = t < 0.5 ? 0.5 - t : t - 0.5;
  const Vec2 blended = sample.tangent * (1.0 - w) + *neighbour * w;
  const double norm = blended.length();
  if (norm > 1e-12) sample.tangent = blended / norm;
  return sample;
}

}  // namespace curvescan::svg::detail
