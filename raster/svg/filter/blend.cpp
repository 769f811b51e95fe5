// feBlend (blend.h).
#include "blend.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace curvescan::svg::detail::filter {
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

}  // namespace

std::optional<BlendMode> parse_blend_mode(std::string_view text) noexcept {
  static constexpr std::array<std::pair<std::string_view, BlendMode>, 16> kModes{{
      {"normal", BlendMode::kNormal},
      {"multiply", BlendMode::kMultiply},
      {"screen", BlendMode::kScreen},
      {"overlay", BlendMode::kOverlay},
      {"darken", BlendMode::kDarken},
      {"lighten", BlendMode::kLighten},
      {"color-dodge", BlendMode::kColorDodge},
      {"color-burn", BlendMode::kColorBurn},
      {"hard-light", BlendMode::kHardLight},
      {"soft-light", BlendMode::kSoftLight},
      {"difference", BlendMode::kDifference},
      {"exclusion", BlendMode::kExclusion},
      {"hue", BlendMode::kHue},
      {"saturation", BlendMode::kSaturation},
      {"color", BlendMode::kColor},
      {"luminosity", BlendMode::kLuminosity},
  }};
  for (const auto& [name, mode] : kModes) {
    if (name == text) return mode;
  }
  return std::nullopt;
}

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

void blend(const FilterImage& in, const FilterImage& in2, BlendMode mode, PixelRect subregion,
           FilterImage& out) noexcept {
  const PixelRect r = subregion.intersect(out.bounds()).intersect(in.bounds()).intersect(in2.bounds());
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) {
      const float* s = in.pixel(x, y);
      const float* b = in2.pixel(x, y);
      float* o = out.pixel(x, y);
      const float as = s[3], ab = b[3];
      float source[3] = {0.0f, 0.0f, 0.0f}, backdrop[3] = {0.0f, 0.0f, 0.0f}, mixed[3];
      for (int c = 0; c < 3; ++c) {
        if (as > 0.0f) source[c] = std::clamp(s[c] / as, 0.0f, 1.0f);
        if (ab > 0.0f) backdrop[c] = std::clamp(b[c] / ab, 0.0f, 1.0f);
      }
      blend_colors(mode, backdrop, source, mixed);
      const float alpha = as + ab - as * ab;
      for (int c = 0; c < 3; ++c) {
        const float value =
            s[c] * (1.0f - ab) + b[c] * (1.0f - as) + as * ab * std::clamp(mixed[c], 0.0f, 1.0f);
        o[c] = std::clamp(value, 0.0f, alpha);
      }
      o[3] = alpha;
    }
  }
}

}  // namespace curvescan::svg::detail::filter
