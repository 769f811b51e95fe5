// feGaussianBlur (gaussian_blur.h).
#include "gaussian_blur.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#include <xmmintrin.h>
#endif

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

// Colour channels that are zero over the whole rectangle (SourceAlpha, a shadow's input) stay zero: only
// the channels that hold something are blurred. Alpha always counts.
void active_channels(const FilterImage& in, PixelRect r, bool alpha_only, bool active[4]) noexcept {
  active[0] = active[1] = active[2] = false;
  active[3] = true;
  for (int y = r.y0; y < r.y1 && !alpha_only; ++y) {
    const float* p = in.pixel(r.x0, y);
    int any[3] = {0, 0, 0};  // a row at a time, without a branch per pixel
    for (int i = 0; i < r.width(); ++i, p += 4) {
      any[0] |= static_cast<int>(p[0] != 0.0f);
      any[1] |= static_cast<int>(p[1] != 0.0f);
      any[2] |= static_cast<int>(p[2] != 0.0f);
    }
    for (int c = 0; c < 3; ++c) active[c] = active[c] || any[c] != 0;
  }
}

// ---- The fast path, for every edge mode: columns of a plane blurred side by side. ----
// Per channel: gathered with rows as columns, the rows blurred (as columns), transposed back, the columns
// blurred, and written back row by row.

// A plane of `rows` lines of `columns` floats, `stride` floats apart: memory it does not own (a band
// buffer, or a strip of columns of a larger plane). One pass reads `from` and writes `to`.
struct Plane {
  float* values = nullptr;
  int columns = 0, rows = 0;
  std::ptrdiff_t stride = 0;
  float* row(int y) const noexcept { return values + static_cast<std::ptrdiff_t>(y) * stride; }
};

// One row of a box along the columns: target = sum · scale, then sum += add - remove (each may be absent,
// `Add`/`Remove` false). Four columns at a time with SSE2 (two doubles per register), the same operations in
// the same order as the plain loop after it, so that both give the same bits.
template <bool Add, bool Remove>
void box_row(float* target, double* sum, const float* add, const float* remove, int w,
             double scale) noexcept {
  int x = 0;
#if defined(__SSE2__)
  const __m128d factor = _mm_set1_pd(scale);
  for (; x + 4 <= w; x += 4) {
    __m128d low = _mm_loadu_pd(sum + x), high = _mm_loadu_pd(sum + x + 2);
    _mm_storeu_ps(target + x, _mm_movelh_ps(_mm_cvtpd_ps(_mm_mul_pd(low, factor)),
                                            _mm_cvtpd_ps(_mm_mul_pd(high, factor))));
    __m128d change_low = _mm_setzero_pd(), change_high = _mm_setzero_pd();
    if constexpr (Add) {
      const __m128 a = _mm_loadu_ps(add + x);
      change_low = _mm_cvtps_pd(a);
      change_high = _mm_cvtps_pd(_mm_movehl_ps(a, a));
    }
    if constexpr (Add && Remove) {
      const __m128 r = _mm_loadu_ps(remove + x);
      change_low = _mm_sub_pd(change_low, _mm_cvtps_pd(r));
      change_high = _mm_sub_pd(change_high, _mm_cvtps_pd(_mm_movehl_ps(r, r)));
    }
    if constexpr (Add) {
      low = _mm_add_pd(low, change_low);
      high = _mm_add_pd(high, change_high);
    } else if constexpr (Remove) {
      const __m128 r = _mm_loadu_ps(remove + x);
      low = _mm_sub_pd(low, _mm_cvtps_pd(r));
      high = _mm_sub_pd(high, _mm_cvtps_pd(_mm_movehl_ps(r, r)));
    }
    _mm_storeu_pd(sum + x, low);
    _mm_storeu_pd(sum + x + 2, high);
  }
#endif
  for (; x < w; ++x) {
    target[x] = static_cast<float>(sum[x] * scale);
    if constexpr (Add && Remove) {
      sum[x] += static_cast<double>(add[x]) - static_cast<double>(remove[x]);
    } else if constexpr (Add) {
      sum[x] += add[x];
    } else if constexpr (Remove) {
      sum[x] -= remove[x];
    }
  }
}

// The sum of rows [a, b] (any integers) of `from` under `mode` (duplicate or wrap) into `sums`, a column
// at a time: each row of the plane is added at most once, with its multiplicity, however wide the window.
void window_rows(const Plane& from, long long a, long long b, EdgeMode mode, std::vector<double>& sums) {
  const int w = from.columns;
  const long long h = from.rows;
  sums.assign(static_cast<std::size_t>(w), 0.0);
  double* sum = sums.data();
  const auto add_row = [&](long long y, double times) {
    const float* row = from.row(static_cast<int>(y));
    for (int x = 0; x < w; ++x) sum[x] += times * row[x];
  };
  if (mode == EdgeMode::kDuplicate) {
    if (a < 0) add_row(0, static_cast<double>(std::min(b, -1LL) - a + 1));       // copies of the first row
    if (b > h - 1) add_row(h - 1, static_cast<double>(b - std::max(a, h) + 1));  // and of the last
    for (long long y = std::max(a, 0LL); y <= std::min(b, h - 1); ++y) add_row(y, 1.0);
    return;
  }
  // wrap: the window holds every row (b - a + 1) / h times, and then (b - a + 1) % h rows from a on.
  const long long length = b - a + 1, whole = length / h;
  for (long long y = 0; y < h && whole > 0; ++y) add_row(y, static_cast<double>(whole));
  for (long long k = 0; k < length % h; ++k) add_row(edge_index(a + k, h, mode), 1.0);
}

// One box along the columns: to(y) = mean of from(y - left .. y + right), rows outside the plane read per
// `mode` (transparent for none). A running sum per column, in double so that adding and removing rows
// leaves no drift.
void box_columns(const Plane& from, const Plane& to, long long left, long long right, EdgeMode mode,
                 std::vector<double>& sums) {
  const int w = from.columns, h = from.rows;
  const double scale = 1.0 / static_cast<double>(left + right + 1);
  if (mode != EdgeMode::kNone) {
    // Every row that enters or leaves the window exists (folded back into the plane), so each step adds
    // one row and removes one; the first window is summed in closed form (window_rows).
    window_rows(from, -left, right, mode, sums);
    double* sum = sums.data();
    for (int y = 0; y < h; ++y) {
      const float* add = from.row(static_cast<int>(edge_index(y + right + 1, h, mode)));
      const float* remove = from.row(static_cast<int>(edge_index(y - left, h, mode)));
      box_row<true, true>(to.row(y), sum, add, remove, w, scale);
    }
    return;
  }
  sums.assign(static_cast<std::size_t>(w), 0.0);
  double* sum = sums.data();
  const long long first_rows = std::min<long long>(right, h - 1);
  for (long long y = 0; y <= first_rows; ++y) {
    const float* add = from.row(static_cast<int>(y));
    for (int x = 0; x < w; ++x) sum[x] += add[x];
  }
  for (int y = 0; y < h; ++y) {
    float* target = to.row(y);
    // Row y + right + 1 enters the window and row y - left leaves it (either may be outside the plane).
    const float* add =
        static_cast<long long>(y) + right + 1 < h ? from.row(static_cast<int>(y + right + 1)) : nullptr;
    const float* remove =
        static_cast<long long>(y) - left >= 0 ? from.row(static_cast<int>(y - left)) : nullptr;
    if (add != nullptr && remove != nullptr) {
      box_row<true, true>(target, sum, add, remove, w, scale);
    } else if (add != nullptr) {
      box_row<true, false>(target, sum, add, remove, w, scale);
    } else if (remove != nullptr) {
      box_row<false, true>(target, sum, add, remove, w, scale);
    } else {
      box_row<false, false>(target, sum, add, remove, w, scale);
    }
  }
}

// The exact kernel along the columns (σ < 2): to(y) = Σ_k kernel(k) from(y + k), rows outside the plane
// read per `mode` (none: skipped, transparent).
void kernel_columns(const Plane& from, const Plane& to, const std::vector<double>& kernel, EdgeMode mode) {
  const int w = from.columns, h = from.rows;
  const int radius = static_cast<int>(kernel.size() / 2);
  for (int y = 0; y < h; ++y) {
    float* target = to.row(y);
    std::fill(target, target + w, 0.0f);
    for (int k = -radius; k <= radius; ++k) {
      const long long source_row = edge_index(y + k, h, mode);
      if (source_row < 0) continue;
      const float weight = static_cast<float>(kernel[static_cast<std::size_t>(k + radius)]);
      const float* source = from.row(static_cast<int>(source_row));
      for (int x = 0; x < w; ++x) target[x] += weight * source[x];
    }
  }
}

// Blurs the columns of `plane` with σ (> 0) into `result` (the same size), which the passes use as the
// other buffer: `plane` is overwritten.
void blur_columns(const Plane& plane, const Plane& result, double sigma, EdgeMode mode,
                  std::vector<double>& sums) {
  if (sigma < 2.0) {
    kernel_columns(plane, result, gaussian_kernel(sigma), mode);
    return;
  }
  const long long d = box_blur_size(sigma);
  const long long h = d / 2;
  if (d % 2 == 1) {
    box_columns(plane, result, h, h, mode, sums);
    box_columns(result, plane, h, h, mode, sums);
    box_columns(plane, result, h, h, mode, sums);
  } else {
    box_columns(plane, result, h, h - 1, mode, sums);  // centred between y - 1 and y
    box_columns(result, plane, h - 1, h, mode, sums);  // centred between y and y + 1
    box_columns(plane, result, h, h, mode, sums);      // size d + 1, centred
  }
}

// Rows [first, first + count) of `from` transposed into `to` (count columns of from.columns rows), in
// cache-sized blocks; with SSE2, four rows by four columns at a time (a 4 x 4 transposition in registers).
void transpose_rows(const Plane& from, int first, int count, const Plane& to) {
  constexpr int kBlock = 32;
  for (int y0 = 0; y0 < count; y0 += kBlock)
    for (int x0 = 0; x0 < from.columns; x0 += kBlock) {
      const int y_end = std::min(count, y0 + kBlock), x_end = std::min(from.columns, x0 + kBlock);
      int y = y0;
#if defined(__SSE2__)
      for (; y + 4 <= y_end; y += 4) {
        const float* s0 = from.row(first + y);
        const float* s1 = from.row(first + y + 1);
        const float* s2 = from.row(first + y + 2);
        const float* s3 = from.row(first + y + 3);
        int x = x0;
        for (; x + 4 <= x_end; x += 4) {
          __m128 a = _mm_loadu_ps(s0 + x), b = _mm_loadu_ps(s1 + x), c = _mm_loadu_ps(s2 + x),
                 d = _mm_loadu_ps(s3 + x);
          _MM_TRANSPOSE4_PS(a, b, c, d);
          _mm_storeu_ps(to.row(x) + y, a);
          _mm_storeu_ps(to.row(x + 1) + y, b);
          _mm_storeu_ps(to.row(x + 2) + y, c);
          _mm_storeu_ps(to.row(x + 3) + y, d);
        }
        for (; x < x_end; ++x) {
          float* target = to.row(x) + y;
          target[0] = s0[x];
          target[1] = s1[x];
          target[2] = s2[x];
          target[3] = s3[x];
        }
      }
#endif
      for (; y < y_end; ++y) {
        const float* source = from.row(first + y);
        for (int x = x0; x < x_end; ++x) to.row(x)[y] = source[x];
      }
    }
}

// Channel `c` of `in` inside `r` into `turned` (r.width() rows of r.height(): row x holds column x),
// in cache-sized blocks; with SSE2, four rows at a time: the four pixels (x, y .. y + 3) transposed in
// registers give the channel down the column.
void gather_turned(const FilterImage& in, PixelRect r, int c, const Plane& turned) {
  constexpr int kBlock = 32;
  const int w = r.width(), h = r.height();
  for (int y0 = 0; y0 < h; y0 += kBlock)
    for (int x0 = 0; x0 < w; x0 += kBlock) {
      const int y_end = std::min(h, y0 + kBlock), x_end = std::min(w, x0 + kBlock);
      int y = y0;
#if defined(__SSE2__)
      for (; y + 4 <= y_end; y += 4) {
        const float* p0 = in.pixel(r.x0, r.y0 + y);
        const float* p1 = in.pixel(r.x0, r.y0 + y + 1);
        const float* p2 = in.pixel(r.x0, r.y0 + y + 2);
        const float* p3 = in.pixel(r.x0, r.y0 + y + 3);
        for (int x = x0; x < x_end; ++x) {
          __m128 channels[4] = {_mm_loadu_ps(p0 + 4 * x), _mm_loadu_ps(p1 + 4 * x), _mm_loadu_ps(p2 + 4 * x),
                                _mm_loadu_ps(p3 + 4 * x)};
          _MM_TRANSPOSE4_PS(channels[0], channels[1], channels[2], channels[3]);
          _mm_storeu_ps(turned.row(x) + y, channels[c]);
        }
      }
#endif
      for (; y < y_end; ++y) {
        const float* p = in.pixel(r.x0, r.y0 + y);
        for (int x = x0; x < x_end; ++x) turned.row(x)[y] = p[4 * x + c];
      }
    }
}

// Reads `in` inside `r` and writes the blur inside `keep` (within r): the rows are blurred over all of r
// (the columns' support), the columns only over keep's columns, and only keep is written.
void gaussian_blur_fast(const FilterImage& in, PixelRect r, PixelRect keep, double sigma_x, double sigma_y,
                        EdgeMode mode, bool alpha_only, FilterImage& out) {
  const int w = r.width(), h = r.height();
  const int first_column = keep.x0 - r.x0, columns = keep.width();
  const bool blur_x = sigma_x > 0.0, blur_y = sigma_y > 0.0;  // false for NaN
  bool active[4];
  active_channels(in, r, alpha_only, active);
  // The rows are blurred a band of kBand rows at a time, turned so that they run down the columns of a
  // small buffer (w rows of kBand), and turned back into `plane` (keep's columns, all h rows); the columns
  // are then blurred a strip of kStrip at a time into another small buffer, and written out. Only `plane`
  // is the rectangle's size; the buffers stay in the cache.
  constexpr int kBand = 32, kStrip = 64;
  FilterPixels plane_memory(static_cast<std::size_t>(columns) * h);
  const Plane plane{plane_memory.data(), columns, h, columns};
  std::vector<float> band_memory(2 * static_cast<std::size_t>(w) * kBand);
  std::vector<float> strip_memory(static_cast<std::size_t>(kStrip) * h);
  std::vector<double> sums;
  const bool colourless = !active[0] && !active[1] && !active[2];
  if (!colourless) {
    // The channels left out are written as zero, in one pass (with only alpha, the last scatter does it).
    for (int y = keep.y0; y < keep.y1; ++y) {
      float* p = out.pixel(keep.x0, y);
      for (int i = 0; i < columns; ++i, p += 4)
        for (int c = 0; c < 3; ++c) p[c] = active[c] ? p[c] : 0.0f;
    }
  }
  for (int c = 0; c < 4; ++c) {
    if (!active[c]) continue;
    for (int y0 = 0; y0 < h; y0 += kBand) {
      const int rows = std::min(kBand, h - y0);
      const Plane turned{band_memory.data(), rows, w, rows};
      const Plane blurred{band_memory.data() + static_cast<std::size_t>(w) * kBand, rows, w, rows};
      gather_turned(in, PixelRect{r.x0, r.y0 + y0, r.x1, r.y0 + y0 + rows}, c, turned);
      if (blur_x) blur_columns(turned, blurred, sigma_x, mode, sums);
      transpose_rows(blur_x ? blurred : turned, first_column, columns,
                     Plane{plane.row(y0), columns, rows, columns});
    }
    for (int x0 = 0; x0 < columns; x0 += kStrip) {
      const int width = std::min(kStrip, columns - x0);
      const Plane strip{plane.values + x0, width, h, columns};
      const Plane result{strip_memory.data(), width, h, width};
      if (blur_y) blur_columns(strip, result, sigma_y, mode, sums);
      const Plane& done = blur_y ? result : strip;
      for (int y = keep.y0; y < keep.y1; ++y) {
        float* p = out.pixel(keep.x0 + x0, y);
        const float* row = done.row(y - r.y0);
        if (c == 3 && colourless) {
          for (int x = 0; x < width; ++x, p += 4) {
            p[0] = p[1] = p[2] = 0.0f;
            p[3] = row[x];
          }
        } else {
          for (int x = 0; x < width; ++x) p[4 * x + c] = row[x];
        }
      }
    }
  }
}

// ---- duplicate and wrap with a blur far wider than the line: the line becomes one value. ----
// The first box takes every sample of the line many times over. For wrap it holds q whole periods and a
// part of one: (q · Σv + part) / d, which is the line's mean Σv / n to within n / d. For duplicate, window
// [i - l, i + r] holds l - i copies of the first sample, the line, and r - (n - 1 - i) copies of the last:
// (l · v[0] + r · v[n - 1]) / (l + r + 1) to within 2n / d. Both are the same value at every i, and a box
// of a constant line (extended by copies or periods of itself) is that constant: the next two boxes leave
// it. With d >= 2^26 · n the error is below 2^-25, under half a float's step at 1 (the result is as
// exact as the blur's float channels), so the blur is computed from that value: the work is a pass over
// the line's ends (duplicate) or its ink (wrap), whatever σ and the region.

constexpr long long kCollapseFactor = 1LL << 26;

// The first box's half-widths left and right of the pixel (blur_line's first pass).
std::pair<long long, long long> first_box(double sigma) noexcept {
  const long long d = box_blur_size(sigma), h = d / 2;
  return d % 2 == 1 ? std::pair{h, h} : std::pair{h, h - 1};
}

bool collapses(double sigma, int n, EdgeMode mode) noexcept {
  if (mode == EdgeMode::kNone || !(sigma >= 2.0) || n <= 0) return false;
  // box_blur_size saturates at 10^12: that width is taken as the blur's (as the other paths do), and the
  // collapse then holds to within 2n / 10^12.
  const long long d = box_blur_size(sigma);
  return d >= std::min<long long>(kCollapseFactor * n, static_cast<long long>(1e12));
}

// What a collapsing blur makes of a line of which `first` and `last` are the end samples and `total` the
// sum of all `n`.
double collapsed_value(double first, double last, double total, long long n, double sigma,
                       EdgeMode mode) noexcept {
  if (mode == EdgeMode::kWrap) return total / static_cast<double>(n);
  const auto [l, r] = first_box(sigma);
  return (static_cast<double>(l) * first + static_cast<double>(r) * last) / static_cast<double>(l + r + 1);
}

// Both or one axis collapses. The blur along one axis is a linear map applied alike to every line, and a
// collapse is a linear form on a line, so they commute: the collapsing axes are reduced first (to a column
// of row values, a row of column values, or one value), the other axis blurred on that one line, and the
// result written over `keep`. Reads only the rows and columns it needs: the ends of the lines for
// duplicate, the input's ink for wrap (the rest of `r` is transparent).
void gaussian_blur_collapsed(const FilterImage& in, PixelRect r, PixelRect keep, double sigma_x,
                             double sigma_y, EdgeMode mode, bool alpha_only, FilterImage& out) {
  const int w = r.width(), h = r.height();
  const bool along_x = collapses(sigma_x, w, mode), along_y = collapses(sigma_y, h, mode);
  const PixelRect ink = in.extent.intersect(r);
  const auto value = [&](int x, int y, int c) -> double {
    if (alpha_only && c < 3) return 0.0;
    return in.pixel(x, y)[c];
  };
  Scratch scratch;
  scratch.line.resize(static_cast<std::size_t>(std::max(w, h)));
  scratch.prefix.resize(static_cast<std::size_t>(std::max(w, h)) + 1);
  // The value of the collapsed line through (x, y) along x (rows) or y (columns).
  const auto collapse_row = [&](int y, int c) {
    double total = 0.0;
    if (mode == EdgeMode::kWrap && y >= ink.y0 && y < ink.y1)
      for (int x = ink.x0; x < ink.x1; ++x) total += value(x, y, c);
    return collapsed_value(value(r.x0, y, c), value(r.x1 - 1, y, c), total, w, sigma_x, mode);
  };
  const auto collapse_column = [&](int x, int c) {
    double total = 0.0;
    if (mode == EdgeMode::kWrap && x >= ink.x0 && x < ink.x1)
      for (int y = ink.y0; y < ink.y1; ++y) total += value(x, y, c);
    return collapsed_value(value(x, r.y0, c), value(x, r.y1 - 1, c), total, h, sigma_y, mode);
  };
  std::vector<float> line;
  for (int c = 0; c < 4; ++c) {
    if (along_x && along_y) {
      // A column of row values, collapsed in turn: one value for the whole rectangle. Only its end rows
      // (duplicate) or the ink's rows (wrap; the others are zero) count.
      double first = collapse_row(r.y0, c), last = collapse_row(r.y1 - 1, c), total = 0.0;
      for (int y = ink.y0; mode == EdgeMode::kWrap && y < ink.y1; ++y) total += collapse_row(y, c);
      const float v = static_cast<float>(collapsed_value(first, last, total, h, sigma_y, mode));
      for (int y = keep.y0; y < keep.y1; ++y)
        for (int x = keep.x0; x < keep.x1; ++x) out.pixel(x, y)[c] = v;
    } else {
      // Every row one value (collapsed along x) or every column one value (along y): that line of values
      // is blurred along the other axis and spread across the collapsed one.
      const int n = along_x ? h : w, first = along_x ? r.y0 : r.x0;
      const double sigma = along_x ? sigma_y : sigma_x;
      line.resize(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i)
        line[static_cast<std::size_t>(i)] =
            static_cast<float>(along_x ? collapse_row(first + i, c) : collapse_column(first + i, c));
      if (sigma > 0.0) {
        const std::vector<double> kernel = sigma < 2.0 ? gaussian_kernel(sigma) : std::vector<double>{};
        blur_line(line.data(), n, sigma, kernel, mode, scratch);
      }
      for (int y = keep.y0; y < keep.y1; ++y)
        for (int x = keep.x0; x < keep.x1; ++x)
          out.pixel(x, y)[c] = line[static_cast<std::size_t>((along_x ? y : x) - first)];
    }
  }
}

}  // namespace

long long box_blur_size(double sigma) noexcept {
  const double d = std::floor(sigma * 3.0 * std::sqrt(2.0 * std::numbers::pi) / 4.0 + 0.5);
  return d > 1e12 ? static_cast<long long>(1e12) : static_cast<long long>(d);
}

void gaussian_blur_reference(const FilterImage& in, PixelRect subregion, double sigma_x, double sigma_y,
                             EdgeMode edge_mode, FilterImage& out, bool alpha_only) {
  const PixelRect r = subregion.intersect(in.bounds()).intersect(out.bounds());
  if (r.empty()) return;
  const int w = r.width(), h = r.height();
  const bool blur_x = sigma_x > 0.0, blur_y = sigma_y > 0.0;  // false for NaN
  bool active[4];
  active_channels(in, r, alpha_only, active);
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

long long blur_reach(double sigma) noexcept {
  if (!(sigma > 0.0)) return 0;
  if (sigma < 2.0) return static_cast<long long>(std::ceil(3.0 * sigma));
  // Three boxes of half-width d / 2 (the even case's third box is d + 1 wide: one more).
  return 3 * (box_blur_size(sigma) / 2) + 1;
}

void gaussian_blur(const FilterImage& in, PixelRect subregion, double sigma_x, double sigma_y,
                   EdgeMode edge_mode, FilterImage& out, bool alpha_only, std::optional<PixelRect> written) {
  const PixelRect r = subregion.intersect(in.bounds()).intersect(out.bounds());
  const PixelRect keep = written ? r.intersect(*written) : r;
  if (keep.empty()) return;
  if (collapses(sigma_x, r.width(), edge_mode) || collapses(sigma_y, r.height(), edge_mode)) {
    gaussian_blur_collapsed(in, r, keep, sigma_x, sigma_y, edge_mode, alpha_only, out);
    return;
  }
  gaussian_blur_fast(in, r, keep, sigma_x, sigma_y, edge_mode, alpha_only, out);
}

}  // namespace curvescan::svg::detail::filter
