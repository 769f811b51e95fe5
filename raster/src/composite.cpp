// Compositing of a solid premultiplied colour with coverage: pixman's OVER with an A8 mask, per pixel.
//
// pixman (pixman-combine32.h) computes x·a/255 rounded to nearest without a division as
//   t = x·a + 0x80;  (t + (t >> 8)) >> 8
// which is exact for x, a in [0, 255] (Blinn, "Three Wrongs Make a Right", IEEE CG&A 1995). The reference
// below divides instead; composite_test.cpp checks that the two agree on every input that matters.
#include "curvescan/raster/paint.h"

namespace curvescan {
namespace {

constexpr std::uint8_t mul_un8(unsigned x, unsigned a) noexcept {
  const unsigned t = x * a + 0x80u;
  return static_cast<std::uint8_t>((t + (t >> 8)) >> 8);
}

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
