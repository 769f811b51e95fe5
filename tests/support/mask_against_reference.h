// Test support: a coverage mask (Rasterizer::rasterize_mask, the path of every glyph bitmap) beside the
// plain reference scan (rasterize_reference) of the same edges, pixel by pixel.
#pragma once

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "curvescan/raster/path.h"
#include "curvescan/raster/rasterizer.h"
#include "scan/path_edges.h"

namespace curvescan::testing {

struct MaskComparison {
  int worst = 0;           // largest difference from the reference, in steps of 255
  bool fast_path = false;  // the fill was proven planar: the dense accumulation wrote the mask
  int distinct = 0;        // how many different byte values the mask holds (the scene is not trivial)
};

/// The mask of `path` (flattened at `tolerance`, quadratics by the glyph renderer's uniform steps) over
/// `box` against the reference scan. The mask starts filled with 7, so a byte the mask pass leaves
/// unwritten differs wherever the reference is not within a step of 7.
inline MaskComparison compare_mask_with_reference(const Path& path, IntRect box, FillRule rule,
                                                  double tolerance) {
  Rasterizer rasterizer(box);
  std::vector<Point> scratch;
  detail::add_path_edges(path, tolerance, rasterizer, scratch, SIZE_MAX, detail::QuadraticSteps::kUniform);
  const int width = box.x1 - box.x0;
  const int height = box.y1 - box.y0;
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 7);
  rasterizer.rasterize_mask(rule, mask);
  MaskComparison result;
  result.fast_path = rasterizer.stats().planar_fills != 0;

  // The reference writes spans in device coordinates: shift them into the box.
  struct Shifted final : SpanSink {
    std::vector<std::uint8_t>* values = nullptr;
    IntRect box;
    int violations = 0;
    void blend(std::span<const Span> spans) override {
      const int w = box.x1 - box.x0;
      for (const Span& s : spans) {
        if (s.y < box.y0 || s.y >= box.y1 || s.x < box.x0 || s.x + s.len > box.x1) {
          ++violations;
          continue;
        }
        for (int i = 0; i < s.len; ++i) {
          (*values)[static_cast<std::size_t>(s.y - box.y0) * static_cast<std::size_t>(w) +
                    static_cast<std::size_t>(s.x - box.x0 + i)] = s.coverage;
        }
      }
    }
  } sink;
  std::vector<std::uint8_t> reference(mask.size(), 0);
  sink.values = &reference;
  sink.box = box;
  rasterizer.rasterize_reference(rule, Antialias::kExact, sink);
  REQUIRE(sink.violations == 0);
  bool seen[256] = {};
  for (std::size_t i = 0; i < mask.size(); ++i) {
    result.worst = std::max(result.worst, std::abs(int{mask[i]} - int{reference[i]}));
    seen[mask[i]] = true;
  }
  result.distinct = static_cast<int>(std::count(std::begin(seen), std::end(seen), true));
  return result;
}

}  // namespace curvescan::testing
