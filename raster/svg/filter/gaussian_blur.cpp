// feGaussianBlur (gaussian_blur.h).
#include "gaussian_blur.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace curvescan::svg::detail::filter {
namespace {

// One line of pixels (4 channels each) being blurred, with scratch space reused between lines.
struct Line {
  std::vector<float> values;   // 4 * n
  std::vector<float> scratch;  // 4 * n
  std::vector<double> prefix;  // 4 * (n + 1): prefix[4 * k + c] = sum of values[0 .. k-1] of channel c
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

// Sum of samples [a, b] (inclusive, any integers) of channel c under `mode`, from prefix sums.
double window_sum(const std::vector<double>& prefix, const float* values, long long n, long long a,
                  long long b, int c, EdgeMode mode) noexcept {
  const auto prefix_at = [&](long long k) { return prefix[static_cast<std::size_t>(4 * k + c)]; };
  switch (mode) {
    case EdgeMode::kNone: {
      const long long lo = std::max(a, 0LL), hi = std::min(b, n - 1);
      return hi < lo ? 0.0 : prefix_at(hi + 1) - prefix_at(lo);
    }
    case EdgeMode::kDuplicate: {
      double sum = 0.0;
      if (a < 0) sum += static_cast<double>(std::min(b, -1LL) - a + 1) * values[c];
      if (b > n - 1) sum += static_cast<double>(b - std::max(a, n) + 1) * values[4 * (n - 1) + c];
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

// One box pass over a line: out[i] = mean of in[i - left .. i + right].
void box_pass(const float* in, float* out, long long n, long long left, long long right, EdgeMode mode,
              std::vector<double>& prefix) {
  for (int c = 0; c < 4; ++c) prefix[static_cast<std::size_t>(c)] = 0.0;
  for (long long k = 0; k < n; ++k) {
    for (int c = 0; c < 4; ++c) {
      prefix[static_cast<std::size_t>(4 * (k + 1) + c)] =
          prefix[static_cast<std::size_t>(4 * k + c)] + in[4 * k + c];
    }
  }
  const double size = static_cast<double>(left + right + 1);
  for (long long i = 0; i < n; ++i) {
    for (int c = 0; c < 4; ++c) {
      out[4 * i + c] = static_cast<float>(window_sum(prefix, in, n, i - left, i + right, c, mode) / size);
    }
  }
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

// Blurs one line in place (line.values) with σ in pixels.
void blur_line(Line& line, long long n, double sigma, EdgeMode mode) {
  float* values = line.values.data();
  float* scratch = line.scratch.data();
  if (sigma < 2.0) {
    const std::vector<double> kernel = gaussian_kernel(sigma);
    const long long radius = static_cast<long long>(kernel.size() / 2);
    for (long long i = 0; i < n; ++i) {
      double sum[4] = {0.0, 0.0, 0.0, 0.0};
      for (long long k = -radius; k <= radius; ++k) {
        const long long source = edge_index(i + k, n, mode);
        if (source < 0) continue;
        const double w = kernel[static_cast<std::size_t>(k + radius)];
        for (int c = 0; c < 4; ++c) sum[c] += w * values[4 * source + c];
      }
      for (int c = 0; c < 4; ++c) scratch[4 * i + c] = static_cast<float>(sum[c]);
    }
    std::copy(scratch, scratch + 4 * n, values);
    return;
  }
  // window_sum takes any window in constant time, however far it reaches past the line.
  const long long d = box_blur_size(sigma);
  if (d % 2 == 1) {
    const long long r = d / 2;
    box_pass(values, scratch, n, r, r, mode, line.prefix);
    box_pass(scratch, values, n, r, r, mode, line.prefix);
    box_pass(values, scratch, n, r, r, mode, line.prefix);
  } else {
    const long long h = d / 2;
    box_pass(values, scratch, n, h, h - 1, mode, line.prefix);  // centred between i - 1 and i
    box_pass(scratch, values, n, h - 1, h, mode, line.prefix);  // centred between i and i + 1
    box_pass(values, scratch, n, h, h, mode, line.prefix);      // size d + 1, centred
  }
  std::copy(scratch, scratch + 4 * n, values);
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
  for (int y = r.y0; y < r.y1; ++y)
    std::copy(in.pixel(r.x0, y), in.pixel(r.x0, y) + 4 * w, out.pixel(r.x0, y));
  const bool blur_x = sigma_x > 0.0, blur_y = sigma_y > 0.0;  // false for NaN
  Line line;
  const int longest = std::max(w, h);
  line.values.resize(static_cast<std::size_t>(4 * longest));
  line.scratch.resize(static_cast<std::size_t>(4 * longest));
  line.prefix.resize(static_cast<std::size_t>(4 * (longest + 1)));
  if (blur_x) {
    for (int y = r.y0; y < r.y1; ++y) {
      float* row = out.pixel(r.x0, y);
      std::copy(row, row + 4 * w, line.values.begin());
      blur_line(line, w, sigma_x, edge_mode);
      std::copy(line.values.begin(), line.values.begin() + 4 * w, row);
    }
  }
  if (blur_y) {
    for (int x = r.x0; x < r.x1; ++x) {
      for (int y = 0; y < h; ++y)
        std::copy(out.pixel(x, r.y0 + y), out.pixel(x, r.y0 + y) + 4, &line.values[4 * y]);
      blur_line(line, h, sigma_y, edge_mode);
      for (int y = 0; y < h; ++y)
        std::copy(&line.values[4 * y], &line.values[4 * y] + 4, out.pixel(x, r.y0 + y));
    }
  }
}

}  // namespace curvescan::svg::detail::filter
