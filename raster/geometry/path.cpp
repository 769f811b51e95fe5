// Path: iteration over its elements, tight bounds and affine transformation (contract in path.h).
#include "curvescan/raster/path.h"

#include <string>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/rational_bezier.h"
#include "path_verb_points.h"

namespace curvescan {

Path::Iterator::Iterator(const Path* path, std::size_t verb_index) noexcept
    : path_(path), verb_index_(verb_index) {
  load();
}

void Path::Iterator::load() noexcept {
  if (path_ == nullptr || verb_index_ >= path_->verbs_.size()) return;
  const PathVerb verb = path_->verbs_[verb_index_];
  const std::span<const Point> all_points = path_->points_;
  element_.verb = verb;
  element_.weights = {};
  if (verb == PathVerb::kClose) {
    element_.points = {};
    element_.start = all_points[point_index_ - 1];
    element_.end = all_points[contour_start_];
    return;
  }
  if (verb == PathVerb::kMove) {
    contour_start_ = point_index_;
    element_.points = all_points.subspan(point_index_, 1);
    element_.start = element_.end = all_points[point_index_];
    return;
  }
  const bool general = verb == PathVerb::kBezier || verb == PathVerb::kRationalBezier;
  const std::size_t count = general ? path_->degrees_[degree_index_] : detail::fixed_point_count(verb);
  // The segment's start is the previous point: the Guarantees put a kMove or a drawing verb before it.
  element_.points = all_points.subspan(point_index_ - 1, count + 1);
  if (verb == PathVerb::kConic || verb == PathVerb::kRationalBezier) {
    element_.weights = std::span<const double>(path_->weights_).subspan(weight_index_, count + 1);
  }
  element_.start = element_.points.front();
  element_.end = element_.points.back();
}

Path::Iterator& Path::Iterator::operator++() noexcept {
  const PathVerb verb = element_.verb;
  if (verb == PathVerb::kMove) {
    point_index_ += 1;
  } else if (verb != PathVerb::kClose) {
    point_index_ += element_.points.size() - 1;
    weight_index_ += element_.weights.size();
    if (verb == PathVerb::kBezier || verb == PathVerb::kRationalBezier) ++degree_index_;
  }
  ++verb_index_;
  load();
  return *this;
}

Rect Path::tight_bounds() const {
  if (empty()) return {};
  Rect box = Rect::from_point(points_.front());
  for (const PathElement& element : *this) {
    if (element.points.size() <= 2) {  // a move or a line: its points
      for (const Point p : element.points) box.include(p);
      continue;
    }
    std::vector<Point> points(element.points.begin(), element.points.end());
    const Rect curve_box =
        element.is_rational() ? RationalBezier(std::move(points), std::vector<double>(element.weights.begin(),
                                                                                      element.weights.end()))
                                    .bounding_box()
                              : Bezier(std::move(points)).bounding_box();
    box.include({curve_box.x0, curve_box.y0});
    box.include({curve_box.x1, curve_box.y1});
  }
  return box;
}

Result<Path> Path::transformed(const Affine& transform) const {
  if (!transform.is_finite()) {
    return Error{ErrorKind::kInvalidArgument, "cannot transform a path by a non-finite matrix"};
  }
  Path result = *this;
  for (std::size_t i = 0; i < result.points_.size(); ++i) {
    Point& p = result.points_[i];
    p = transform.apply(p);
    if (!p.is_finite()) {
      return Error{ErrorKind::kInvalidArgument,
                   "the transform maps path point " + std::to_string(i) + " outside the finite range"};
    }
    if (i == 0) {
      result.bounds_ = Rect::from_point(p);
    } else {
      result.bounds_.include(p);
    }
  }
  return result;
}

}  // namespace curvescan
