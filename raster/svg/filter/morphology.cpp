#include "morphology.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string_view>
#include <vector>

#include "primitive_numbers.h"

namespace curvescan::svg::detail::filter {

namespace {

/// dst[i] = min (or max) of src[j] for j in [i - r, i + r] clipped to [0, n), for strided float arrays.
/// A monotonic queue: each index enters and leaves it at most once, so the cost is O(n) whatever r is
/// (the running-extremum method of D. Lemire, "Streaming maximum-minimum filter using no more than three
/// comparisons per element", 2006). `queue` is scratch space of at least n ints.
void sliding_extreme(const float* src, std::ptrdiff_t src_stride, int n, int r, float* dst,
                     std::ptrdiff_t dst_stride, bool maximum, std::vector<int>& queue) {
  const auto at = [&](int i) { return src[i * src_stride]; };
  // `v` replaces the queue's back element when it is at least as extreme (later elements live longer).
  const auto dominates = [&](float v, float back) { return maximum ? v >= back : v <= back; };
  int head = 0, tail = 0, next = 0;
  for (int i = 0; i < n; ++i) {
    const int last = i + std::min(r, n - 1 - i);
    for (; next <= last; ++next) {
      const float v = at(next);
      while (tail > head && dominates(v, at(queue[static_cast<std::size_t>(tail - 1)]))) --tail;
      queue[static_cast<std::size_t>(tail++)] = next;
    }
    while (queue[static_cast<std::size_t>(head)] < i - r) ++head;
    dst[i * dst_stride] = at(queue[static_cast<std::size_t>(head)]);
  }
}

/// A radius in filter pixels, rounded to whole pixels and bounded by the image (a larger window is the
/// same window once clipped).
int pixel_radius(double pixels, int extent) noexcept {
  if (!(pixels > 0.0)) return 0;
  return static_cast<int>(std::lround(std::min(pixels, static_cast<double>(extent))));
}

}  // namespace

std::optional<MorphologyParams> read_morphology(const pugi::xml_node& primitive, std::string& /*error*/) {
  MorphologyParams params;
  params.op = std::string_view(primitive.attribute("operator").value()) == "dilate"
                  ? MorphologyOperator::kDilate
                  : MorphologyOperator::kErode;
  if (const auto radius = primitive_number_pair(primitive, "radius")) {
    params.radius_x = radius->x;
    params.radius_y = radius->y;
  }
  return params;
}

void render_morphology(const MorphologyParams& params, const FilterSpace& space, PixelRect subregion,
                       const FilterImage& in, FilterImage& out) {
  const PixelRect area = subregion.intersect(out.bounds()).intersect(in.bounds());
  if (area.empty()) return;
  const int width = area.width(), height = area.height();
  if (!(params.radius_x > 0.0) || !(params.radius_y > 0.0)) {
    for (int y = area.y0; y < area.y1; ++y)
      std::copy_n(in.pixel(area.x0, y), 4 * width, out.pixel(area.x0, y));
    return;
  }
  const int rx = pixel_radius(space.x_to_pixels(space.user_width(params.radius_x)), width);
  const int ry = pixel_radius(space.y_to_pixels(space.user_height(params.radius_y)), height);
  const bool maximum = params.op == MorphologyOperator::kDilate;

  // Pass 1, along rows, into a scratch image the size of the area; pass 2, along columns, into `out`.
  std::vector<float> rows(static_cast<std::size_t>(width) * height * 4);
  std::vector<int> queue(static_cast<std::size_t>(std::max(width, height)));
  for (int y = 0; y < height; ++y) {
    const float* src = in.pixel(area.x0, area.y0 + y);
    float* dst = rows.data() + static_cast<std::size_t>(y) * width * 4;
    for (int c = 0; c < 4; ++c) sliding_extreme(src + c, 4, width, rx, dst + c, 4, maximum, queue);
  }
  const std::ptrdiff_t out_stride = static_cast<std::ptrdiff_t>(out.width) * 4;
  for (int x = 0; x < width; ++x) {
    const float* src = rows.data() + static_cast<std::size_t>(x) * 4;
    float* dst = out.pixel(area.x0 + x, area.y0);
    for (int c = 0; c < 4; ++c)
      sliding_extreme(src + c, static_cast<std::ptrdiff_t>(width) * 4, height, ry, dst + c, out_stride,
                      maximum, queue);
  }
}

}  // namespace curvescan::svg::detail::filter
