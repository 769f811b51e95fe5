#include "morphology.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string_view>
#include <vector>

#include "primitive_numbers.h"

namespace curvescan::svg::detail::filter {

namespace {

/// dst[i] for the positions i in [d0, d1) = min (or max) of src[j] for j in [i - r, i + r] clipped to
/// [s0, s1), the positions where the source exists; 0 (transparent) where that window is empty. `src`
/// points at position s0 and `dst` at position d0, both strided.
/// A monotonic queue: each index enters and leaves it at most once, so the cost is O(n) whatever r is
/// (the running-extremum method of D. Lemire, "Streaming maximum-minimum filter using no more than three
/// comparisons per element", 2006). `queue` is scratch space of at least s1 - s0 ints.
void sliding_extreme(const float* src, std::ptrdiff_t src_stride, int s0, int s1, float* dst,
                     std::ptrdiff_t dst_stride, int d0, int d1, int r, bool maximum,
                     std::vector<int>& queue) {
  const auto at = [&](int j) { return src[static_cast<std::ptrdiff_t>(j - s0) * src_stride]; };
  // `v` replaces the queue's back element when it is at least as extreme (later elements live longer).
  const auto dominates = [&](float v, float back) { return maximum ? v >= back : v <= back; };
  int head = 0, tail = 0;
  int next = static_cast<int>(std::max<long long>(s0, static_cast<long long>(d0) - r));
  for (int i = d0; i < d1; ++i) {
    const int last = static_cast<int>(std::min<long long>(static_cast<long long>(i) + r, s1 - 1));
    for (; next <= last; ++next) {
      const float v = at(next);
      while (tail > head && dominates(v, at(queue[static_cast<std::size_t>(tail - 1)]))) --tail;
      queue[static_cast<std::size_t>(tail++)] = next;
    }
    while (head < tail && queue[static_cast<std::size_t>(head)] < static_cast<long long>(i) - r) ++head;
    dst[static_cast<std::ptrdiff_t>(i - d0) * dst_stride] =
        head < tail ? at(queue[static_cast<std::size_t>(head)]) : 0.0f;
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

bool morphology_is_identity(const MorphologyParams& params) noexcept {
  // `!(r >= 0)` is also true for NaN.
  return !(params.radius_x >= 0.0) || !(params.radius_y >= 0.0) ||
         (params.radius_x == 0.0 && params.radius_y == 0.0);
}

PixelRect render_morphology(const MorphologyParams& params, const FilterSpace& space, PixelRect subregion,
                            const FilterImage& in, FilterImage& out, std::optional<PixelRect> input_area,
                            std::optional<PixelRect> needed) {
  PixelRect area = subregion.intersect(out.bounds()).intersect(in.bounds());
  if (needed) area = area.intersect(*needed);
  if (area.empty()) return {};
  if (morphology_is_identity(params)) {
    for (int y = area.y0; y < area.y1; ++y)
      std::copy_n(in.pixel(area.x0, y), 4 * area.width(), out.pixel(area.x0, y));
    return area;
  }
  const int rx = pixel_radius(space.x_to_pixels(space.user_width(params.radius_x)), in.width);
  const int ry = pixel_radius(space.y_to_pixels(space.user_height(params.radius_y)), in.height);
  const bool maximum = params.op == MorphologyOperator::kDilate;
  // Outside the input's ink every pixel is transparent (FilterImage::extent). A pixel farther than the
  // radius from the ink has a window of transparent pixels, or none: it stays transparent. The windows
  // need not read all those zeros: a dilation's maximum ignores them (channels are >= 0), and for an
  // erosion one ring of them around the ink stands for all -- a window (a rectangle) that reaches from the
  // ink to a zero pixel holds a pixel of that ring too. So the reads stop at the ink (dilate) or one pixel
  // beyond it (erode), and a huge radius over a huge region costs the ink and the needed pixels.
  const PixelRect ink = in.extent.intersect(in.bounds());
  area = area.intersect(ink.grown(rx, ry));
  if (area.empty()) return {};
  const PixelRect source = input_area.value_or(subregion).intersect(maximum ? ink : ink.grown(1, 1));
  // The pixels the windows of `area` can reach where the input exists.
  const PixelRect read = source.intersect(in.bounds()).intersect(area.grown(rx, ry));
  if (read.empty()) return {};  // every window is empty: the result stays transparent

  // Pass 1, along rows: for each row of `read`, the extreme at area's columns, into a scratch image of
  // read.height() rows by area.width(); pass 2, along columns, into `out`.
  const int width = area.width();
  std::vector<float> rows(static_cast<std::size_t>(width) * read.height() * 4);
  std::vector<int> queue(static_cast<std::size_t>(std::max(read.width(), read.height())));
  for (int y = read.y0; y < read.y1; ++y) {
    const float* src = in.pixel(read.x0, y);
    float* dst = rows.data() + static_cast<std::size_t>(y - read.y0) * width * 4;
    for (int c = 0; c < 4; ++c)
      sliding_extreme(src + c, 4, read.x0, read.x1, dst + c, 4, area.x0, area.x1, rx, maximum, queue);
  }
  const std::ptrdiff_t out_stride = static_cast<std::ptrdiff_t>(out.width) * 4;
  for (int x = 0; x < width; ++x) {
    const float* src = rows.data() + static_cast<std::size_t>(x) * 4;
    float* dst = out.pixel(area.x0 + x, area.y0);
    for (int c = 0; c < 4; ++c)
      sliding_extreme(src + c, static_cast<std::ptrdiff_t>(width) * 4, read.y0, read.y1, dst + c, out_stride,
                      area.y0, area.y1, ry, maximum, queue);
  }
  return area;
}

}  // namespace curvescan::svg::detail::filter
