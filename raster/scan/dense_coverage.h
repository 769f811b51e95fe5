// DenseCoverage: exact-area accumulation for a whole pixel box at once, written out as an 8-bit mask.
//
// CoverageRow accumulates one row at a time and hands it on as spans, visiting only the cells a piece
// touched: right for a canvas, where the compositor wants runs. A coverage mask (a glyph bitmap) wants
// every pixel of a small box instead, so here every row of the box has its own accumulation row, each
// boundary piece is added once to the rows it crosses (no per-row bookkeeping of live pieces or touched
// cells), and one pass per row turns the prefix sums into bytes — four columns at a time with SSE2, the
// accumulate of font-rs (Raph Levien, "Inside the fastest font renderer in the world", 2016).
//
// The cells are floats: half the memory traffic of doubles and four lanes per SSE register. What that
// costs: each cell holds a sum of a few piece contributions, each rounded to 2^-24 relative, and the
// prefix sum across a row of w columns adds at most w roundings of partial sums in [-1, 2]; the box is
// limited to kMaxWidth columns, so the coverage of a pixel is off by less than 4096 · 2 · 2^-24 < 5e-4,
// an eighth of one 8-bit step (which can still move a value that sits on a rounding midpoint by one step).
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "coverage_row.h"

namespace curvescan::detail {

class DenseCoverage {
 public:
  /// The widest and largest box accumulated densely (the float error bound above, and a memory cap of
  /// 16 MiB of cells); larger fills take the row scan.
  static constexpr int kMaxWidth = 4096;
  static constexpr std::int64_t kMaxPixels = std::int64_t{1} << 22;

  [[nodiscard]] static bool fits(int width, int height) noexcept {
    return width <= kMaxWidth && std::int64_t{width} * height <= kMaxPixels;
  }

  /// Prepares a box of `width` x `height` pixels whose top-left pixel is device (x0, y0); the box must
  /// fit(). All cells are zero (write_mask leaves them so).
  void reset(int x0, int y0, int width, int height);

  /// Adds the boundary piece from (xa, ya) to (xb, yb), device coordinates, ya < yb, inside one pixel row
  /// of the box (floor(ya) == row, yb <= row + 1), with sign +1 (the filled region starts right of it) or
  /// -1 (it ends there). x is clamped to the box against rounding.
  void add_piece(int row, double xa, double xb, double h, double sign) noexcept {
    const double width = width_;
    const auto r = static_cast<std::size_t>(row - y0_);
    accumulate_piece(cells_.data() + r * stride_, std::clamp(xa - x0_, 0.0, width),
                     std::clamp(xb - x0_, 0.0, width), h, sign);
  }

  /// Writes round(255 · coverage) of every pixel of the box into `mask` (row-major, width · height
  /// bytes) and clears the cells.
  void write_mask(std::span<std::uint8_t> mask) noexcept;

 private:
  std::vector<float> cells_;  // height rows of stride_ = width + 2 cells (the right side and one past it)
  int x0_ = 0;
  int y0_ = 0;
  int width_ = 0;
  int height_ = 0;
  std::size_t stride_ = 2;
};

}  // namespace curvescan::detail
