// feTurbulence (Filter Effects 1, section 15.26). The oracle is the specification's reference C code,
// transcribed plainly below (global tables, int lattice coordinates, the same statement order), with one
// documented change: the lattice cell is reduced modulo 256 after the stitching comparison, not before
// (see turbulence.cpp; without stitching the two orders are the same). The kernel must agree with it to
// float precision: both evaluate the same double expressions, and the kernel stores floats, so the
// tolerance is 1e-6 (about 8 float ulps at 1.0).
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>

#include "filter_kernel_support.h"
#include "svg/filter/turbulence.h"

using namespace curvescan;
using namespace curvescan::svg::detail::filter;
using curvescan::svg::testing::compare_images;
using curvescan::svg::testing::PrimitiveXml;
using curvescan::svg::testing::transparent_outside;

namespace {

// ---- The reference code of the specification, transcribed. ----
namespace reference {

constexpr int BSize = 0x100;
constexpr int BM = 0xff;
constexpr int PerlinN = 0x1000;
int uLatticeSelector[BSize + BSize + 2];
double fGradient[4][BSize + BSize + 2][2];
struct StitchInfo {
  int nWidth, nHeight, nWrapX, nWrapY;
};
constexpr long RAND_m = 2147483647;
constexpr long RAND_a = 16807;
constexpr long RAND_q = 127773;
constexpr long RAND_r = 2836;

long setup_seed(long lSeed) {
  if (lSeed <= 0) lSeed = -(lSeed % (RAND_m - 1)) + 1;
  if (lSeed > RAND_m - 1) lSeed = RAND_m - 1;
  return lSeed;
}
long random(long lSeed) {
  long result = RAND_a * (lSeed % RAND_q) - RAND_r * (lSeed / RAND_q);
  if (result <= 0) result += RAND_m;
  return result;
}
void init(long lSeed) {
  double s;
  int i, j, k;
  lSeed = setup_seed(lSeed);
  for (k = 0; k < 4; k++) {
    for (i = 0; i < BSize; i++) {
      uLatticeSelector[i] = i;
      for (j = 0; j < 2; j++)
        fGradient[k][i][j] = static_cast<double>(((lSeed = random(lSeed)) % (BSize + BSize)) - BSize) / BSize;
      s = double(
          std::sqrt(fGradient[k][i][0] * fGradient[k][i][0] + fGradient[k][i][1] * fGradient[k][i][1]));
      fGradient[k][i][0] /= s;
      fGradient[k][i][1] /= s;
    }
  }
  while (--i) {
    k = uLatticeSelector[i];
    uLatticeSelector[i] = uLatticeSelector[j = static_cast<int>((lSeed = random(lSeed)) % BSize)];
    uLatticeSelector[j] = k;
  }
  for (i = 0; i < BSize + 2; i++) {
    uLatticeSelector[BSize + i] = uLatticeSelector[i];
    for (k = 0; k < 4; k++)
      for (j = 0; j < 2; j++) fGradient[k][BSize + i][j] = fGradient[k][i][j];
  }
}
double s_curve(double t) {
  return t * t * (3. - 2. * t);
}
double lerp(double t, double a, double b) {
  return a + t * (b - a);
}
double noise2(int nColorChannel, double vec[2], StitchInfo* pStitchInfo) {
  int bx0, bx1, by0, by1, b00, b10, b01, b11;
  double rx0, rx1, ry0, ry1, *q, sx, sy, a, b, t, u, v;
  int i, j;
  t = vec[0] + PerlinN;
  bx0 = static_cast<int>(t);  // the reference masks with BM here; see the file comment
  bx1 = bx0 + 1;
  rx0 = t - static_cast<int>(t);
  rx1 = rx0 - 1.0f;
  t = vec[1] + PerlinN;
  by0 = static_cast<int>(t);
  by1 = by0 + 1;
  ry0 = t - static_cast<int>(t);
  ry1 = ry0 - 1.0f;
  if (pStitchInfo != nullptr) {
    if (bx0 >= pStitchInfo->nWrapX) bx0 -= pStitchInfo->nWidth;
    if (bx1 >= pStitchInfo->nWrapX) bx1 -= pStitchInfo->nWidth;
    if (by0 >= pStitchInfo->nWrapY) by0 -= pStitchInfo->nHeight;
    if (by1 >= pStitchInfo->nWrapY) by1 -= pStitchInfo->nHeight;
  }
  bx0 &= BM;
  bx1 &= BM;
  by0 &= BM;
  by1 &= BM;
  i = uLatticeSelector[bx0];
  j = uLatticeSelector[bx1];
  b00 = uLatticeSelector[i + by0];
  b10 = uLatticeSelector[j + by0];
  b01 = uLatticeSelector[i + by1];
  b11 = uLatticeSelector[j + by1];
  sx = double(s_curve(rx0));
  sy = double(s_curve(ry0));
  q = fGradient[nColorChannel][b00];
  u = rx0 * q[0] + ry0 * q[1];
  q = fGradient[nColorChannel][b10];
  v = rx1 * q[0] + ry0 * q[1];
  a = lerp(sx, u, v);
  q = fGradient[nColorChannel][b01];
  u = rx0 * q[0] + ry1 * q[1];
  q = fGradient[nColorChannel][b11];
  v = rx1 * q[0] + ry1 * q[1];
  b = lerp(sx, u, v);
  return lerp(sy, a, b);
}
double turbulence(int nColorChannel, double* point, double fBaseFreqX, double fBaseFreqY, int nNumOctaves,
                  bool bFractalSum, bool bDoStitching, double fTileX, double fTileY, double fTileWidth,
                  double fTileHeight) {
  StitchInfo stitch;
  StitchInfo* pStitchInfo = nullptr;
  if (bDoStitching) {
    if (fBaseFreqX != 0.0) {
      double fLoFreq = double(std::floor(fTileWidth * fBaseFreqX)) / fTileWidth;
      double fHiFreq = double(std::ceil(fTileWidth * fBaseFreqX)) / fTileWidth;
      if (fBaseFreqX / fLoFreq < fHiFreq / fBaseFreqX)
        fBaseFreqX = fLoFreq;
      else
        fBaseFreqX = fHiFreq;
    }
    if (fBaseFreqY != 0.0) {
      double fLoFreq = double(std::floor(fTileHeight * fBaseFreqY)) / fTileHeight;
      double fHiFreq = double(std::ceil(fTileHeight * fBaseFreqY)) / fTileHeight;
      if (fBaseFreqY / fLoFreq < fHiFreq / fBaseFreqY)
        fBaseFreqY = fLoFreq;
      else
        fBaseFreqY = fHiFreq;
    }
    pStitchInfo = &stitch;
    stitch.nWidth = int(fTileWidth * fBaseFreqX + 0.5f);
    stitch.nWrapX = static_cast<int>(fTileX * fBaseFreqX + PerlinN + stitch.nWidth);
    stitch.nHeight = int(fTileHeight * fBaseFreqY + 0.5f);
    stitch.nWrapY = static_cast<int>(fTileY * fBaseFreqY + PerlinN + stitch.nHeight);
  }
  double fSum = 0.0f;
  double vec[2];
  vec[0] = point[0] * fBaseFreqX;
  vec[1] = point[1] * fBaseFreqY;
  double ratio = 1;
  for (int nOctave = 0; nOctave < nNumOctaves; nOctave++) {
    if (bFractalSum)
      fSum += double(noise2(nColorChannel, vec, pStitchInfo) / ratio);
    else
      fSum += double(std::fabs(noise2(nColorChannel, vec, pStitchInfo)) / ratio);
    vec[0] *= 2;
    vec[1] *= 2;
    ratio *= 2;
    if (pStitchInfo != nullptr) {
      stitch.nWidth *= 2;
      stitch.nWrapX = 2 * stitch.nWrapX - PerlinN;
      stitch.nHeight *= 2;
      stitch.nWrapY = 2 * stitch.nWrapY - PerlinN;
    }
  }
  return fSum;
}

}  // namespace reference

/// The whole image the oracle way: for each pixel the four channels at the user point of its top-left
/// corner, mapped to colour as the specification says ((sum + 1) / 2 for fractalNoise), clamped and
/// premultiplied.
FilterImage oracle_image(const TurbulenceParams& p, const FilterSpace& space, PixelRect area, int width,
                         int height) {
  reference::init(static_cast<long>(p.seed));
  FilterImage image(width, height);
  const double tile_x = space.origin_x + area.x0 / space.scale_x,
               tile_y = space.origin_y + area.y0 / space.scale_y;
  const double tile_w = area.width() / space.scale_x, tile_h = area.height() / space.scale_y;
  for (int y = area.y0; y < area.y1; ++y) {
    for (int x = area.x0; x < area.x1; ++x) {
      double point[2] = {space.origin_x + x / space.scale_x, space.origin_y + y / space.scale_y};
      double rgba[4];
      for (int c = 0; c < 4; ++c) {
        const double sum =
            reference::turbulence(c, point, p.base_frequency_x, p.base_frequency_y, p.num_octaves,
                                  p.fractal_noise, p.stitch_tiles, tile_x, tile_y, tile_w, tile_h);
        rgba[c] = std::clamp(p.fractal_noise ? (sum * 255.0 + 255.0) / 2.0 / 255.0 : sum, 0.0, 1.0);
      }
      float* out = image.pixel(x, y);
      for (int c = 0; c < 3; ++c) out[c] = static_cast<float>(rgba[c] * rgba[3]);
      out[3] = static_cast<float>(rgba[3]);
    }
  }
  return image;
}

TurbulenceParams read_ok(const std::string& xml) {
  const PrimitiveXml doc(xml);
  std::string error;
  const auto params = read_turbulence(doc.element(), error);
  INFO(xml << " -> " << error);
  REQUIRE(params);
  CHECK(error.empty());
  return *params;
}

}  // namespace

TEST_CASE("feTurbulence: the kernel reproduces the specification's reference code",
          "[svg][filter][turbulence]") {
  struct Case {
    const char* xml;
    FilterSpace space;
    PixelRect area;
  };
  FilterSpace scaled;
  scaled.scale_x = 2.0;
  scaled.scale_y = 1.5;
  scaled.origin_x = -7.25;
  scaled.origin_y = 13.0;
  const Case cases[] = {
      {R"(<feTurbulence baseFrequency="0.05" numOctaves="2" seed="0"/>)", FilterSpace{}, {0, 0, 48, 40}},
      {R"(<feTurbulence type="fractalNoise" baseFrequency="0.03 0.09" numOctaves="4" seed="7"/>)",
       FilterSpace{},
       {3, 5, 45, 37}},
      {R"(<feTurbulence type="fractalNoise" baseFrequency="0.02" numOctaves="3" seed="-12.7"/>)",
       scaled,
       {0, 0, 48, 40}},
      {R"(<feTurbulence baseFrequency="0.1" numOctaves="1" seed="1e9" stitchTiles="stitch"/>)",
       FilterSpace{},
       {4, 2, 37, 31}},
      {R"(<feTurbulence type="fractalNoise" baseFrequency="0.047 0.013" numOctaves="5" seed="3"
          stitchTiles="stitch"/>)",
       scaled,
       {1, 1, 47, 39}},
  };
  for (const Case& c : cases) {
    const TurbulenceParams params = read_ok(c.xml);
    FilterImage out(48, 40);
    render_turbulence(params, c.space, c.area, out);
    const FilterImage expected = oracle_image(params, c.space, c.area, 48, 40);
    const auto diff = compare_images(out, expected);
    INFO(c.xml << " worst at " << diff.x << "," << diff.y << " channel " << diff.channel);
    CHECK(diff.max_diff <= 1e-6);
    CHECK(transparent_outside(out, c.area));
  }
}

TEST_CASE("feTurbulence: noise is not trivial and depends on seed, type and frequency",
          "[svg][filter][turbulence]") {
  // Guards against an oracle and kernel that agree on a constant: the pattern must vary across the image
  // and change with each parameter.
  const auto render = [](const std::string& xml) {
    FilterImage out(32, 32);
    render_turbulence(read_ok(xml), FilterSpace{}, {0, 0, 32, 32}, out);
    return out;
  };
  const FilterImage a = render(R"(<feTurbulence baseFrequency="0.1" numOctaves="2" seed="1"/>)");
  float lo = 1.0f, hi = 0.0f;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) lo = std::min(lo, a.pixel(x, y)[3]), hi = std::max(hi, a.pixel(x, y)[3]);
  CHECK(hi - lo > 0.2f);
  CHECK(compare_images(a, render(R"(<feTurbulence baseFrequency="0.1" numOctaves="2" seed="2"/>)")).max_diff >
        0.1);
  CHECK(compare_images(
            a, render(R"(<feTurbulence type="fractalNoise" baseFrequency="0.1" numOctaves="2" seed="1"/>)"))
            .max_diff > 0.1);
  // Seeds are truncated towards zero: 1.9 is seed 1, -0.9 is seed 0 (same as the default).
  CHECK(compare_images(a, render(R"(<feTurbulence baseFrequency="0.1" numOctaves="2" seed="1.9"/>)"))
            .max_diff == 0.0);
  CHECK(compare_images(render(R"(<feTurbulence baseFrequency="0.1" seed="-0.9"/>)"),
                       render(R"(<feTurbulence baseFrequency="0.1"/>)"))
            .max_diff == 0.0);
}

TEST_CASE("feTurbulence: with stitchTiles the tile's opposite edges continue each other",
          "[svg][filter][turbulence]") {
  // With stitching, the first octave's lattice wraps after exactly the tile: the noise at a point of the
  // tile equals the noise one tile width to the right (the oracle evaluated outside the tile). Checked on
  // the reference code itself with the kernel's adjusted frequencies, then the kernel is held to the
  // reference inside the tile by the first test.
  const TurbulenceParams params = read_ok(R"(<feTurbulence baseFrequency="0.0625" numOctaves="1" seed="5"
      stitchTiles="stitch"/>)");
  reference::init(params.seed);
  const double tile_w = 32.0, tile_h = 32.0;
  for (double y = 0.5; y < 32.0; y += 3.0) {
    double p[2] = {1.5, y};
    double q[2] = {1.5 + tile_w, y};
    const double a = reference::turbulence(0, p, 0.0625, 0.0625, 1, true, true, 0, 0, tile_w, tile_h);
    const double b = reference::turbulence(0, q, 0.0625, 0.0625, 1, true, true, 0, 0, tile_w, tile_h);
    CHECK(a == Approx(b).margin(1e-12));  // the same lattice cell and the same fraction, up to rounding
  }
  // And without stitching the values one tile apart differ (so the check above is not vacuous).
  double p[2] = {1.5, 7.5}, q[2] = {33.5, 7.5};
  CHECK(std::fabs(reference::turbulence(0, p, 0.0625, 0.0625, 1, true, false, 0, 0, tile_w, tile_h) -
                  reference::turbulence(0, q, 0.0625, 0.0625, 1, true, false, 0, 0, tile_w, tile_h)) > 1e-3);
}

TEST_CASE("feTurbulence: attributes, lacuna values and errors", "[svg][filter][turbulence]") {
  const TurbulenceParams defaults = read_ok("<feTurbulence/>");
  CHECK(defaults.base_frequency_x == 0.0);
  CHECK(defaults.base_frequency_y == 0.0);
  CHECK(defaults.num_octaves == 1);
  CHECK(defaults.seed == 0);
  CHECK_FALSE(defaults.stitch_tiles);
  CHECK_FALSE(defaults.fractal_noise);

  const TurbulenceParams two = read_ok(R"(<feTurbulence baseFrequency="0.1, 0.2" type="fractalNoise"
      stitchTiles="stitch" numOctaves="3" seed="-4.6"/>)");
  CHECK(two.base_frequency_x == 0.1);
  CHECK(two.base_frequency_y == 0.2);
  CHECK(two.fractal_noise);
  CHECK(two.stitch_tiles);
  CHECK(two.num_octaves == 3);
  CHECK(two.seed == -4);

  // Unparsable values take the lacuna values.
  const TurbulenceParams junk = read_ok(R"(<feTurbulence baseFrequency="0.1 0.2 0.3" numOctaves="2.5"
      seed="NaN" type="Turbulence" stitchTiles="yes"/>)");
  CHECK(junk.base_frequency_x == 0.0);
  CHECK(junk.num_octaves == 1);
  CHECK(junk.seed == 0);
  CHECK_FALSE(junk.fractal_noise);
  CHECK_FALSE(junk.stitch_tiles);

  for (const char* xml :
       {R"(<feTurbulence baseFrequency="-0.1"/>)", R"(<feTurbulence baseFrequency="0.1 -1e-9"/>)"}) {
    const PrimitiveXml doc(xml);
    std::string error;
    CHECK_FALSE(read_turbulence(doc.element(), error));
    CHECK(error.find("baseFrequency") != std::string::npos);
  }
}

TEST_CASE("feTurbulence: hostile numbers are bounded and fast", "[svg][filter][turbulence]") {
  const TurbulenceParams huge =
      read_ok(R"(<feTurbulence numOctaves="1e308" seed="1e308" baseFrequency="1e308"/>)");
  CHECK(huge.num_octaves == kMaxTurbulenceOctaves);
  const TurbulenceParams negative =
      read_ok(R"(<feTurbulence numOctaves="-5" seed="-1e308" baseFrequency="0.1"/>)");
  CHECK(negative.num_octaves == 0);

  FilterSpace far;
  far.origin_x = 1e15;  // user coordinates beyond the int range of the reference code
  far.origin_y = -1e15;
  const auto start = std::chrono::steady_clock::now();
  for (const TurbulenceParams& p : {huge, negative}) {
    for (const FilterSpace& space : {FilterSpace{}, far}) {
      TurbulenceParams stitched = p;
      stitched.stitch_tiles = true;
      for (const TurbulenceParams& q : {p, stitched}) {
        FilterImage out(64, 64);
        render_turbulence(q, space, {0, 0, 64, 64}, out);
        for (const float v : out.rgba) REQUIRE((v >= 0.0f && v <= 1.0f));
      }
    }
  }
  // Zero octaves: turbulence is transparent black; fractalNoise is 50 % grey at 50 % alpha.
  FilterImage zero(4, 4);
  TurbulenceParams fractal = negative;
  fractal.fractal_noise = true;
  render_turbulence(fractal, FilterSpace{}, {0, 0, 4, 4}, zero);
  CHECK(zero.pixel(2, 2)[3] == 0.5f);
  CHECK(zero.pixel(2, 2)[0] == 0.25f);
  // 8 renders of 64 x 64 pixels at up to 24 octaves: well under a second even unoptimized.
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(20));
}
