// Compositing and paint: pixman-style MUL_UN8 compositing held to a plain division reference, and the
// colour conversions of Paint.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "curvescan/raster/paint.h"

using namespace curvescan;

namespace {

std::uint8_t u8(int v) {
  return static_cast<std::uint8_t>(v);
}

}  // namespace

TEST_CASE("composite_source_over equals its division reference on every (channel, alpha, coverage)",
          "[composite]") {
  // Exhaustive over the factors that meet in each MUL_UN8: a grey source (c, a) with c <= a, every
  // coverage, on a few destinations. 2^15 sources x 256 coverages x 4 destinations ~ 3.4e7 blends.
  const Rgba8 destinations[] = {{0, 0, 0, 0}, {255, 255, 255, 255}, {10, 200, 37, 201}, {1, 0, 1, 1}};
  for (int a = 0; a <= 255; a += 1) {
    for (int c = 0; c <= a; ++c) {
      const Rgba8 source{u8(c), u8(a - c), u8(c / 2), u8(a)};
      for (int m = 0; m <= 255; ++m) {
        for (const Rgba8 d : destinations) {
          const Rgba8 fast = composite_source_over(d, source, u8(m));
          const Rgba8 reference = composite_source_over_reference(d, source, u8(m));
          if (!(fast == reference)) {
            CAPTURE(a, c, m, d.r, d.g, d.b, d.a);
            REQUIRE(fast == reference);
          }
        }
      }
    }
  }
}

TEST_CASE("composite_source_over: identities of source-over", "[composite]") {
  std::mt19937 rng(31337);
  std::uniform_int_distribution<int> byte(0, 255);
  for (int trial = 0; trial < 100000; ++trial) {
    const int da = byte(rng), sa = byte(rng);
    const Rgba8 d{u8(byte(rng) * da / 255), u8(byte(rng) * da / 255), u8(byte(rng) * da / 255), u8(da)};
    const Rgba8 s{u8(byte(rng) * sa / 255), u8(byte(rng) * sa / 255), u8(byte(rng) * sa / 255), u8(sa)};
    CHECK(composite_source_over(d, s, 0) == d);                              // no coverage: untouched
    CHECK(composite_source_over(d, Rgba8{0, 0, 0, 0}, u8(byte(rng))) == d);  // transparent source
    const Rgba8 opaque{s.r, s.g, s.b, 255};
    CHECK(composite_source_over(d, opaque, 255) == opaque);  // opaque and fully covered: replaces
    const Rgba8 out = composite_source_over(d, s, u8(byte(rng)));
    // Premultiplied stays valid: colour <= alpha (pixman's rounding keeps it so for valid inputs).
    CHECK(out.r <= out.a);
    CHECK(out.g <= out.a);
    CHECK(out.b <= out.a);
  }
}

TEST_CASE("Color::from_rgba8 paints its 8-bit channels, premultiplied as Cairo does", "[paint]") {
  // Opaque: c/255·65535 = c·257, whose high byte is c again, so every opaque 8-bit colour is kept.
  for (int c = 0; c <= 255; ++c) {
    const auto v = static_cast<std::uint8_t>(c);
    CHECK(Paint::solid(Color::from_rgba8(v, v, v)).color == Rgba8{v, v, v, 255});
  }
  // Translucent: c16 = floor(c/255 · a/255 · 65535 + 0.5) = floor(c·a·257/255 + 0.5), byte c16 >> 8.
  // 255,128 -> 32896 >> 8 = 128; 128,128 -> 16513 >> 8 = 64; 1,128 -> 129 >> 8 = 0; alpha 128 -> 128.
  CHECK(Paint::solid(Color::from_rgba8(255, 128, 1, 128)).color == Rgba8{128, 64, 0, 128});
  CHECK(Paint::solid(Color::from_rgba8(200, 100, 50, 0)).color == Rgba8{0, 0, 0, 0});
  CHECK(Paint::solid(Color::from_rgba8(1, 2, 3)).is_opaque());
}

TEST_CASE("Paint::solid converts doubles as Cairo does, clamping and zeroing NaN", "[paint]") {
  // c16 = floor(c·a·65535 + 0.5), byte = c16 >> 8: 1.0 -> 255, 0.5 -> 32768 >> 8 = 128.
  CHECK(Paint::solid({1.0, 0.5, 0.0, 1.0}).color == Rgba8{255, 128, 0, 255});
  // Premultiplied: 0.5·0.5 = 0.25 -> 16384 >> 8 = 64; alpha 0.5 -> 128.
  CHECK(Paint::solid({0.5, 1.0, 0.0, 0.5}).color == Rgba8{64, 128, 0, 128});
  // The high byte of the 16-bit value: 0.995 -> 65207 >> 8 = 254; 0.6 -> 39321 >> 8 = 153.
  CHECK(Paint::solid({0.995, 0.6, 0.0, 1.0}).color == Rgba8{254, 153, 0, 255});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(Paint::solid({2.0, -1.0, nan, 1.0}).color == Rgba8{255, 0, 0, 255});
  CHECK(Paint::solid({1.0, 1.0, 1.0, nan}).color == Rgba8{0, 0, 0, 0});
  // Valid premultiplied output for every alpha.
  for (int i = 0; i <= 1000; ++i) {
    const double a = i / 1000.0;
    const Rgba8 c = Paint::solid({1.0, 0.3, 0.7, a}).color;
    CHECK(c.r <= c.a);
  }
}
