// The pixel functions of the filter primitives (Filter Effects 1, section 9) against their formulas,
// written out here per pixel. Values are floats computed from the same formulas in a different order,
// so they agree to float rounding (1e-6 on values in [0, 1], a few ulps of 6e-8).
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "svg/filter/blend.h"
#include "svg/filter/color_matrix.h"
#include "svg/filter/color_space.h"
#include "svg/filter/component_transfer.h"
#include "svg/filter/composite.h"
#include "svg/filter/drop_shadow.h"
#include "svg/filter/filter_surface.h"
#include "svg/filter/flood.h"
#include "svg/filter/offset.h"
#include "svg/filter/tile.h"
#include "svg/painting_properties.h"

using namespace curvescan::svg::detail::filter;

namespace {

constexpr float kTolerance = 1e-6f;

FilterImage random_image(int w, int h, unsigned seed) {
  FilterImage image(w, h);
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float* p = image.pixel(x, y);
      p[3] = unit(random);
      if (x == 0) p[3] = 0.0f;  // a transparent column
      if (x == 1) p[3] = 1.0f;  // an opaque one
      for (int c = 0; c < 3; ++c) p[c] = unit(random) * p[3];
    }
  return image;
}

}  // namespace

TEST_CASE("feFlood fills only the subregion, premultiplied", "[svg][filter]") {
  FilterImage out(8, 8);
  flood(FilterColor{1.0f, 0.5f, 0.0f, 0.5f}, PixelRect{2, 3, 6, 5}, out);
  CHECK(out.pixel(2, 3)[0] == 0.5f);
  CHECK(out.pixel(5, 4)[1] == 0.25f);
  CHECK(out.pixel(5, 4)[3] == 0.5f);
  CHECK(out.pixel(6, 4)[3] == 0.0f);
  CHECK(out.pixel(1, 3)[3] == 0.0f);
}

TEST_CASE("feOffset moves by whole pixels and reads transparent outside the input", "[svg][filter]") {
  const FilterImage in = random_image(10, 10, 3);
  FilterImage out(10, 10);
  offset(in, in.bounds(), 3, -2, out);
  for (int c = 0; c < 4; ++c) CHECK(out.pixel(5, 5)[c] == in.pixel(2, 7)[c]);
  CHECK(out.pixel(1, 5)[3] == 0.0f);  // reads x = -2
  CHECK(out.pixel(5, 9)[3] == 0.0f);  // reads y = 11
  FilterImage far(10, 10);
  offset(in, in.bounds(), 1000000000, 0, far);
  CHECK(far.pixel(5, 5)[3] == 0.0f);
}

TEST_CASE("feOffset in the memory of its own input gives what it gives into a separate image",
          "[svg][filter]") {
  // The filter graph moves an image read for the last time in place: the row order and the overlapping copy
  // within a row must read every pixel before it is overwritten. Exact equality: both copy the same floats.
  const FilterImage in = random_image(12, 9, 7);
  for (const auto& [dx, dy] : {std::pair{3, 2}, std::pair{-3, 2}, std::pair{3, -2}, std::pair{-4, -1},
                               std::pair{0, 3}, std::pair{5, 0}, std::pair{-2, 0}, std::pair{20, -1}}) {
    for (const PixelRect area : {in.bounds(), PixelRect{2, 1, 10, 8}}) {
      FilterImage separate(12, 9);
      offset(in, area, dx, dy, separate);
      FilterImage same = in;
      offset(same, area, dx, dy, same);
      for (int y = area.y0; y < area.y1; ++y)
        for (int x = area.x0; x < area.x1; ++x)
          for (int c = 0; c < 4; ++c) REQUIRE(same.pixel(x, y)[c] == separate.pixel(x, y)[c]);
    }
  }
}

TEST_CASE("feOffset rounds a fractional offset as nearest-pixel sampling at pixel centres does",
          "[svg][filter]") {
  // The oracle: output pixel x reads input pixel floor(x + 0.5 - d), so the shift is x - that, and it must
  // not depend on x. Offsets every 1/8 pixel over [-12, 12] (halves among them), at several x.
  for (int eighths = -96; eighths <= 96; ++eighths) {
    const double d = eighths / 8.0;
    for (const int x : {-3, 0, 5, 17}) {
      const long long sampled = x - static_cast<long long>(std::floor(x + 0.5 - d));
      INFO("d = " << d << ", x = " << x);
      CHECK(whole_pixel_offset(d) == sampled);
    }
  }
  CHECK(whole_pixel_offset(7.5) == 7);  // 5 user units at zoom 1.5
  CHECK(whole_pixel_offset(-7.5) == -8);
  CHECK(whole_pixel_offset(std::nan("")) == 0);
  CHECK(whole_pixel_offset(1e300) == 1000000000);  // clamped: beyond any image
  CHECK(whole_pixel_offset(-1e300) == -1000000000);
}

TEST_CASE("feComposite: every operator by its Porter-Duff formula, arithmetic clamped", "[svg][filter]") {
  const FilterImage a = random_image(6, 6, 4), b = random_image(6, 6, 5);
  struct Case {
    CompositeOperator op;
    float (*formula)(float ac, float aa, float bc, float ba);
  };
  const Case cases[] = {
      {CompositeOperator::kOver, [](float ac, float aa, float bc, float) { return ac + bc * (1 - aa); }},
      {CompositeOperator::kIn, [](float ac, float, float, float ba) { return ac * ba; }},
      {CompositeOperator::kOut, [](float ac, float, float, float ba) { return ac * (1 - ba); }},
      {CompositeOperator::kAtop,
       [](float ac, float aa, float bc, float ba) { return ac * ba + bc * (1 - aa); }},
      {CompositeOperator::kXor,
       [](float ac, float aa, float bc, float ba) { return ac * (1 - ba) + bc * (1 - aa); }},
      {CompositeOperator::kLighter, [](float ac, float, float bc, float) { return std::min(1.0f, ac + bc); }},
  };
  for (const Case& test : cases) {
    FilterImage out(6, 6);
    composite(a, b, CompositeParams{test.op}, a.bounds(), out);
    for (int y = 0; y < 6; ++y)
      for (int x = 0; x < 6; ++x)
        for (int c = 0; c < 4; ++c) {
          const float expected =
              test.formula(a.pixel(x, y)[c], a.pixel(x, y)[3], b.pixel(x, y)[c], b.pixel(x, y)[3]);
          CHECK(out.pixel(x, y)[c] == Approx(expected).margin(kTolerance));
        }
  }
  // arithmetic: k1·A·B + k2·A + k3·B + k4, clamped to [0, 1], colour to alpha.
  const CompositeParams arithmetic{CompositeOperator::kArithmetic, 0.5, 0.7, -0.4, 0.2};
  FilterImage out(6, 6);
  composite(a, b, arithmetic, a.bounds(), out);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 6; ++x) {
      float v[4];
      for (int c = 0; c < 4; ++c) {
        const double r =
            0.5 * a.pixel(x, y)[c] * b.pixel(x, y)[c] + 0.7 * a.pixel(x, y)[c] - 0.4 * b.pixel(x, y)[c] + 0.2;
        v[c] = float(std::min(1.0, std::max(0.0, r)));
      }
      for (int c = 0; c < 3; ++c) v[c] = std::min(v[c], v[3]);
      for (int c = 0; c < 4; ++c) CHECK(out.pixel(x, y)[c] == Approx(v[c]).margin(kTolerance));
    }
}

TEST_CASE("feMerge composites its inputs source-over, first at the bottom", "[svg][filter]") {
  const FilterImage a = random_image(5, 5, 6), b = random_image(5, 5, 7), c3 = random_image(5, 5, 8);
  FilterImage out(5, 5);
  merge({&a, &b, &c3}, a.bounds(), out);
  for (int c = 0; c < 4; ++c) {
    const float ab = b.pixel(3, 2)[c] + a.pixel(3, 2)[c] * (1 - b.pixel(3, 2)[3]);
    const float ab_alpha = b.pixel(3, 2)[3] + a.pixel(3, 2)[3] * (1 - b.pixel(3, 2)[3]);
    (void)ab_alpha;
    const float expected = c3.pixel(3, 2)[c] + ab * (1 - c3.pixel(3, 2)[3]);
    CHECK(out.pixel(3, 2)[c] == Approx(expected).margin(kTolerance));
  }
}

TEST_CASE("feBlend: separable modes by the Compositing 1 formulas", "[svg][filter]") {
  // B(Cb, Cs) per channel, from Compositing and Blending 1, 5.3.
  const auto formula = [](BlendMode mode, double cb, double cs) -> double {
    switch (mode) {
      case BlendMode::kMultiply:
        return cb * cs;
      case BlendMode::kScreen:
        return cb + cs - cb * cs;
      case BlendMode::kDarken:
        return std::min(cb, cs);
      case BlendMode::kLighten:
        return std::max(cb, cs);
      case BlendMode::kDifference:
        return std::fabs(cb - cs);
      case BlendMode::kExclusion:
        return cb + cs - 2 * cb * cs;
      case BlendMode::kOverlay:
        return cb <= 0.5 ? 2 * cs * cb : 1 - 2 * (1 - cs) * (1 - cb);
      case BlendMode::kHardLight:
        return cs <= 0.5 ? 2 * cs * cb : 1 - 2 * (1 - cs) * (1 - cb);
      case BlendMode::kColorDodge:
        return cb == 0 ? 0 : cs >= 1 ? 1 : std::min(1.0, cb / (1 - cs));
      case BlendMode::kColorBurn:
        return cb >= 1 ? 1 : cs <= 0 ? 0 : 1 - std::min(1.0, (1 - cb) / cs);
      case BlendMode::kSoftLight: {
        if (cs <= 0.5) return cb - (1 - 2 * cs) * cb * (1 - cb);
        const double d = cb <= 0.25 ? ((16 * cb - 12) * cb + 4) * cb : std::sqrt(cb);
        return cb + (2 * cs - 1) * (d - cb);
      }
      default:
        return cs;
    }
  };
  const FilterImage s = random_image(6, 6, 9), b = random_image(6, 6, 10);
  for (const BlendMode mode :
       {BlendMode::kNormal, BlendMode::kMultiply, BlendMode::kScreen, BlendMode::kOverlay, BlendMode::kDarken,
        BlendMode::kLighten, BlendMode::kColorDodge, BlendMode::kColorBurn, BlendMode::kHardLight,
        BlendMode::kSoftLight, BlendMode::kDifference, BlendMode::kExclusion}) {
    FilterImage out(6, 6);
    blend(s, b, mode, s.bounds(), out);
    for (int y = 0; y < 6; ++y)
      for (int x = 0; x < 6; ++x) {
        const float* sp = s.pixel(x, y);
        const float* bp = b.pixel(x, y);
        const double as = sp[3], ab = bp[3];
        for (int c = 0; c < 3; ++c) {
          const double Cs = as > 0 ? sp[c] / as : 0, Cb = ab > 0 ? bp[c] / ab : 0;
          const double expected = sp[c] * (1 - ab) + bp[c] * (1 - as) + as * ab * formula(mode, Cb, Cs);
          INFO("mode " << int(mode));
          CHECK(out.pixel(x, y)[c] == Approx(expected).margin(1e-5));  // division by alpha: a few ulps more
        }
        CHECK(out.pixel(x, y)[3] == Approx(as + ab - as * ab).margin(kTolerance));
      }
  }
  CHECK(curvescan::svg::detail::parse_blend_mode("color-dodge") == BlendMode::kColorDodge);
  CHECK(!curvescan::svg::detail::parse_blend_mode("plus-lighter"));
}

TEST_CASE("feBlend: the non-separable modes keep the hue, saturation and luminosity they promise",
          "[svg][filter]") {
  const auto lum = [](const float c[3]) { return 0.3 * c[0] + 0.59 * c[1] + 0.11 * c[2]; };
  // Colours chosen so that no result leaves the gamut (ClipColor would then trade saturation for it).
  const float backdrop[3] = {0.2f, 0.6f, 0.4f}, source[3] = {0.5f, 0.2f, 0.3f};
  float out[3];
  blend_colors(BlendMode::kLuminosity, backdrop, source, out);
  CHECK(lum(out) == Approx(lum(source)).margin(1e-6));  // luminosity of the source
  blend_colors(BlendMode::kColor, backdrop, source, out);
  CHECK(lum(out) == Approx(lum(backdrop)).margin(1e-6));  // luminosity of the backdrop
  blend_colors(BlendMode::kSaturation, backdrop, source, out);
  const auto sat = [](const float c[3]) {
    return std::max({c[0], c[1], c[2]}) - std::min({c[0], c[1], c[2]});
  };
  CHECK(sat(out) == Approx(sat(source)).margin(1e-6));
  CHECK(lum(out) == Approx(lum(backdrop)).margin(1e-6));
  blend_colors(BlendMode::kHue, backdrop, source, out);
  CHECK(lum(out) == Approx(lum(backdrop)).margin(1e-6));
  CHECK(sat(out) == Approx(sat(backdrop)).margin(1e-6));
  // Grey has no hue: hue blending a grey source onto a colour gives a grey of the backdrop's luminosity.
  const float grey[3] = {0.5f, 0.5f, 0.5f};
  blend_colors(BlendMode::kHue, backdrop, grey, out);
  CHECK(out[0] == Approx(out[1]).margin(1e-6));
  CHECK(out[0] == Approx(lum(backdrop)).margin(1e-6));
}

TEST_CASE("feColorMatrix works on unpremultiplied colour, clamps, and builds the spec's matrices",
          "[svg][filter]") {
  const FilterImage in = random_image(6, 6, 11);
  const ColorMatrix m{0.5, 0.2, 0.1, 0.0, 0.1, 0.0, 1.2, 0.0, 0.0, -0.1,
                      0.3, 0.3, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.8, 0.1};
  FilterImage out(6, 6);
  color_matrix(in, m, in.bounds(), out);
  for (int x = 0; x < 6; ++x) {
    const float* p = in.pixel(x, 3);
    const double a = p[3];
    const double v[4] = {a > 0 ? p[0] / a : 0, a > 0 ? p[1] / a : 0, a > 0 ? p[2] / a : 0, a};
    double r[4];
    for (int row = 0; row < 4; ++row) {
      r[row] = m[5 * row] * v[0] + m[5 * row + 1] * v[1] + m[5 * row + 2] * v[2] + m[5 * row + 3] * v[3] +
               m[5 * row + 4];
      r[row] = std::min(1.0, std::max(0.0, r[row]));
    }
    for (int c = 0; c < 3; ++c) CHECK(out.pixel(x, 3)[c] == Approx(r[c] * r[3]).margin(1e-5));
    CHECK(out.pixel(x, 3)[3] == Approx(r[3]).margin(kTolerance));
  }
  // saturate(1) and hueRotate(0) are the identity; hueRotate(360) too.
  const ColorMatrix identity = identity_color_matrix();
  for (std::size_t i = 0; i < 20; ++i) {
    CHECK(saturate_matrix(1.0)[i] == Approx(identity[i]).margin(1e-12));
    CHECK(hue_rotate_matrix(0.0)[i] == Approx(identity[i]).margin(1e-3));  // the spec's 3-digit constants
    CHECK(hue_rotate_matrix(360.0)[i] == Approx(hue_rotate_matrix(0.0)[i]).margin(1e-12));
  }
  // saturate(0): every row the luminance weights 0.213, 0.715, 0.072.
  CHECK(saturate_matrix(0.0)[5] == Approx(0.213));
  CHECK(saturate_matrix(0.0)[11] == Approx(0.715));
  CHECK(luminance_to_alpha_matrix()[15] == 0.2125);
}

TEST_CASE("feComponentTransfer: table, discrete, linear, gamma by the formulas", "[svg][filter]") {
  TransferFunction table;
  table.type = TransferFunction::Type::kTable;
  table.table_values = {0.0, 1.0, 0.5};
  CHECK(table.apply(0.25) == Approx(0.5));   // k = 0: 0 + 0.25·2·(1 - 0)
  CHECK(table.apply(0.75) == Approx(0.75));  // k = 1: 1 + 0.25·2·(0.5 - 1)
  CHECK(table.apply(1.0) == Approx(0.5));
  TransferFunction discrete;
  discrete.type = TransferFunction::Type::kDiscrete;
  discrete.table_values = {0.2, 0.4, 0.8};
  CHECK(discrete.apply(0.0) == Approx(0.2));
  CHECK(discrete.apply(0.34) == Approx(0.4));  // floor(0.34·3) = 1
  CHECK(discrete.apply(1.0) == Approx(0.8));   // k = n - 1 at C = 1
  TransferFunction linear;
  linear.type = TransferFunction::Type::kLinear;
  linear.slope = 2.0;
  linear.intercept = -0.25;
  CHECK(linear.apply(0.5) == Approx(0.75));
  CHECK(linear.apply(0.9) == 1.0);  // clamped
  CHECK(linear.apply(0.1) == 0.0);
  TransferFunction gamma;
  gamma.type = TransferFunction::Type::kGamma;
  gamma.amplitude = 0.8;
  gamma.exponent = 2.0;
  gamma.offset = 0.1;
  CHECK(gamma.apply(0.5) == Approx(0.3));
  TransferFunction empty;
  empty.type = TransferFunction::Type::kTable;
  CHECK(empty.apply(0.3) == Approx(0.3));  // an empty table is the identity
  // On an image: unpremultiplied in, premultiplied out.
  FilterImage in(1, 1);
  float* p = in.pixel(0, 0);
  p[0] = 0.25f, p[1] = 0.1f, p[2] = 0.0f, p[3] = 0.5f;  // colour (0.5, 0.2, 0)
  FilterImage out(1, 1);
  component_transfer(in,
                     TransferFunctions{linear, TransferFunction{}, TransferFunction{}, TransferFunction{}},
                     in.bounds(), out);
  CHECK(out.pixel(0, 0)[0] == Approx(0.75 * 0.5).margin(kTolerance));
  CHECK(out.pixel(0, 0)[1] == Approx(0.1).margin(kTolerance));
}

TEST_CASE("feTile repeats the input's subregion from its own origin", "[svg][filter]") {
  const FilterImage in = random_image(12, 12, 12);
  FilterImage out(12, 12);
  tile(in, PixelRect{2, 3, 5, 5}, in.bounds(), out);  // a 3 x 2 tile at (2, 3)
  for (int c = 0; c < 4; ++c) {
    CHECK(out.pixel(2, 3)[c] == in.pixel(2, 3)[c]);
    CHECK(out.pixel(5, 3)[c] == in.pixel(2, 3)[c]);
    CHECK(out.pixel(1, 2)[c] == in.pixel(4, 4)[c]);  // to the left and above wrap backwards
    CHECK(out.pixel(10, 9)[c] == in.pixel(4, 3)[c]);
  }
}

TEST_CASE("feDropShadow is blur, offset, flood-in and merge", "[svg][filter]") {
  FilterImage in(20, 20);
  for (int y = 5; y < 10; ++y)
    for (int x = 5; x < 10; ++x) {
      float* p = in.pixel(x, y);
      p[0] = 1.0f, p[3] = 1.0f;
    }
  DropShadowParams params;
  params.dx = 6.0;
  params.dy = 6.0;
  params.color = FilterColor{0.0f, 0.0f, 1.0f, 0.5f};
  FilterImage out(20, 20);
  drop_shadow(in, params, in.bounds(), out);
  // Without blur: the source where it is, a half-transparent blue square 6 pixels further.
  CHECK(out.pixel(7, 7)[0] == 1.0f);
  CHECK(out.pixel(13, 13)[2] == 0.5f);
  CHECK(out.pixel(13, 13)[3] == 0.5f);
  CHECK(out.pixel(9, 12)[3] == 0.0f);
  CHECK(out.pixel(11, 11)[3] == 0.5f);
}

TEST_CASE("linearRGB conversions follow the sRGB transfer function and invert each other", "[svg][filter]") {
  CHECK(srgb_to_linear(0.5f) == Approx(0.2140).margin(1e-4));
  CHECK(srgb_to_linear(0.04f) == Approx(0.04 / 12.92).margin(1e-7));
  CHECK(linear_to_srgb(srgb_to_linear(0.7f)) == Approx(0.7f).margin(1e-6));
  FilterImage image(1, 1);
  float* p = image.pixel(0, 0);
  p[0] = 0.25f, p[3] = 0.5f;  // colour 0.5
  convert_color_space(image, ColorSpace::kSrgb, ColorSpace::kLinearRgb);
  // The table interpolates linearly between 4096 samples: error below 2e-5 (the second derivative of the
  // curve is at most ~13 near 0.04, times (1/4096)^2 / 8).
  CHECK(image.pixel(0, 0)[0] == Approx(srgb_to_linear(0.5f) * 0.5f).margin(2e-5));
  convert_color_space(image, ColorSpace::kLinearRgb, ColorSpace::kSrgb);
  CHECK(image.pixel(0, 0)[0] == Approx(0.25f).margin(2e-5));
  CHECK(image.pixel(0, 0)[3] == 0.5f);
}

TEST_CASE("to_image from linearRGB gives the bytes of converting the image first, then quantizing",
          "[svg][filter]") {
  // The fused path converts a row at a time with the same arithmetic (convert_pixels): no tolerance.
  FilterImage image = random_image(37, 11, 7);
  image.extent = PixelRect{2, 1, 30, 10};  // only the extent is converted and written
  FilterImage converted = image;
  convert_color_space(converted, ColorSpace::kLinearRgb, ColorSpace::kSrgb);
  const curvescan::Image fused = to_image(image, ColorSpace::kLinearRgb);
  const curvescan::Image separate = to_image(converted);
  CHECK(fused.pixels() == separate.pixels());
  CHECK(fused.at(0, 0) == curvescan::Rgba8{});  // outside the extent
  CHECK(to_image(image, ColorSpace::kSrgb).pixels() == to_image(image).pixels());
}
