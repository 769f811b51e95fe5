#include "curvescan/raster/pixel_format.h"

namespace curvescan {
namespace {

// c·255/a rounded to nearest, clamped to 255 (premultiplied colours from other producers may exceed a).
constexpr std::uint8_t div_un8(unsigned c, unsigned a) noexcept {
  const unsigned q = (c * 255u + a / 2u) / a;
  return static_cast<std::uint8_t>(q > 255u ? 255u : q);
}

}  // namespace

Rgba8 premultiply(StraightRgba8 p) noexcept {
  return {mul_un8(p.r, p.a), mul_un8(p.g, p.a), mul_un8(p.b, p.a), p.a};
}

StraightRgba8 unpremultiply(Rgba8 p) noexcept {
  if (p.a == 0) return {0, 0, 0, 0};
  return {div_un8(p.r, p.a), div_un8(p.g, p.a), div_un8(p.b, p.a), p.a};
}

}  // namespace curvescan
