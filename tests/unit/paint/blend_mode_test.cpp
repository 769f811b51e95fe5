// mix-blend-mode's pixel function (layer.h, blend_source_over) against the formulas of CSS Compositing and
// Blending 1 written out again here in double, straight from the specification's pseudo-code (section
// 10.1 and 10.2 for B, section 5.1 for the compositing): random premultiplied colours, every mode.
// Tolerance: one 8-bit step (the implementation computes in float and rounds once; the oracle rounds the
// double result, so the two may land on either side of a rounding midpoint).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>

#include "curvescan/raster/layer.h"

using namespace curvescan;

namespace {

struct Colour {
  double r, g, b;
};

double lum(Colour c) { return 0.3 * c.r + 0.59 * c.g + 0.11 * c.b; }

Colour clip_color(Colour c) {
  const double l = lum(c);
  const double n = std::min({c.r, c.g, c.b});
  const double x = std::max({c.r, c.g, c.b});
  auto fix = [&](double v) {
    if (n < 0.0) v = l + (((v - l) * l) / (l - n));
    if (x > 1.0) v = l + (((v - l) * (1.0 - l)) / (x - l));
    return v;
  };
  return {fix(c.r), fix(c.g), fix(c.b)};
}

Colour set_lum(Colour c, double l) {
  const double d = l - lum(c);
  return clip_color({c.r + d, c.g + d, c.b + d});
}

double sat(Colour c) { return std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b}); }

// The specification's SetSat: Cmax, Cmid, Cmin by value.
Colour set_sat(Colour c, double s) {
  double* channels[3] = {&c.r, &c.g, &c.b};
  std::sort(channels, channels + 3, [](double* a, double* b) { return *a < *b; });
  double& cmin = *channels[0];
  double& cmid = *channels[1];
  double& cmax = *channels[2];
  if (cmax > cmin) {
    cmid = (((cmid - cmin) * s) / (cmax - cmin));
    cmax = s;
  } else {
    cmid = cmax = 0.0;
  }
  cmin = 0.0;
  return c;
}

double separable(BlendMode mode, double cb, double cs) {
  switch (mode) {
    case BlendMode::kNormal: return cs;
    case BlendMode::kMultiply: return cb * cs;
    case BlendMode::kScreen: return cb + cs - (cb * cs);
    case BlendMode::kOverlay:  // HardLight(Cs, Cb)
      return cb <= 0.5 ? cs * 2.0 * cb : cs + (2.0 * cb - 1.0) - cs * (2.0 * cb - 1.0);
    case BlendMode::kDarken: return std::min(cb, cs);
    case BlendMode::kLighten: return std::max(cb, cs);
    case BlendMode::kColorDodge:
      if (cb == 0.0) return 0.0;
      if (cs == 1.0) return 1.0;
      return std::min(1.0, cb / (1.0 - cs));
    case BlendMode::kColorBurn:
      if (cb == 1.0) return 1.0;
      if (cs == 0.0) return 0.0;
      return 1.0 - std::min(1.0, (1.0 - cb) / cs);
    case BlendMode::kHardLight:
      return cs <= 0.5 ? cb * 2.0 * cs : cb + (2.0 * cs - 1.0) - cb * (2.0 * cs - 1.0);
    case BlendMode::kSoftLight: {
      if (cs <= 0.5) return cb - (1.0 - 2.0 * cs) * cb * (1.0 - cb);
      const double d = cb <= 0.25 ? ((16.0 * cb - 12.0) * cb + 4.0) * cb : std::sqrt(cb);
      return cb + (2.0 * cs - 1.0) * (d - cb);
    }
    case BlendMode::kDifference: return std::abs(cb - cs);
    case BlendMode::kExclusion: return cb + cs - 2.0 * cb * cs;
    default: return 0.0;
  }
}

Colour blend(BlendMode mode, Colour cb, Colour cs) {
  switch (mode) {
    case BlendMode::kHue: return set_lum(set_sat(cs, sat(cb)), lum(cb));
    case BlendMode::kSaturation: return set_lum(set_sat(cb, sat(cs)), lum(cb));
    case BlendMode::kColor: return set_lum(cs, lum(cb));
    case BlendMode::kLuminosity: return set_lum(cb, lum(cs));
    default: return {separable(mode, cb.r, cs.r), separable(mode, cb.g, cs.g), separable(mode, cb.b, cs.b)};
  }
}

Rgba8 oracle(Rgba8 backdrop, Rgba8 source, int coverage, BlendMode mode) {
  const double k = coverage / 255.0;
  const double as = source.a / 255.0 * k;
  const double ab = backdrop.a / 255.0;
  const Colour cs_pre{source.r / 255.0 * k, source.g / 255.0 * k, source.b / 255.0 * k};
  const Colour cb_pre{backdrop.r / 255.0, backdrop.g / 255.0, backdrop.b / 255.0};
  Colour mixed{0, 0, 0};
  if (as > 0.0 && ab > 0.0) {
    mixed = blend(mode, {cb_pre.r / ab, cb_pre.g / ab, cb_pre.b / ab}, {cs_pre.r / as, cs_pre.g / as, cs_pre.b / as});
  }
  auto channel = [&](double cs, double cb, double m) {
    const double co = cs * (1.0 - ab) + cb * (1.0 - as) + as * ab * m;
    return static_cast<std::uint8_t>(std::clamp(co, 0.0, 1.0) * 255.0 + 0.5);
  };
  const auto alpha = static_cast<std::uint8_t>(std::clamp(as + ab * (1.0 - as), 0.0, 1.0) * 255.0 + 0.5);
  return {std::min(channel(cs_pre.r, cb_pre.r, mixed.r), alpha), std::min(channel(cs_pre.g, cb_pre.g, mixed.g), alpha),
          std::min(channel(cs_pre.b, cb_pre.b, mixed.b), alpha), alpha};
}

Rgba8 random_premultiplied(std::mt19937& rng) {
  std::uniform_int_distribution<int> byte(0, 255);
  const int a = (rng() % 4 == 0) ? 255 : byte(rng);  // opaque often: the common case
  std::uniform_int_distribution<int> channel(0, a);
  return {static_cast<std::uint8_t>(channel(rng)), static_cast<std::uint8_t>(channel(rng)),
          static_cast<std::uint8_t>(channel(rng)), static_cast<std::uint8_t>(a)};
}

}  // namespace

TEST_CASE("blend_source_over follows the specification's formulas for every blend mode", "[paint][blend]") {
  std::mt19937 rng(2611);
  for (int m = 0; m <= static_cast<int>(BlendMode::kLuminosity); ++m) {
    const auto mode = static_cast<BlendMode>(m);
    for (int i = 0; i < 4000; ++i) {
      const Rgba8 backdrop = random_premultiplied(rng);
      const Rgba8 source = random_premultiplied(rng);
      const int coverage = (i % 3 == 0) ? 255 : static_cast<int>(rng() % 256);
      const Rgba8 got = blend_source_over(backdrop, source, static_cast<std::uint8_t>(coverage), mode);
      const Rgba8 want = oracle(backdrop, source, coverage, mode);
      INFO("mode " << m << " backdrop " << int{backdrop.r} << "," << int{backdrop.g} << "," << int{backdrop.b} << ","
                   << int{backdrop.a} << " source " << int{source.r} << "," << int{source.g} << "," << int{source.b}
                   << "," << int{source.a} << " coverage " << coverage);
      REQUIRE(std::abs(got.r - want.r) <= 1);
      REQUIRE(std::abs(got.g - want.g) <= 1);
      REQUIRE(std::abs(got.b - want.b) <= 1);
      REQUIRE(std::abs(got.a - want.a) <= 1);
      REQUIRE(got.r <= got.a);
      REQUIRE(got.g <= got.a);
      REQUIRE(got.b <= got.a);
    }
  }
}

TEST_CASE("blend modes on known colours", "[paint][blend]") {
  const Rgba8 red{255, 0, 0, 255};
  const Rgba8 grey{128, 128, 128, 255};
  const Rgba8 blue{0, 0, 255, 255};
  // Multiply with white keeps the backdrop; with red over blue, nothing is left (black).
  CHECK(blend_source_over(red, Rgba8{255, 255, 255, 255}, 255, BlendMode::kMultiply) == red);
  CHECK(blend_source_over(blue, red, 255, BlendMode::kMultiply) == Rgba8{0, 0, 0, 255});
  // Screen of red and blue: magenta. Difference of a colour with itself: black.
  CHECK(blend_source_over(blue, red, 255, BlendMode::kScreen) == Rgba8{255, 0, 255, 255});
  CHECK(blend_source_over(grey, grey, 255, BlendMode::kDifference) == Rgba8{0, 0, 0, 255});
  // Over a transparent backdrop every mode is plain source-over (αb = 0 leaves cs).
  CHECK(blend_source_over(Rgba8{}, red, 255, BlendMode::kDifference) == red);
  // Luminosity of grey over red: red's hue at grey's luminance, (0.5, 0.5, 0.5) has lum 0.502.
  const Rgba8 l = blend_source_over(red, grey, 255, BlendMode::kLuminosity);
  CHECK(std::abs(0.3 * l.r + 0.59 * l.g + 0.11 * l.b - 128.0) <= 2.0);  // luminance kept within rounding
  CHECK(l.r > l.g);
}
