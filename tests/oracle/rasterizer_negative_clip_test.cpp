// Regression: a clip box at negative rows (a glyph's box above its baseline, as MaskRenderer uses) made
// bucket_edges_by_row truncate a negative top (-0.5 -> 0) instead of flooring it, compute zero rows and
// write past its buckets (heap overflow under ASan, "double free or corruption" in the glyph benchmark).
#include <catch2/catch.hpp>
#include <map>
#include <vector>

#include "coverage_mask.h"

namespace curvescan::testing {
namespace {

// Spans of a clip at arbitrary (negative) coordinates, keyed by pixel, so optimised and reference agree
// pixel for pixel whatever the origin.
class PixelSink final : public SpanSink {
 public:
  void blend(std::span<const Span> spans) override {
    for (const Span& s : spans)
      for (int i = 0; i < s.len; ++i) coverage[{s.x + i, s.y}] = s.coverage;
  }
  std::map<std::pair<int, int>, int> coverage;
};

std::map<std::pair<int, int>, int> render(const Shape& shape, IntRect clip, bool reference) {
  Rasterizer rasterizer(clip);
  add_shape(rasterizer, shape);
  PixelSink sink;
  if (reference) {
    rasterizer.rasterize_reference(FillRule::kNonZero, Antialias::kExact, sink);
  } else {
    rasterizer.rasterize(FillRule::kNonZero, Antialias::kExact, sink);
  }
  return sink.coverage;
}

}  // namespace

TEST_CASE("rasterizer: clip boxes at negative rows (glyph boxes above the baseline)", "[oracle][regression]") {
  // A triangle wholly above y = 0 with fractional tops, in clips that end at row 0 and above it.
  const Shape triangle{{{1.25, -9.5}, {8.75, -6.25}, {3.5, -0.5}}};
  for (const IntRect clip : {IntRect{0, -10, 10, 0}, IntRect{-3, -12, 12, -1}, IntRect{0, -10, 10, 5}}) {
    INFO("clip y " << clip.y0 << ".." << clip.y1);
    const auto optimised = render(triangle, clip, false);
    const auto reference = render(triangle, clip, true);
    REQUIRE(!optimised.empty());
    REQUIRE(optimised.size() == reference.size());
    for (const auto& [pixel, value] : reference) {
      // The optimised scan may differ from the plain one by one 8-bit rounding step (named_cases_test).
      CHECK(std::abs(optimised.at(pixel) - value) <= 1);
    }
    // Every covered pixel lies in the clip.
    for (const auto& [pixel, value] : optimised) {
      CHECK(pixel.second >= clip.y0);
      CHECK(pixel.second < clip.y1);
    }
  }
}

}  // namespace curvescan::testing
