// feConvolveMatrix (Filter Effects 1, section 15.10). The oracle is the specification's formula evaluated
// directly for each pixel, with the edge modes written out (duplicate: clamp the coordinate; wrap: add or
// subtract the size until inside; none: skip) and the kernel indexed as kernelMatrix[orderX - J - 1,
// orderY - I - 1]. The kernel and the oracle sum the same products in the same order in double; results
// are stored as floats, so channels agree within 1e-6.
#include <catch2/catch.hpp>
#include <chrono>
#include <optional>
#include <random>
#include <sstream>

#include "filter_kernel_support.h"
#include "svg/filter/convolve_matrix.h"

using namespace curvescan;
using namespace curvescan::svg::detail::filter;
using curvescan::svg::testing::compare_images;
using curvescan::svg::testing::PrimitiveXml;
using curvescan::svg::testing::random_image;
using curvescan::svg::testing::same_inside_and_transparent_outside;
using curvescan::svg::testing::transparent_outside;

namespace {

/// The source pixel for (x, y) under `mode` inside `area`, or nullptr for transparent black.
const float* oracle_source(const FilterImage& in, PixelRect area, int x, int y, EdgeMode mode) {
  if (mode == EdgeMode::kNone && !area.contains(x, y)) return nullptr;
  if (mode == EdgeMode::kDuplicate) {
    x = std::min(std::max(x, area.x0), area.x1 - 1);
    y = std::min(std::max(y, area.y0), area.y1 - 1);
  }
  if (mode == EdgeMode::kWrap) {
    while (x < area.x0) x += area.width();
    while (x >= area.x1) x -= area.width();
    while (y < area.y0) y += area.height();
    while (y >= area.y1) y -= area.height();
  }
  return in.pixel(x, y);
}

// `input_area`: where the input exists, whose edge the edge mode extends (by default the subregion).
FilterImage oracle(const ConvolveMatrixParams& p, const FilterImage& in, PixelRect area,
                   std::optional<PixelRect> input_area = std::nullopt) {
  const PixelRect edge = input_area.value_or(area);
  FilterImage out(in.width, in.height);
  for (int y = area.y0; y < area.y1; ++y) {
    for (int x = area.x0; x < area.x1; ++x) {
      double sum[4] = {0, 0, 0, 0};
      for (int i = 0; i < p.order_y; ++i) {
        for (int j = 0; j < p.order_x; ++j) {
          const float* s = oracle_source(in, edge, x - p.target_x + j, y - p.target_y + i, p.edge_mode);
          if (s == nullptr) continue;
          const int column = p.order_x - j - 1, row = p.order_y - i - 1;
          const double k = p.kernel[static_cast<std::size_t>(row * p.order_x + column)];
          for (int c = 0; c < 4; ++c) {
            // preserveAlpha: the colour is convolved unpremultiplied.
            double v = s[c];
            if (p.preserve_alpha && c < 3) v = s[3] > 0.0f ? std::min(1.0, double(s[c]) / s[3]) : 0.0;
            sum[c] += k * v;
          }
        }
      }
      float* o = out.pixel(x, y);
      if (p.preserve_alpha) {
        const float a = in.pixel(x, y)[3];
        for (int c = 0; c < 3; ++c)
          o[c] = static_cast<float>(std::clamp(sum[c] / p.divisor + p.bias, 0.0, 1.0)) * a;
        o[3] = a;
      } else {
        // bias * ALPHA with ALPHA the unclamped result alpha; then alpha to [0, 1], colour to [0, alpha].
        const double raw = sum[3] / p.divisor + p.bias;
        const double a = std::clamp(raw, 0.0, 1.0);
        for (int c = 0; c < 3; ++c)
          o[c] = static_cast<float>(std::clamp(sum[c] / p.divisor + p.bias * raw, 0.0, a));
        o[3] = static_cast<float>(a);
      }
    }
  }
  return out;
}

std::optional<ConvolveMatrixParams> read(const std::string& xml, std::string& error) {
  const PrimitiveXml doc(xml);
  return read_convolve_matrix(doc.element(), error);
}

}  // namespace

TEST_CASE("feConvolveMatrix: matches the formula for every edge mode, target and preserveAlpha",
          "[svg][filter][convolve]") {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> weight(-1.0, 2.0);
  const FilterImage in = random_image(23, 19, 7);
  int cases = 0;
  for (const char* edge : {"duplicate", "wrap", "none"}) {
    for (const auto& [ox, oy] : {std::pair{3, 3}, std::pair{1, 4}, std::pair{5, 2}, std::pair{7, 7}}) {
      for (const bool preserve : {false, true}) {
        std::ostringstream xml;
        xml << "<feConvolveMatrix order=\"" << ox << " " << oy << "\" kernelMatrix=\"";
        for (int i = 0; i < ox * oy; ++i) xml << weight(rng) << " ";
        xml << "\" edgeMode=\"" << edge << "\" targetX=\"" << (ox - 1) << "\" targetY=\"0\" bias=\""
            << (preserve ? 0.1 : -0.05) << "\" preserveAlpha=\"" << (preserve ? "true" : "false") << "\"";
        if (ox == 5) xml << " divisor=\"3.5\"";
        xml << "/>";
        std::string error;
        const auto params = read(xml.str(), error);
        INFO(xml.str() << " " << error);
        REQUIRE(params);
        for (const PixelRect area : {in.bounds(), PixelRect{2, 3, 20, 15}, PixelRect{5, 5, 6, 8}}) {
          FilterImage out(23, 19);
          render_convolve_matrix(*params, FilterSpace{}, area, in, out);
          const auto diff = compare_images(out, oracle(*params, in, area));
          INFO("worst at " << diff.x << "," << diff.y << " channel " << diff.channel);
          CHECK(diff.max_diff <= 1e-6);
          CHECK(transparent_outside(out, area));
          // Only the needed pixels: the same values there (the same arithmetic: exactly), nothing else.
          const PixelRect written{7, 6, 15, 13};
          FilterImage part(23, 19);
          render_convolve_matrix(*params, FilterSpace{}, area, in, part, written);
          CHECK(same_inside_and_transparent_outside(part, out, area.intersect(written)));
          // The input exists beyond the subregion (its own subregion is larger, or smaller): the kernel
          // reads it there, and the edge mode extends it at its own edge.
          for (const PixelRect input_area : {in.bounds(), PixelRect{4, 4, 18, 16}}) {
            FilterImage wide(23, 19);
            render_convolve_matrix(*params, FilterSpace{}, area, in, wide, std::nullopt, input_area);
            const auto beyond = compare_images(wide, oracle(*params, in, area, input_area));
            INFO("input area " << input_area.x0 << "," << input_area.y0 << " worst at " << beyond.x << ","
                               << beyond.y << " channel " << beyond.channel);
            CHECK(beyond.max_diff <= 1e-6);
            CHECK(transparent_outside(wide, area));
          }
          ++cases;
        }
      }
    }
  }
  CHECK(cases == 72);
}

TEST_CASE("feConvolveMatrix: a known kernel on a known image", "[svg][filter][convolve]") {
  // Independent of both implementations: a 3 x 1 kernel "1 2 3" (rotated: weight 3 on the left neighbour,
  // 1 on the right), divisor 6 by default, on an opaque ramp 0, 0.2, 0.4, 0.6 of red.
  FilterImage ramp(4, 1);
  for (int x = 0; x < 4; ++x) {
    ramp.pixel(x, 0)[0] = 0.2f * static_cast<float>(x);
    ramp.pixel(x, 0)[3] = 1.0f;
  }
  std::string error;
  const auto p = read(R"(<feConvolveMatrix order="3 1" kernelMatrix="1 2 3"/>)", error);
  REQUIRE(p);
  CHECK(p->divisor == 6.0);
  CHECK(p->target_x == 1);
  CHECK(p->target_y == 0);
  FilterImage out(4, 1);
  render_convolve_matrix(*p, FilterSpace{}, ramp.bounds(), ramp, out);
  // x = 1: (3 * 0 + 2 * 0.2 + 1 * 0.4) / 6 = 0.8 / 6; x = 0 duplicates the edge: (3*0 + 0 + 0.2) / 6.
  CHECK(out.pixel(1, 0)[0] == Approx(0.8 / 6).margin(1e-6));
  CHECK(out.pixel(0, 0)[0] == Approx(0.2 / 6).margin(1e-6));
  CHECK(out.pixel(1, 0)[3] == Approx(1.0).margin(1e-6));
}

TEST_CASE("feConvolveMatrix: attributes and errors", "[svg][filter][convolve]") {
  std::string error;
  {
    const auto p = read(R"(<feConvolveMatrix order="2" kernelMatrix="1 -1 1 -1" edgeMode="bogus"/>)", error);
    REQUIRE(p);
    CHECK(p->order_x == 2);
    CHECK(p->order_y == 2);
    CHECK(p->divisor == 1.0);  // the sum is 0
    CHECK(p->target_x == 1);
    CHECK(p->edge_mode == EdgeMode::kDuplicate);
    CHECK_FALSE(p->preserve_alpha);
  }
  {
    // Regression: 0.1 * 8 - 0.8 sums to about 1e-16 in binary floating point, not 0; used as the divisor it
    // saturated every pixel. A sum within rounding error of zero is zero: the divisor is 1.
    const auto p = read(R"(<feConvolveMatrix kernelMatrix="0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 -0.8"/>)", error);
    REQUIRE(p);
    double sum = 0.0;
    for (const double k : p->kernel) sum += k;
    CHECK(sum != 0.0);  // the premise: the rounding error exists
    CHECK(p->divisor == 1.0);
  }
  {
    // Filter Effects 1: a non-integer order is truncated towards zero.
    const auto p = read(R"(<feConvolveMatrix order="2.5 1.99" kernelMatrix="1 2"/>)", error);
    REQUIRE(p);
    CHECK(p->order_x == 2);
    CHECK(p->order_y == 1);
  }
  {
    const auto p = read(R"(<feConvolveMatrix kernelMatrix="1 1 1 1 1 1 1 1 1" divisor="0" edgeMode="wrap"
        preserveAlpha="true" kernelUnitLength="2"/>)",
                        error);
    REQUIRE(p);
    CHECK(p->divisor == 9.0);
    CHECK(p->edge_mode == EdgeMode::kWrap);
    CHECK(p->preserve_alpha);
    CHECK(p->kernel_unit_length);
  }
  const char* errors[] = {
      R"(<feConvolveMatrix/>)",                                         // no kernelMatrix
      R"(<feConvolveMatrix kernelMatrix="1 2 3"/>)",                    // 3 numbers for 3 x 3
      R"(<feConvolveMatrix order="0" kernelMatrix=""/>)",               // order 0
      R"(<feConvolveMatrix order="-3" kernelMatrix="1"/>)",             // negative
      R"(<feConvolveMatrix order="0.9" kernelMatrix="1"/>)",            // truncated to 0
      R"(<feConvolveMatrix order="1 1 1" kernelMatrix="1"/>)",          // three numbers
      R"(<feConvolveMatrix order="NaN" kernelMatrix="1"/>)",            // not a number
      R"(<feConvolveMatrix order="1e308" kernelMatrix="1"/>)",          // beyond the cap
      R"(<feConvolveMatrix order="33 1" kernelMatrix="1"/>)",           // beyond the cap
      R"(<feConvolveMatrix order="1" kernelMatrix="1" targetX="1"/>)",  // target outside
      R"(<feConvolveMatrix order="3" kernelMatrix="1 1 1 1 1 1 1 1 1" targetY="-1"/>)",
      R"(<feConvolveMatrix order="3" kernelMatrix="1 1 1 1 1 1 1 1 1" targetX="0.5"/>)",
      R"(<feConvolveMatrix order="1" kernelMatrix="1" kernelUnitLength="-1"/>)",
  };
  for (const char* xml : errors) {
    error.clear();
    INFO(xml);
    CHECK_FALSE(read(xml, error));
    CHECK_FALSE(error.empty());
  }
}

TEST_CASE("feConvolveMatrix: the largest order is bounded and hostile weights stay in range",
          "[svg][filter][convolve]") {
  std::ostringstream xml;
  xml << "<feConvolveMatrix order=\"" << kMaxConvolveOrder << "\" kernelMatrix=\"";
  for (int i = 0; i < kMaxConvolveOrder * kMaxConvolveOrder; ++i) xml << (i % 2 == 0 ? "1e308 " : "-1e308 ");
  xml << "\" edgeMode=\"wrap\"/>";
  std::string error;
  const auto p = read(xml.str(), error);
  REQUIRE(p);
  CHECK(p->divisor == 1.0);  // the sum of +-1e308 is 0
  const FilterImage in = random_image(64, 64, 9);
  FilterImage out(64, 64);
  const auto start = std::chrono::steady_clock::now();
  render_convolve_matrix(*p, FilterSpace{}, in.bounds(), in, out);
  // 4096 pixels x 1024 weights x 4 channels: about 17 million multiply-adds.
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(20));
  for (const float v : out.rgba) REQUIRE((v >= 0.0f && v <= 1.0f));
}
