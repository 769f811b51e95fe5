// Test support: polygons as lists of contours, and 8-bit coverage masks rendered by curvescan.
//
// A MaskSink also checks the SpanSink contract (rows top to bottom, left to right, no overlap, inside the
// clip, no zero coverage), so every test that renders through it checks the contract too.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <span>
#include <vector>

#include "curvescan/curves/point.h"
#include "curvescan/raster/rasterizer.h"

namespace curvescan::testing {

/// A closed contour (the last point joins the first) and a shape made of contours.
using Contour = std::vector<Point>;
using Shape = std::vector<Contour>;

/// 8-bit coverage, row-major, width x height.
struct CoverageMask {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> values;

  CoverageMask() = default;
  CoverageMask(int w, int h) : width(w), height(h), values(static_cast<std::size_t>(w) * h, 0) {}
  [[nodiscard]] std::uint8_t at(int x, int y) const {
    return values[static_cast<std::size_t>(y) * width + x];
  }
  [[nodiscard]] std::uint8_t& at(int x, int y) { return values[static_cast<std::size_t>(y) * width + x]; }
  [[nodiscard]] double total() const {
    double sum = 0.0;
    for (const std::uint8_t v : values) sum += v;
    return sum / 255.0;
  }
};

/// Writes spans into a mask and counts violations of the SpanSink contract.
class MaskSink final : public SpanSink {
 public:
  explicit MaskSink(CoverageMask& mask) : mask_(mask) {}
  void blend(std::span<const Span> spans) override {
    for (const Span& s : spans) {
      const bool inside =
          s.len > 0 && s.y >= 0 && s.y < mask_.height && s.x >= 0 && s.x + s.len <= mask_.width;
      const bool ordered = s.y > last_y_ || (s.y == last_y_ && s.x >= last_end_);
      if (!inside || !ordered || s.coverage == 0) {
        ++violations;
        continue;
      }
      for (int i = 0; i < s.len; ++i) mask_.at(s.x + i, s.y) = s.coverage;
      last_y_ = s.y;
      last_end_ = s.x + s.len;
      ++span_count;
    }
  }
  int violations = 0;
  long span_count = 0;

 private:
  CoverageMask& mask_;
  int last_y_ = -1;
  int last_end_ = 0;
};

/// Adds every edge of `shape` (contours closed) to `rasterizer`.
inline void add_shape(Rasterizer& rasterizer, const Shape& shape) {
  for (const Contour& contour : shape) {
    for (std::size_t i = 0; i < contour.size(); ++i) {
      rasterizer.add_line(contour[i], contour[(i + 1) % contour.size()]);
    }
  }
}

enum class ScanPath { kOptimised, kReference };

/// Renders `shape` with curvescan into a width x height mask (clip = the canvas).
inline CoverageMask render_curvescan(const Shape& shape, int width, int height, FillRule rule,
                                     Antialias antialias = Antialias::kExact,
                                     ScanPath path = ScanPath::kOptimised, int* violations = nullptr) {
  CoverageMask mask(width, height);
  Rasterizer rasterizer(IntRect{0, 0, width, height});
  add_shape(rasterizer, shape);
  MaskSink sink(mask);
  if (path == ScanPath::kOptimised) {
    rasterizer.rasterize(rule, antialias, sink);
  } else {
    rasterizer.rasterize_reference(rule, antialias, sink);
  }
  if (violations != nullptr) *violations = sink.violations;
  return mask;
}

/// Largest absolute difference between two masks of the same size, in 8-bit steps.
inline int max_abs_diff(const CoverageMask& a, const CoverageMask& b) {
  int worst = 0;
  for (std::size_t i = 0; i < a.values.size(); ++i)
    worst = std::max(worst, std::abs(a.values[i] - b.values[i]));
  return worst;
}

/// One fill of `shape` on a width x height mask, by the scan (rasterize) and by the reference scan
/// (rasterize_reference) on the same edges: the largest difference, the sink contract violations of both,
/// and the scan's statistics (which path it took). The whole-fill sweep's crossing budget
/// (Rasterizer::set_sweep_crossing_budget) is 0 unless given: the comparison is then of the row scan, which
/// a crossing fill takes when that budget runs out.
struct ReferenceComparison {
  int max_diff = 0;
  int violations = 0;
  RasterizerStats stats;
};

inline ReferenceComparison compare_with_reference(const Shape& shape, int width, int height, FillRule rule,
                                                  double sweep_crossing_budget = 0.0) {
  ReferenceComparison out;
  Rasterizer rasterizer(IntRect{0, 0, width, height});
  rasterizer.set_sweep_crossing_budget(sweep_crossing_budget);
  add_shape(rasterizer, shape);
  CoverageMask fast(width, height);
  MaskSink fast_sink(fast);
  rasterizer.rasterize(rule, Antialias::kExact, fast_sink);
  out.stats = rasterizer.stats();
  CoverageMask reference(width, height);
  MaskSink reference_sink(reference);
  rasterizer.rasterize_reference(rule, Antialias::kExact, reference_sink);
  out.max_diff = max_abs_diff(fast, reference);
  out.violations = fast_sink.violations + reference_sink.violations;
  return out;
}

/// One fill of `shape` over `clip` (whose origin is the mask's) three ways on the same edges: the scan
/// (rasterize), the plain reference scan (rasterize_reference) and the mask pass (rasterize_mask, the path
/// of glyph bitmaps: the dense accumulation where the fill is proven planar). The mask starts at 0x5a, so
/// a byte the mask pass leaves unwritten differs from the reference. `sweep_crossing_budget` as in
/// Rasterizer::set_sweep_crossing_budget; without it, the rasterizer's own.
struct SpanAndMaskComparison {
  int max_diff = 0;                     // rasterize (spans) against the reference
  int mask_max_diff = 0;                // rasterize_mask against the reference
  int violations = 0;                   // the sink contract, both span scans
  RasterizerStats stats;                // the span scan's: which path it took
  std::uint64_t mask_planar_fills = 0;  // the mask pass's planar fills
};

inline SpanAndMaskComparison compare_spans_and_mask_with_reference(
    const Shape& shape, FillRule rule, IntRect clip,
    std::optional<double> sweep_crossing_budget = std::nullopt) {
  SpanAndMaskComparison out;
  Rasterizer rasterizer(clip);
  if (sweep_crossing_budget) rasterizer.set_sweep_crossing_budget(*sweep_crossing_budget);
  add_shape(rasterizer, shape);
  CoverageMask fast(clip.x1, clip.y1);
  MaskSink fast_sink(fast);
  rasterizer.rasterize(rule, Antialias::kExact, fast_sink);
  out.stats = rasterizer.stats();
  CoverageMask reference(clip.x1, clip.y1);
  MaskSink reference_sink(reference);
  rasterizer.rasterize_reference(rule, Antialias::kExact, reference_sink);
  out.max_diff = max_abs_diff(fast, reference);
  out.violations = fast_sink.violations + reference_sink.violations;
  CoverageMask dense(clip.x1, clip.y1);
  std::fill(dense.values.begin(), dense.values.end(), std::uint8_t{0x5a});
  rasterizer.rasterize_mask(rule, dense.values);
  out.mask_planar_fills = rasterizer.stats().planar_fills;
  out.mask_max_diff = max_abs_diff(dense, reference);
  return out;
}

}  // namespace curvescan::testing
