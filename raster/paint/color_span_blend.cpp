// blend_color_span (color_span_blend.h).
#include "color_span_blend.h"

#include "curvescan/raster/paint.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace curvescan::detail {

void blend_color_span(Rgba8* row, const Rgba8* colors, int len, std::uint8_t coverage) noexcept {
  int i = 0;
#if defined(__SSE2__)
  static_assert(sizeof(Rgba8) == 4, "four bytes per pixel, four pixels per 128-bit register");
  const __m128i zero = _mm_setzero_si128();
  const __m128i half = _mm_set1_epi16(0x80);
  const __m128i times257 = _mm_set1_epi16(257);
  const __m128i full = _mm_set1_epi16(255);
  const __m128i alpha_bytes = _mm_set1_epi32(static_cast<int>(0xff000000u));  // a is the fourth byte
  const __m128i coverage16 = _mm_set1_epi16(static_cast<short>(coverage));
  // mul_un8(x, a) in every 16-bit lane, exactly: see blend_solid_span in composite.cpp.
  const auto mul_un8_lanes = [&](__m128i x, __m128i a) {
    return _mm_mulhi_epu16(_mm_add_epi16(_mm_mullo_epi16(x, a), half), times257);
  };
  // 255 − alpha of each of the two pixels held in 16-bit lanes, in all four lanes of that pixel.
  const auto keep_of = [&](__m128i pixels16) {
    const __m128i alpha = _mm_shufflehi_epi16(_mm_shufflelo_epi16(pixels16, 0xff), 0xff);
    return _mm_sub_epi16(full, alpha);
  };
  for (; i + 4 <= len; i += 4) {
    __m128i source = _mm_loadu_si128(reinterpret_cast<const __m128i*>(colors + i));
    __m128i source_lo = _mm_unpacklo_epi8(source, zero);
    __m128i source_hi = _mm_unpackhi_epi8(source, zero);
    if (coverage != 255) {
      source_lo = mul_un8_lanes(source_lo, coverage16);
      source_hi = mul_un8_lanes(source_hi, coverage16);
      source = _mm_packus_epi16(source_lo, source_hi);
    }
    __m128i* p = reinterpret_cast<__m128i*>(row + i);
    if (_mm_movemask_epi8(_mm_cmpeq_epi8(source, zero)) == 0xffff) continue;  // d' = 0 + d
    if (_mm_movemask_epi8(_mm_cmpeq_epi8(_mm_and_si128(source, alpha_bytes), alpha_bytes)) == 0xffff) {
      _mm_storeu_si128(p, source);  // every s'.a = 255: d' = s' + MUL_UN8(d, 0)
      continue;
    }
    const __m128i d = _mm_loadu_si128(p);
    const __m128i kept_lo = mul_un8_lanes(_mm_unpacklo_epi8(d, zero), keep_of(source_lo));
    const __m128i kept_hi = mul_un8_lanes(_mm_unpackhi_epi8(d, zero), keep_of(source_hi));
    _mm_storeu_si128(p, _mm_adds_epu8(_mm_packus_epi16(kept_lo, kept_hi), source));
  }
#endif
  for (; i < len; ++i) row[i] = composite_source_over(row[i], colors[i], coverage);
}

}  // namespace curvescan::detail
