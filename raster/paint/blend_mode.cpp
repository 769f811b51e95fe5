// The blend modes of CSS Compositing and Blending 1 (section 10, "Blending"), for mix-blend-mode and
// feBlend (the filter primitive calls blend_colors on its float pixels): the
// separable modes channel by channel, the non-separable ones (hue, saturation, color, luminosity) through
// the specification's Lum / ClipColor / SetLum / Sat / SetSat helpers, then source-over (section 5.1).
// Computed in float on unpremultiplied colours and rounded once; group compositing is not a hot path
// (one pass per blended group), so clarity wins over 8-bit tricks here.
#include <algorithm>
#include <array>
#include <cmath>

#include "curvescan/raster/layer.h"

namespace curvescan {
namespace {

float separable(BlendMode mode, float cb, float cs) noexcept {
  switch (mode) {
    case BlendMode::kNormal:
      return cs;
    case BlendMode::kMultiply:
      return cb * cs;
    case BlendMode::kScreen:
      return cb + cs - cb * cs;
    case BlendMode::kOverlay:  // HardLight(Cs, Cb)
      return separable(BlendMode::kHardLight, cs, cb);
    case BlendMode::kDarken:
      return std::min(cb, cs);
    case BlendMode::kLighten:
      return std::max(cb, cs);
    case BlendMode::kColorDodge:
      if (cb == 0.0f) return 0.0f;
      if (cs >= 1.0f) return 1.0f;
      return std::min(1.0f, cb / (1.0f - cs));
    case BlendMode::kColorBurn:
      if (cb >= 1.0f) return 1.0f;
      if (cs <= 0.0f) return 0.0f;
      return 1.0f - std::min(1.0f, (1.0f - cb) / cs);
    case BlendMode::kHardLight:
      return cs <= 0.5f ? cb * 2.0f * cs : separable(BlendMode::kScreen, cb, 2.0f * cs - 1.0f);
    case BlendMode::kSoftLight: {
      if (cs <= 0.5f) return cb - (1.0f - 2.0f * cs) * cb * (1.0f - cb);
      const float d = cb <= 0.25f ? ((16.0f * cb - 12.0f) * cb + 4.0f) * cb : std::sqrt(cb);
      return cb + (2.0f * cs - 1.0f) * (d - cb);
    }
    case BlendMode::kDifference:
      return std::fabs(cb - cs);
    case BlendMode::kExclusion:
      return cb + cs - 2.0f * cb * cs;
    default:
      return cs;
  }
}

using Rgb = std::array<float, 3>;

float lum(const Rgb& c) noexcept {
  return 0.3f * c[0] + 0.59f * c[1] + 0.11f * c[2];
}

Rgb clip_color(Rgb c) noexcept {
  const float l = lum(c);
  const float n = std::min({c[0], c[1], c[2]}), x = std::max({c[0], c[1], c[2]});
  for (float& v : c) {
    if (n < 0.0f && l - n != 0.0f) v = l + (v - l) * l / (l - n);
    if (x > 1.0f && x - l != 0.0f) v = l + (v - l) * (1.0f - l) / (x - l);
  }
  return c;
}

Rgb set_lum(Rgb c, float l) noexcept {
  const float d = l - lum(c);
  for (float& v : c) v += d;
  return clip_color(c);
}

float sat(const Rgb& c) noexcept {
  return std::max({c[0], c[1], c[2]}) - std::min({c[0], c[1], c[2]});
}

Rgb set_sat(Rgb c, float s) noexcept {
  // Compositing 1, 5.7: Cmax, Cmid and Cmin of C, found by index so that ties keep the spec's order.
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int i, int j) { return c[i] < c[j]; });
  float& cmin = c[order[0]];
  float& cmid = c[order[1]];
  float& cmax = c[order[2]];
  if (cmax > cmin) {
    cmid = (cmid - cmin) * s / (cmax - cmin);
    cmax = s;
  } else {
    cmid = cmax = 0.0f;
  }
  cmin = 0.0f;
  return c;
}


std::uint8_t to_u8(float v) noexcept {
  return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
}

}  // namespace

void blend_colors(BlendMode mode, const float backdrop[3], const float source[3], float result[3]) noexcept {
  const Rgb cb{backdrop[0], backdrop[1], backdrop[2]}, cs{source[0], source[1], source[2]};
  Rgb out;
  switch (mode) {
    case BlendMode::kHue:
      out = set_lum(set_sat(cs, sat(cb)), lum(cb));
      break;
    case BlendMode::kSaturation:
      out = set_lum(set_sat(cb, sat(cs)), lum(cb));
      break;
    case BlendMode::kColor:
      out = set_lum(cs, lum(cb));
      break;
    case BlendMode::kLuminosity:
      out = set_lum(cb, lum(cs));
      break;
    default:
      for (int c = 0; c < 3; ++c) out[c] = separable(mode, cb[c], cs[c]);
  }
  for (int c = 0; c < 3; ++c) result[c] = out[c];
}

Rgba8 blend_source_over(Rgba8 backdrop, Rgba8 source, std::uint8_t coverage, BlendMode mode) noexcept {
  const float k = coverage / 255.0f;
  const float as = source.a / 255.0f * k;
  const float ab = backdrop.a / 255.0f;
  if (as == 0.0f) return backdrop;
  const Rgb cs_premultiplied{source.r / 255.0f * k, source.g / 255.0f * k, source.b / 255.0f * k};
  const Rgb cb_premultiplied{backdrop.r / 255.0f, backdrop.g / 255.0f, backdrop.b / 255.0f};
  Rgb mixed{0.0f, 0.0f, 0.0f};
  if (ab > 0.0f) {
    const Rgb cs{cs_premultiplied[0] / as, cs_premultiplied[1] / as, cs_premultiplied[2] / as};
    const Rgb cb{cb_premultiplied[0] / ab, cb_premultiplied[1] / ab, cb_premultiplied[2] / ab};
    blend_colors(mode, cb.data(), cs.data(), mixed.data());
  }
  Rgba8 out;
  std::uint8_t* channels[3] = {&out.r, &out.g, &out.b};
  for (int i = 0; i < 3; ++i) {
    const float co = cs_premultiplied[i] * (1.0f - ab) + cb_premultiplied[i] * (1.0f - as) + as * ab * mixed[i];
    *channels[i] = to_u8(co);
  }
  const float ao = as + ab * (1.0f - as);
  out.a = to_u8(ao);
  // Premultiplied: no channel above alpha (rounding of a blend near 1 could give one).
  out.r = std::min(out.r, out.a);
  out.g = std::min(out.g, out.a);
  out.b = std::min(out.b, out.a);
  return out;
}

}  // namespace curvescan
