// Test support: the oracle tests' check that the whole-fill sweep (raster/scan/rasterizer_planar.cpp) took a
// shape, for the spans and for the coverage mask, and matched the plain reference scan under both fill rules.
//
// Metric: the sweep sums the same exact area as the reference scan in another order, so an area within
// ~1e-12 of a rounding midpoint may round either way: at most 1 step of 255 per pixel.
#pragma once

#include <catch2/catch.hpp>
#include <cstdint>

#include "coverage_mask.h"

namespace curvescan::testing {

/// What a swept shape must also show besides matching the reference.
enum class SweptCrossings { kAny, kSome };

/// Under both rules: the sweep took `shape` (planar_fills == 1 for the spans and for the mask) and matched
/// the reference within 1 step; with kSome it also resolved at least one crossing under each rule.
/// Returns the crossings resolved by the span scans.
inline std::uint64_t check_swept(const Shape& shape, IntRect clip,
                                 SweptCrossings crossings_expected = SweptCrossings::kAny) {
  std::uint64_t crossings = 0;
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const SpanAndMaskComparison run = compare_spans_and_mask_with_reference(shape, rule, clip);
    INFO((rule == FillRule::kNonZero ? "nonzero" : "even-odd")
         << ", sweep crossings " << run.stats.sweep_crossings);
    CHECK(run.stats.planar_fills == 1);
    CHECK(run.mask_planar_fills == 1);
    if (crossings_expected == SweptCrossings::kSome) CHECK(run.stats.sweep_crossings > 0);
    CHECK(run.max_diff <= 1);
    CHECK(run.mask_max_diff <= 1);
    CHECK(run.violations == 0);
    crossings += run.stats.sweep_crossings;
  }
  return crossings;
}

}  // namespace curvescan::testing
