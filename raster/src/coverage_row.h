// CoverageRow: exact-area accumulation for one pixel row, after font-rs and FreeType's "cells".
//
// The row is the strip y..y+1 of the clip box. Each call to add_boundary() adds one straight piece of the
// boundary of the (already rule-resolved) filled region, inside a horizontal band of the strip, with sign
// +1 where the region starts to its right ("enter") and -1 where it ends ("leave"). For every pixel column c
// the piece adds the area of the band inside [c, c+1] lying to the right of the piece; the sum over the
// pieces of one band is then the area of the union of the disjoint trapezoids between enter and leave
// pieces, which is the area of the filled region inside the pixel.
//
// Storage is the classic accumulation buffer: acc[c] holds cover(c) - cover(c-1), so a prefix sum across
// the row gives the coverage, and a piece touches only the columns it crosses plus one (font-rs's
// accumulate; Raph Levien, "Inside the fastest font renderer in the world", 2016). Memory is one double per
// column of the clip, whatever the area of the shape.
#pragma once

#include <cstdint>
#include <vector>

#include "curvescan/raster/span.h"

namespace curvescan::detail {

class CoverageRow {
 public:
  /// Prepares for rows of `width` pixels starting at device column `x0`; keeps capacity. O(1) when the
  /// width is unchanged and the last row was emitted (emit() leaves the buffer zero): a fill of a small
  /// shape does not pay for the width of the clip.
  void reset(int x0, int width);

  /// Adds the boundary piece from (xa, top of band) to (xb, bottom of band), band height h > 0,
  /// device x in [x0, x0 + width]. sign: +1 enter, -1 leave. Exact up to double rounding.
  void add_boundary(double xa, double xb, double h, double sign) noexcept;

  /// Converts the accumulated coverage of row `y` to 8-bit spans (round(area·255), area clamped to
  /// [0, 1] only against rounding), appends the non-zero ones to `out`, and clears the row.
  void emit(int y, std::vector<Span>& out);

  /// The plain per-pixel form of emit(): appends the 8-bit coverage of every column, zeros included
  /// (used by the reference path and its tests), and clears the row.
  void emit_all(std::vector<unsigned char>& out);

 private:
  void touch(int cell) noexcept { touched_[static_cast<std::size_t>(cell) >> 6] |= std::uint64_t{1} << (cell & 63); }

  // True from the first add_boundary() of a row until it is emitted: only then can acc_ hold non-zeros.
  bool dirty_ = false;
  std::vector<double> acc_;  // width + 2 entries: columns 0..width-1, the right side, and one past it
  // One bit per cell of acc_ that was written since the last emit: emit() visits only those (the coverage
  // is constant between them), skipping 64 untouched columns per word inside and between shapes.
  std::vector<std::uint64_t> touched_;
  int x0_ = 0;
  int width_ = 0;
};

/// 8-bit coverage of an area in [0, 1]: round(area·255), with area clamped against rounding noise.
[[nodiscard]] inline unsigned char coverage_to_u8(double area) noexcept {
  const double clamped = area < 0.0 ? 0.0 : (area > 1.0 ? 1.0 : area);
  return static_cast<unsigned char>(clamped * 255.0 + 0.5);
}

}  // namespace curvescan::detail
