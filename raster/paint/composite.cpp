// Compositing of a solid premultiplied colour with coverage: pixman's OVER with an A8 mask, per pixel.
//
// pixman (pixman-combine32.h) computes x·a/255 rounded to nearest without a division as
//   t = x·a + 0x80;  (t + (t >> 8)) >> 8
// which is exact for x, a in [0, 255] (Blinn, "Three Wrongs Make a Right", IEEE CG&A 1995). The reference
// below divides instead; composite_test.cpp checks that the two agree on every input that matters.
//
// blend_solid_span (solid_span_compositor.h) is the same arithmetic for a run of pixels that share the
// source and coverage: the source side is done once, and the destination side four pixels at a time in
// 16-bit lanes (t = x·a + 0x80 <= 65153 fits an unsigned 16-bit lane, so the lanes compute exactly the
// scalar mul_un8), with a saturating byte add as add_saturated; the source side and the last pixels of a
// span (all of a thin stroke's spans of one to three pixels) take the same lanes one pixel at a time. It
// is held to composite_source_over pixel for pixel by tests/oracle/rasterizer_perf_compositor_test.cpp
// and, for every span length up to nine and every coverage, by tests/unit/paint/span_fast_paths_test.cpp.
//
// Where the processor has AVX2 (chosen at run time, as dense_coverage.cpp does: the build targets baseline
// x86-64), a span's groups of eight pixels go through the same lanes twice as wide: the same products and
// roundings per channel, so the same bytes, in half the instructions. The inside of a large translucent
// fill is such spans; per pixel the SSE2 loop was about five instructions, the AVX2 one is under three, and
// the pixels (a 512² canvas is 1 MiB, in L2) are read and written at the cache's speed either way.
#include "curvescan/raster/paint.h"
#include "curvescan/raster/pixel_format.h"

#include "solid_span_compositor.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__SSE2__) && defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define CURVESCAN_BLEND_AVX2 1
#include <immintrin.h>
#endif

namespace curvescan {
namespace {

// round(x·a/255) by division: 255 is odd, so x·a/255 is never exactly halfway and +127 rounds to nearest.
constexpr std::uint8_t mul_un8_by_division(unsigned x, unsigned a) noexcept {
  return static_cast<std::uint8_t>((x * a + 127u) / 255u);
}

// pixman's UN8_ADD_UN8: saturating add (valid premultiplied inputs never saturate, others may).
constexpr std::uint8_t add_saturated(unsigned x, unsigned y) noexcept {
  const unsigned sum = x + y;
  return static_cast<std::uint8_t>(sum > 255u ? 255u : sum);
}

}  // namespace

namespace detail {

namespace {

#if defined(CURVESCAN_BLEND_AVX2)
// __builtin_cpu_supports needs __builtin_cpu_init when it runs before main (a static initialiser).
const bool kHasAvx2 = [] {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") != 0;
}();

/// blend_run's loop over groups of eight pixels with AVX2, from pixel 0 while eight remain: returns the first
/// pixel not blended. `source_word` is s' (the colour through the coverage), as in blend_run. unpack and
/// pack work within each 128-bit half, so the eight pixels come back in their order.
__attribute__((target("avx2"))) int blend_groups_of_eight(Rgba8* row, int len,
                                                          std::uint32_t source_word) noexcept {
  const __m256i zero = _mm256_setzero_si256();
  const __m256i half = _mm256_set1_epi16(0x80);
  const __m256i times257 = _mm256_set1_epi16(257);
  const __m256i keep16 = _mm256_set1_epi16(static_cast<short>(255u - (source_word >> 24)));
  const __m256i source = _mm256_set1_epi32(static_cast<int>(source_word));
  // blend_run's scale (mul_un8 in 16-bit lanes), written out: a lambda would not be compiled for AVX2.
  int i = 0;
  for (; i + 8 <= len; i += 8) {
    __m256i* p = reinterpret_cast<__m256i*>(row + i);
    const __m256i d = _mm256_loadu_si256(p);
    const __m256i lo = _mm256_mulhi_epu16(
        _mm256_add_epi16(_mm256_mullo_epi16(_mm256_unpacklo_epi8(d, zero), keep16), half), times257);
    const __m256i hi = _mm256_mulhi_epu16(
        _mm256_add_epi16(_mm256_mullo_epi16(_mm256_unpackhi_epi8(d, zero), keep16), half), times257);
    _mm256_storeu_si256(p, _mm256_adds_epu8(_mm256_packus_epi16(lo, hi), source));
  }
  return i;
}
#else
constexpr bool kHasAvx2 = false;
#endif

// The body of blend_solid_span, inlined into the span loop of blend_solid_spans too (a thin stroke's spans
// are a pixel or two long, so a call and the constants' set-up per span cost as much as the pixels).
// `avx2`: whether groups of eight may take blend_groups_of_eight (false holds the SSE2 loop to the same
// bytes in tests on a processor that has AVX2).
[[gnu::always_inline]] inline void blend_run(Rgba8* row, int len, Rgba8 color, std::uint8_t coverage,
                                             [[maybe_unused]] bool avx2) noexcept {
#if defined(__SSE2__)
  static_assert(sizeof(Rgba8) == 4, "four bytes per pixel, loaded as 32-bit lanes");
  const __m128i zero = _mm_setzero_si128();
  const __m128i half = _mm_set1_epi16(0x80);
  const __m128i times257 = _mm_set1_epi16(257);
  // mul_un8(x, a) in every 16-bit lane: (t + (t >> 8)) >> 8 equals (t·257) >> 16 for any t < 2^16
  // (t + t/256 and t + floor(t/256) have the same floor after division by 256, their difference being
  // below 1/256), and (t·257) >> 16 is one unsigned high multiply.
  const auto scale = [&](__m128i x, __m128i a16) {
    return _mm_mulhi_epu16(_mm_add_epi16(_mm_mullo_epi16(x, a16), half), times257);
  };
  std::uint32_t color_word = 0;
  __builtin_memcpy(&color_word, &color, 4);
  __m128i source = _mm_cvtsi32_si128(static_cast<int>(color_word));
  if (coverage != 255) {
    // The source side, s' = mul_un8(colour, coverage) per channel, in the same lanes.
    source = _mm_packus_epi16(
        scale(_mm_unpacklo_epi8(source, zero), _mm_set1_epi16(static_cast<short>(coverage))), zero);
  }
  const auto source_word = static_cast<std::uint32_t>(_mm_cvtsi128_si32(source));
  source = _mm_set1_epi32(static_cast<int>(source_word));
  const __m128i keep16 = _mm_set1_epi16(static_cast<short>(255u - (source_word >> 24)));  // 255 - s'.a
  int i = 0;
#if defined(CURVESCAN_BLEND_AVX2)
  if (avx2 && len >= 8) i = blend_groups_of_eight(row, len, source_word);
#endif
  for (; i + 4 <= len; i += 4) {
    __m128i* p = reinterpret_cast<__m128i*>(row + i);
    const __m128i d = _mm_loadu_si128(p);
    const __m128i kept = _mm_packus_epi16(scale(_mm_unpacklo_epi8(d, zero), keep16),
                                          scale(_mm_unpackhi_epi8(d, zero), keep16));
    _mm_storeu_si128(p, _mm_adds_epu8(kept, source));
  }
  // The last pixels (all of them in the one- to three-pixel spans of a thin stroke) one at a time in
  // the same lanes: the same arithmetic as the loop, without the scalar per-channel code.
  for (; i < len; ++i) {
    std::uint32_t word = 0;
    __builtin_memcpy(&word, row + i, 4);
    const __m128i d = _mm_cvtsi32_si128(static_cast<int>(word));
    const __m128i kept = _mm_packus_epi16(scale(_mm_unpacklo_epi8(d, zero), keep16), zero);
    word = static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_adds_epu8(kept, source)));
    __builtin_memcpy(static_cast<void*>(row + i), &word, 4);
  }
#else
  Rgba8 s = color;
  if (coverage != 255)
    s = {mul_un8(s.r, coverage), mul_un8(s.g, coverage), mul_un8(s.b, coverage), mul_un8(s.a, coverage)};
  const unsigned keep = 255u - s.a;
  for (int i = 0; i < len; ++i) {
    const Rgba8 d = row[i];
    row[i] = {add_saturated(s.r, mul_un8(d.r, keep)), add_saturated(s.g, mul_un8(d.g, keep)),
              add_saturated(s.b, mul_un8(d.b, keep)), add_saturated(s.a, mul_un8(d.a, keep))};
  }
#endif
}

}  // namespace

void blend_solid_span(Rgba8* row, int len, Rgba8 color, std::uint8_t coverage) noexcept {
  blend_run(row, len, color, coverage, kHasAvx2);
}

void blend_solid_span_without_avx2(Rgba8* row, int len, Rgba8 color, std::uint8_t coverage) noexcept {
  blend_run(row, len, color, coverage, false);
}

void blend_solid_spans(Image& image, std::span<const Span> spans, Rgba8 color) noexcept {
  if (color.a == 0) return;  // premultiplied: a transparent colour is all zero and changes nothing
  const bool avx2 = kHasAvx2;
  for (const Span& span : spans) {
    if (span.coverage == 0) continue;
    Rgba8* row = image.row(span.y) + span.x;
    if (span.coverage == 255 && color.a == 255) {
      fill_pixels(row, static_cast<std::size_t>(span.len), color);
      continue;
    }
    blend_run(row, span.len, color, span.coverage, avx2);
  }
}

}  // namespace detail

Rgba8 composite_source_over(Rgba8 d, Rgba8 s, std::uint8_t coverage) noexcept {
  if (coverage != 255)
    s = {mul_un8(s.r, coverage), mul_un8(s.g, coverage), mul_un8(s.b, coverage), mul_un8(s.a, coverage)};
  const unsigned keep = 255u - s.a;
  return {add_saturated(s.r, mul_un8(d.r, keep)), add_saturated(s.g, mul_un8(d.g, keep)),
          add_saturated(s.b, mul_un8(d.b, keep)), add_saturated(s.a, mul_un8(d.a, keep))};
}

Rgba8 composite_source_over_reference(Rgba8 d, Rgba8 s, std::uint8_t coverage) noexcept {
  const Rgba8 seen{mul_un8_by_division(s.r, coverage), mul_un8_by_division(s.g, coverage),
                   mul_un8_by_division(s.b, coverage), mul_un8_by_division(s.a, coverage)};
  const unsigned keep = 255u - seen.a;
  return {add_saturated(seen.r, mul_un8_by_division(d.r, keep)),
          add_saturated(seen.g, mul_un8_by_division(d.g, keep)),
          add_saturated(seen.b, mul_un8_by_division(d.b, keep)),
          add_saturated(seen.a, mul_un8_by_division(d.a, keep))};
}

}  // namespace curvescan
