// DenseCoverage: see dense_coverage.h.
#include "dense_coverage.h"

#include <algorithm>
#include <cstring>

#include "coverage_row.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
// Eight columns per register where the processor has AVX2, chosen at run time (the build targets baseline
// x86-64): GCC's and Clang's target attribute compiles one function for AVX2 without a library or a
// second build, and __builtin_cpu_supports picks it. Highway or xsimd would do the same dispatch for a
// whole family of instruction sets; for one loop of a dozen intrinsics they would be a dependency without
// a gain (README.md, dependencies).
#if defined(__SSE2__) && defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define CURVESCAN_DENSE_AVX2 1
#include <immintrin.h>
#endif

namespace curvescan::detail {

void DenseCoverage::reset(int x0, int y0, int width, int height) {
  x0_ = x0;
  y0_ = y0;
  width_ = width;
  height_ = height;
  // The right side and one past it, rounded up to whole groups of four columns (write_row's last group
  // may read up to three cells past the right side: they stay zero).
  stride_ = (static_cast<std::size_t>(width) + 2 + 3) & ~std::size_t{3};
  const std::size_t cells = stride_ * static_cast<std::size_t>(height);
  // write_mask clears every cell it reads, so the buffer is all zero between fills; growing adds zeros.
  if (cells_.size() < cells) cells_.resize(cells, 0.0f);
}

namespace {

#if defined(CURVESCAN_DENSE_AVX2)
/// write_row's groups of eight columns with eight lanes per register, from column 0 while eight remain:
/// returns the first column not written; `running_sum` is the prefix sum before column 0 on entry and
/// after the last column written on return. The same sums as the four-lane form in another order of
/// additions: every partial sum is still a difference of coverages (|·| <= 255) plus the half, so the
/// rounding bound of dense_coverage.h holds.
///
/// A group whose eight cells are all zero (no boundary piece wrote them: the inside of a stem, a counter,
/// the margins of a large glyph) needs no prefix sum and no clearing: every column's sum is the carry, so
/// its bytes are the carry's byte, the same bits the full step would give (adding +0.0 changes no sum).
/// At 100 px most rows of a glyph are more than half such groups (docs/benchmarks.md).
__attribute__((target("avx2"))) int write_columns_avx2(float* acc, int width, std::uint8_t* out,
                                                       float& running_sum) noexcept {
  const __m256 zero = _mm256_setzero_ps();
  __m256 carry = _mm256_set1_ps(running_sum);
  int c = 0;
  for (; c + 8 <= width; c += 8) {
    float* const cells = acc + c;
    __m256 x = _mm256_loadu_ps(cells);
    const __m256i bits = _mm256_castps_si256(x);
    if (_mm256_testz_si256(bits, bits)) {
      const __m128i sum = _mm_cvttps_epi32(_mm256_castps256_ps128(carry));
      const __m128i words = _mm_packs_epi32(sum, sum);
      _mm_storel_epi64(reinterpret_cast<__m128i*>(out + c), _mm_packus_epi16(words, words));
      continue;
    }
    _mm256_storeu_ps(cells, zero);
    // Prefix sums inside each 128-bit half (two shifted adds), then the low half's total added to the
    // high half, then the carry of the columns to the left, broadcast from the previous group's last
    // column.
    x = _mm256_add_ps(x, _mm256_castsi256_ps(_mm256_slli_si256(_mm256_castps_si256(x), 4)));
    x = _mm256_add_ps(x, _mm256_castsi256_ps(_mm256_slli_si256(_mm256_castps_si256(x), 8)));
    const __m256 low_total = _mm256_permute_ps(_mm256_permute2f128_ps(x, x, 0x08), _MM_SHUFFLE(3, 3, 3, 3));
    x = _mm256_add_ps(_mm256_add_ps(x, low_total), carry);
    const __m256 last = _mm256_permute_ps(x, _MM_SHUFFLE(3, 3, 3, 3));
    carry = _mm256_permute2f128_ps(last, last, 0x11);
    const __m256i sums = _mm256_cvttps_epi32(x);
    const __m128i words = _mm_packs_epi32(_mm256_castsi256_si128(sums), _mm256_extracti128_si256(sums, 1));
    _mm_storel_epi64(reinterpret_cast<__m128i*>(out + c), _mm_packus_epi16(words, words));
  }
  running_sum = _mm256_cvtss_f32(carry);
  return c;
}
#endif

/// One row: the prefix sums of `acc[0 .. width)` (255 · coverage deltas) plus one half, truncated to bytes
/// into `out`; clears acc[0 .. width + 2). With `may_overrun` (a row followed by at least three bytes of the
/// mask: not the last row, nor the second last of a mask one or two columns wide), the bytes are written
/// four at a time up to the next multiple of four: the up to three bytes past the row land in the rows
/// below, which are written afterwards, and the cells they come from are those of the
/// right side and the zero padding of the stride (reset()), cleared here as well. A row of a 12 px glyph
/// is 5 to 10 columns: this replaces the per-column tail of the prefix sum by one more vector step.
[[gnu::always_inline]] inline void write_row(float* acc, int width, std::uint8_t* out,
                                             [[maybe_unused]] bool may_overrun,
                                             [[maybe_unused]] bool avx2) noexcept {
  int c = 0;
  // The rounding's half starts the prefix sum, so each column's sum is 255·coverage + 0.5 already.
  float sum = 0.5f;
#if defined(__SSE2__)
  // Four columns per register: a prefix sum inside the register (two shifted adds), plus the carry of the
  // columns to the left broadcast from the previous register's last lane. No clamp: coverage is in [0, 1]
  // up to float rounding (the pieces bound the filled region), so 255·coverage + 0.5 truncates to 0..255
  // except for negative noise, which the saturating packs send to 0.
  const __m128 zero = _mm_setzero_ps();
#if defined(CURVESCAN_DENSE_AVX2)
  if (avx2 && width >= 16) c = write_columns_avx2(acc, width, out, sum);
#endif
  __m128 carry = _mm_set1_ps(sum);
  const auto four_columns = [&](int column) {
    __m128 x = _mm_loadu_ps(acc + column);
    _mm_storeu_ps(acc + column, zero);
    x = _mm_add_ps(x, _mm_castsi128_ps(_mm_slli_si128(_mm_castps_si128(x), 4)));
    x = _mm_add_ps(x, _mm_castsi128_ps(_mm_slli_si128(_mm_castps_si128(x), 8)));
    x = _mm_add_ps(x, carry);
    carry = _mm_shuffle_ps(x, x, _MM_SHUFFLE(3, 3, 3, 3));
    return _mm_cvttps_epi32(x);
  };
  const auto store_four = [&](int column) {
    __m128i bytes = four_columns(column);
    bytes = _mm_packs_epi32(bytes, bytes);
    bytes = _mm_packus_epi16(bytes, bytes);
    const int four = _mm_cvtsi128_si32(bytes);
    std::memcpy(out + column, &four, 4);
  };
  for (; c + 16 <= width; c += 16) {
    const __m128i a = four_columns(c);
    const __m128i b = four_columns(c + 4);
    const __m128i d = four_columns(c + 8);
    const __m128i e = four_columns(c + 12);
    const __m128i bytes = _mm_packus_epi16(_mm_packs_epi32(a, b), _mm_packs_epi32(d, e));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + c), bytes);
  }
  for (; c + 4 <= width; c += 4) store_four(c);
  if (may_overrun && c < width) {
    store_four(c);  // cells c .. c + 3 (at most width + 2 < stride) read and cleared
    c = width;
  }
  sum = _mm_cvtss_f32(carry);
#endif
  for (; c < width; ++c) {
    sum += acc[c];
    acc[c] = 0.0f;
    // round(255·coverage), coverage clamped to [0, 1] against rounding noise.
    out[c] = static_cast<std::uint8_t>(sum < 0.0f ? 0.0f : (sum > 255.0f ? 255.0f : sum));
  }
  // The right side of the box and one past it: pieces on the right edge carry into them; never shown.
  acc[width] = 0.0f;
  acc[width + 1] = 0.0f;
}

/// Every row of the box, by write_row: `cells` holds `height` rows of `stride` cells, `mask` width · height
/// bytes.
[[gnu::always_inline]] inline void write_rows(float* cells, std::size_t stride, int width, int height,
                                              std::span<std::uint8_t> mask, bool avx2) noexcept {
  const auto columns = static_cast<std::size_t>(width);
  const std::size_t padded_width = (columns + 3) & ~std::size_t{3};  // write_row's overrun: < 4 bytes
  for (int row = 0; row < height; ++row) {
    const std::size_t start = static_cast<std::size_t>(row) * columns;
    write_row(cells + static_cast<std::size_t>(row) * stride, width, mask.data() + start,
              start + padded_width <= mask.size(), avx2);
  }
}

#if defined(CURVESCAN_DENSE_AVX2)
/// write_rows compiled for AVX2 as a whole, so that each row's groups of eight (write_columns_avx2) are
/// inlined into the row loop instead of called once per row (a call and the carry through memory: at
/// 100 px about a tenth of the byte pass).
__attribute__((target("avx2"))) void write_rows_avx2(float* cells, std::size_t stride, int width, int height,
                                                     std::span<std::uint8_t> mask) noexcept {
  write_rows(cells, stride, width, height, mask, true);
}
#endif

}  // namespace

void DenseCoverage::write_mask(std::span<std::uint8_t> mask) noexcept {
#if defined(CURVESCAN_DENSE_AVX2)
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2) {
    write_rows_avx2(cells_.data(), stride_, width_, height_, mask);
    return;
  }
#endif
  write_rows(cells_.data(), stride_, width_, height_, mask, false);
}

}  // namespace curvescan::detail
