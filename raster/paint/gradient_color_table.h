// PadColorTable: the colours of a pad-spread gradient at every one of pixman's 16.16 positions, so that a
// large gradient fill looks its colours up instead of evaluating them.
//
// Exactness. The walker (gradient_walker.h) gives a colour that depends on the fixed-point position pos
// alone. Under pad spread the normalized stops run from 0 to 1 (gradient.cpp), so every pos below 0 lies
// in the constant segment before the first stop and every pos above 65536 (1.0) in the constant segment
// after the last: 65 539 entries (below, 0 .. 65536, above) are every colour the walker can give, and each
// entry is the walker's own output, so a lookup is the walker's colour bit for bit. index_of(t) is
// fixed_position(t) clamped to [−1, 65537], computed without its wide clamp: a product t·65536 beyond
// [−2, 65538] lands on the "below" or "above" entry either way. Repeat and reflect evaluate the float ramp
// at the unfolded position (as pixman does), which makes the colour depend on the period through float
// rounding; they keep the walker.
//
// Why not a small table. A table of 256 or 1024 entries (pixman has none; Skia's old cache and Blend2D use
// such sizes) moves t by up to half a table step: on the steep ramps of tests/oracle/paint_gradient_test.cpp
// that is more than the one level the Cairo oracle allows. The full table is 256 KiB and 65 539 walker
// evaluations, about the cost of shading as many pixels, so the compositor builds it only for fills that
// have already shaded that many (gradient_span_compositor.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "gradient_walker.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace curvescan::detail {

class PadColorTable {
 public:
  static constexpr std::size_t kNanIndex = kFixedOne + 3;
  static constexpr std::size_t kEntries = kNanIndex + 1;
  /// The table's memory, counted against the render's memory budget (Canvas::fill).
  static constexpr std::int64_t kBytes = static_cast<std::int64_t>(kEntries * sizeof(Rgba8));

  explicit PadColorTable(GradientWalker& walker) : entries_(kEntries) {
    walker.colors_at_fixed(-1, kNanIndex, entries_.data());
    entries_[kNanIndex] = {};  // NaN -> transparent, as GradientWalker::color_at
  }

  /// The walker's colour at t (pad spread): GradientWalker::color_at(t).
  [[nodiscard]] Rgba8 color_at(double t) const noexcept { return entries_[index_of(t)]; }

  /// out[i] = color_at(t[i]) for i in [0, n): index_of two at a time in SSE2 double lanes.
  void colors_at(const double* t, int n, Rgba8* out) const noexcept {
    int i = 0;
#if defined(__SSE2__)
    const __m128d scale = _mm_set1_pd(65536.0);
    const __m128d lowest = _mm_set1_pd(-2.0), highest = _mm_set1_pd(static_cast<double>(kFixedOne + 2));
    const __m128d snap = _mm_set1_pd(kFixedSnap), minus_snap = _mm_set1_pd(-kFixedSnap);
    const __m128d one = _mm_set1_pd(1.0);
    const __m128d first_entry = _mm_set1_pd(-1.0),
                  last_entry = _mm_set1_pd(static_cast<double>(kFixedOne + 1));
    const __m128d nan_index = _mm_set1_pd(static_cast<double>(kNanIndex));
    for (; i + 2 <= n; i += 2) {
      const __m128d ts = _mm_loadu_pd(t + i);
      const __m128d is_nan = _mm_cmpunord_pd(ts, ts);
      // max/min return their second operand for a NaN lane; is_nan replaces that lane's result below.
      const __m128d fixed = _mm_min_pd(_mm_max_pd(_mm_mul_pd(ts, scale), lowest), highest);
      const __m128d truncated = _mm_cvtepi32_pd(_mm_cvttpd_epi32(fixed));
      const __m128d fraction = _mm_sub_pd(fixed, truncated);
      const __m128d up = _mm_and_pd(_mm_cmpgt_pd(fraction, snap), one);
      const __m128d down = _mm_and_pd(_mm_cmplt_pd(fraction, minus_snap), one);
      const __m128d pos =
          _mm_min_pd(_mm_max_pd(_mm_sub_pd(_mm_add_pd(truncated, up), down), first_entry), last_entry);
      const __m128d index =
          _mm_or_pd(_mm_andnot_pd(is_nan, _mm_add_pd(pos, one)), _mm_and_pd(is_nan, nan_index));
      const __m128i indices = _mm_cvttpd_epi32(index);
      out[i] = entries_[static_cast<std::size_t>(_mm_cvtsi128_si32(indices))];
      out[i + 1] = entries_[static_cast<std::size_t>(_mm_cvtsi128_si32(_mm_srli_si128(indices, 4)))];
    }
#endif
    for (; i < n; ++i) out[i] = color_at(t[i]);
  }

  [[nodiscard]] static std::size_t index_of(double t) noexcept {
    if (std::isnan(t)) return kNanIndex;
    const double fixed = std::clamp(t * 65536.0, -2.0, static_cast<double>(kFixedOne + 2));
    const int truncated = static_cast<int>(fixed);  // towards zero, as fixed_position
    const double fraction = fixed - static_cast<double>(truncated);
    const int pos =
        truncated + static_cast<int>(fraction > kFixedSnap) - static_cast<int>(fraction < -kFixedSnap);
    return static_cast<std::size_t>(std::clamp(pos, -1, static_cast<int>(kFixedOne) + 1) + 1);
  }

 private:
  std::vector<Rgba8> entries_;
};

}  // namespace curvescan::detail
