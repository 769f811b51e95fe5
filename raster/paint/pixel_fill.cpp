// fill_pixels (pixel_fill.h).
#include "pixel_fill.h"

#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace curvescan::detail {

void fill_pixels(Rgba8* first, std::size_t count, Rgba8 color) noexcept {
  static_assert(sizeof(Rgba8) == 4, "four bytes per pixel");
  if (color.r == color.g && color.g == color.b && color.b == color.a) {
    std::memset(static_cast<void*>(first), color.r, count * sizeof(Rgba8));
    return;
  }
  std::uint32_t word = 0;
  std::memcpy(&word, &color, sizeof word);
#if defined(__x86_64__) && defined(__GNUC__)
  if (count >= kStringStorePixels) {
    // The ABI guarantees the direction flag is clear on entry, so the string store runs upwards.
    void* destination = first;
    asm volatile("rep stosl" : "+D"(destination), "+c"(count) : "a"(word) : "memory");
    return;
  }
#endif
  std::size_t i = 0;
#if defined(__SSE2__)
  const __m128i four = _mm_set1_epi32(static_cast<int>(word));
  for (; i + 16 <= count; i += 16) {
    __m128i* p = reinterpret_cast<__m128i*>(first + i);
    _mm_storeu_si128(p, four);
    _mm_storeu_si128(p + 1, four);
    _mm_storeu_si128(p + 2, four);
    _mm_storeu_si128(p + 3, four);
  }
  for (; i + 4 <= count; i += 4) _mm_storeu_si128(reinterpret_cast<__m128i*>(first + i), four);
#endif
  for (; i < count; ++i) first[i] = color;
}

}  // namespace curvescan::detail
