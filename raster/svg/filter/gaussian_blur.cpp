// feGaussianBlur (gaussian_blur.h).
#include "gaussian_blur.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace curvescan::svg::detail::filter {
namespace {

// Blurring works on planes: one channel of the subregion, w x h floats, row by row. The vertical pass
// transposes the plane so that it too runs along contiguous memory.
struct Scratch {
  std::vector<float> line;     // one line's blurred values
  std::vector<double> prefix;  // n + 1 prefix sums of a line
};

// The index of sample `i` of a line of `n` under `mode`, or -1 for transparent black.
long long edge_index(long long i, long long n, EdgeMode mode) noexcept {
  if (i >= 0 && i < n) return i;
  switch (mode) {
    case EdgeMode::kNone:
      return -1;
    case EdgeMode::kDuplicate:
      return i < 0 ? 0 : n - 1;
    case EdgeMode::kWrap:
      return ((i % n) + n) % n;
  }
  return -1;
}

// Sum of samples [a, b] (inclusive, any integers) of a line under `mode`, from its prefix sums.
double window_sum(const std::vector<double>& prefix, const float* values, long long n, long long a,
                  long long b, EdgeMode mode) noexcept {
  const auto prefix_at = [&](long long k) { return prefix[static_cast<std::size_t>(k)]; };
  switch (mode) {
    case EdgeMode::kNone: {
      const long long lo = std::max(a, 0LL), hi = std::min(b, n - 1);
      return hi < lo ? 0.0 : prefix_at(hi + 1) - prefix_at(lo);
    }
    case EdgeMode::kDuplicate: {
      double sum = 0.0;
      if (a < 0) sum += static_cast<double>(std::min(b, -1LL) - a + 1) * values[0];
      if (b > n - 1) sum += static_cast<double>(b - std::max(a, n) + 1) * values[n - 1];
      const long long lo = std::max(a, 0LL), hi = std::min(b, n - 1);
      if (hi >= lo) sum += prefix_at(hi + 1) - prefix_at(lo);
      return sum;
    }
    case EdgeMode::kWrap: {
      // S(k): the sum of the periodic samples [0, k), for any integer k.
      const auto periodic = [&](long long k) {
        const long long periods = k >= 0 ? k / n : -((-k + n - 1) / n);
        return static_cast<double>(periods) * prefix_at(n) + prefix_at(k - periods * n);
      };
      return periodic(b + 1) - periodic(a);
    }
  }
  return 0.0;
}

// One box pass over a line, in place: v[i] = mean of v[i - left .. i + right].
void box_pass(float* values, long long n, long long left, long long right, EdgeMode mode, Scratch& scratch) {
  std::vector<double>& prefix = scratch.prefix;
  prefix[0] = 0.0;
  for (long long k = 0; k < n; ++k) {
    prefix[static_cast<std::size_t>(k + 1)] = prefix[static_cast<std::size_t>(k)] + values[k];
  }
  const double scale = 1.0 / static_cast<double>(left + right + 1);
  float* out = scratch.line.data();
  if (mode == EdgeMode::kNone) {
    // The common case, without a branch per sample: the window clamped to the line.
    for (long long i = 0; i < n; ++i) {
      const long long lo = std::clamp(i - left, 0LL, n), hi = std::clamp(i + right + 1, 0LL, n);
      out[i] = static_cast<float>(
          (prefix[static_cast<std::size_t>(hi)] - prefix[static_cast<std::size_t>(lo)]) * scale);
    }
  } else {
    for (long long i = 0; i < n; ++i) {
      out[i] = static_cast<float>(window_sum(prefix, values, n, i - left, i + right, mode) * scale);
    }
  }
  std::copy(out, out + n, values);
}

// The exact kernel for small σ: weights over [-radius, radius], summing to 1.
std::vector<double> gaussian_kernel(double sigma) {
  const int radius = static_cast<int>(std::ceil(3.0 * sigma));
  std::vector<double> weights(static_cast<std::size_t>(2 * radius + 1));
  double total = 0.0;
  for (int k = -radius; k <= radius; ++k) {
    const double w = std::exp(-(k * k) / (2.0 * sigma * sigma));
    weights[static_cast<std::size_t>(k + radius)] = w;
    total += w;
  }
  for (double& w : weights) w /= total;
  return weights;
}

// Blurs one line in place with σ in pixels.
void blur_line(float* values, long long n, double sigma, const std::vector<double>& kernel, EdgeMode mode,
               Scratch& scratch) {
  if (sigma < 2.0) {
    const long long radius = static_cast<long long>(kernel.size() / 2);
    float* out = scratch.line.data();
    for (long long i = 0; i < n; ++i) {
      double sum = 0.0;
      if (i >= radius && i + radius < n) {  // inside: no edge handling
        const float* centre = values + i;
        for (long long k = -radius; k <= radius; ++k)
          sum += kernel[static_cast<std::size_t>(k + radius)] * centre[k];
      } else {
        for (long long k = -radius; k <= radius; ++k) {
          const long long source = edge_index(i + k, n, mode);
          if (source >= 0) sum += kernel[static_cast<std::size_t>(k + radius)] * values[source];
        }
      }
      out[i] = static_cast<float>(sum);
    }
    std::copy(out, out + n, values);
    return;
  }
  // window_sum takes any window in constant time, however far it reaches past the line.
  const long long d = box_blur_size(sigma);
  if (d % 2 == 1) {
    const long long r = d / 2;
    for (int pass = 0; pass < 3; ++pass) box_pass(values, n, r, r, mode, scratch);
  } else {
    const long long h = d / 2;
    box_pass(values, n, h, h - 1, mode, scratch);  // centred between i - 1 and i
    box_pass(values, n, h - 1, h, mode, scratch);  // centred between i and i + 1
    box_pass(values, n, h, h, mode, scratch);      // size d + 1, centred
  }
}

// Blurs every row of a w x h plane.
void blur_rows(std::vector<float>& plane, int w, int h, double sigma, EdgeMode mode, Scratch& scratch) {
  const std::vector<double> kernel = sigma < 2.0 ? gaussian_kernel(sigma) : std::vector<double>{};
  for (int y = 0; y < h; ++y)
    blur_line(plane.data() + static_cast<std::size_t>(y) * w, w, sigma, kernel, mode, scratch);
}

// `plane` (w x h) transposed into `out` (h x w), in cache-sized blocks.
void transpose(const std::vector<float>& plane, int w, int h, std::vector<float>& out) {
  constexpr int kBlock = 32;
  out.resize(plane.size());
  for (int y0 = 0; y0 < h; y0 += kBlock)
    for (int x0 = 0; x0 < w; x0 += kBlock)
      for (int y = y0; y < std::min(h, y0 + kBlock); ++y)
        for (int x = x0; x < std::min(w, x0 + kBlock); ++x)
          out[static_cast<std::size_t>(x) * h + y] = plane[static_cast<std::size_t>(y) * w + x];
}

}  // namespace

long long box_blur_size(double sigma) noexcept {
  const double d = std::floor(sigma * 3.0 * std::sqrt(2.0 * std::numbers::pi) / 4.0 + 0.5);
  return d > 1e12 ? static_cast<long long>(1e12) : static_cast<long long>(d);
}

void gaussian_blur(const FilterImage& in, PixelRect subregion, double sigma_x, double sigma_y,
                   EdgeMode edge_mode, FilterImage& out) {
  const PixelRect r = subregion.intersect(in.bounds()).intersect(out.bounds());
  if (r.empty()) return;
  const int w = r.width(), h = r.height();
  const bool blur_x = sigma_x > 0.0, blur_y = sigma_y > 0.0;  // false for NaN
  // Colour channels that are zero over the whole subregion (SourceAlpha, a shadow's input) stay zero: only
  // the channels that hold something are blurred.
  bool active[4] = {false, false, false, true};
  for (int y = r.y0; y < r.y1; ++y) {
    const float* p = in.pixel(r.x0, y);
    for (int i = 0; i < w; ++i, p += 4) {
      active[0] = active[0] || p[0] != 0.0f;
      active[1] = active[1] || p[1] != 0.0f;
      active[2] = active[2] || p[2] != 0.0f;
    }
  }
  Scratch scratch;
  scratch.line.resize(static_cast<std::size_t>(std::max(w, h)));
  scratch.prefix.resize(static_cast<std::size_t>(std::max(w, h)) + 1);
  std::vector<float> plane(static_cast<std::size_t>(w) * h), transposed;
  for (int c = 0; c < 4; ++c) {
    if (!active[c]) {
      for (int y = r.y0; y < r.y1; ++y) {
        float* p = out.pixel(r.x0, y);
        for (int i = 0; i < w; ++i) p[4 * i + c] = 0.0f;
      }
      continue;
    }
    for (int y = 0; y < h; ++y) {
      const float* p = in.pixel(r.x0, r.y0 + y);
      float* row = plane.data() + static_cast<std::size_t>(y) * w;
      for (int i = 0; i < w; ++i) row[i] = p[4 * i + c];
    }
    if (blur_x) blur_rows(plane, w, h, sigma_x, edge_mode, scratch);
    if (blur_y) {
      transpose(plane, w, h, transposed);
      blur_rows(transposed, h, w, sigma_y, edge_mode, scratch);
      transpose(transposed, h, w, plane);
    }
    for (int y = 0; y < h; ++y) {
      float* p = out.pixel(r.x0, r.y0 + y);
      const float* row = plane.data() + static_cast<std::size_t>(y) * w;
      for (int i = 0; i < w; ++i) p[4 * i + c] = row[i];
    }
  }
}

}  // namespace curvescan::svg::detail::filter
