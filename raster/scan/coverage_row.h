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

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "curvescan/raster/rasterizer.h"

namespace curvescan::detail {

/// The several-columns case of accumulate_piece (below), kept out of line so that the common one-column
/// case inlines into the callers' loops: u0 < u1, c0 < c1 the first and last column the piece enters.
template <class Cell>
void accumulate_piece_across(Cell* acc, double u0, double u1, int c0, int c1, double h, double sign) noexcept {
  // Cut the piece at each column line. Heights are proportional to the x travelled (dy/dx constant); the
  // last part takes the rest of h so that the row sum is h exactly.
  const double dydx = h / (u1 - u0);
  const double first_x = static_cast<double>(c0 + 1) - u0;
  double h_used = std::min(first_x * dydx, h);
  double area = 0.5 * h_used * first_x;  // triangle right of the piece inside column c0
  acc[c0] += static_cast<Cell>(sign * area);
  acc[c0 + 1] += static_cast<Cell>(sign * (h_used - area));
  const double full = std::min(dydx, h);
  for (int c = c0 + 1; c < c1; ++c) {
    const double part = std::min(full, h - h_used);
    acc[c] += static_cast<Cell>(sign * 0.5 * part);
    acc[c + 1] += static_cast<Cell>(sign * 0.5 * part);
    h_used += part;
  }
  const double last = std::max(h - h_used, 0.0);
  const double last_x = u1 - static_cast<double>(c1);
  area = last * (1.0 - 0.5 * last_x);
  acc[c1] += static_cast<Cell>(sign * area);
  acc[c1 + 1] += static_cast<Cell>(sign * (last - area));
}

/// The arithmetic of CoverageRow::add_boundary, shared with the dense accumulation (dense_coverage.h):
/// adds to the accumulation row `acc` (acc[c] = cover(c) - cover(c - 1)) the area right of the straight
/// piece from column coordinate ua at the top of a band of height h > 0 to ub at its bottom, with `sign`,
/// where 0 <= ua, ub <= width of the row. Writes acc[c0 .. c1 + 1], c0 and c1 the first and last column
/// the piece enters, and returns them. Exact up to double rounding (Cell = double) or up to float rounding
/// of each cell's sum (Cell = float).
template <class Cell>
inline std::pair<int, int> accumulate_piece(Cell* acc, double ua, double ub, double h, double sign) noexcept {
  // The area right of a straight piece inside one column does not change when the piece is flipped
  // upside down, so order the ends left to right.
  const double u0 = ua < ub ? ua : ub;
  const double u1 = ua < ub ? ub : ua;
  const int c0 = static_cast<int>(u0);
  // Last column the piece really enters: a piece ending exactly on a column line does not enter the
  // column to the right of it.
  int c1 = static_cast<int>(u1);
  if (c1 > c0 && static_cast<double>(c1) == u1) --c1;
  if (c0 != c1) {
    accumulate_piece_across(acc, u0, u1, c0, c1, h, sign);
    return {c0, c1};
  }
  // One column: the part right of the piece is a trapezoid of height h whose left side runs from u0 to
  // u1, so its area is h·(c0 + 1 - mean(u0, u1)); the rest of h carries to the next column.
  const double area = h * (static_cast<double>(c0 + 1) - 0.5 * (u0 + u1));
  acc[c0] += static_cast<Cell>(sign * area);
  acc[c0 + 1] += static_cast<Cell>(sign * (h - area));
  return {c0, c1};
}

/// 8-bit coverage of an area in [0, 1]: round(area·255), with area clamped against rounding noise.
[[nodiscard]] inline unsigned char coverage_to_u8(double area) noexcept {
  const double clamped = area < 0.0 ? 0.0 : (area > 1.0 ? 1.0 : area);
  return static_cast<unsigned char>(clamped * 255.0 + 0.5);
}

class CoverageRow {
 public:
  /// Prepares for rows of `width` pixels starting at device column `x0`; keeps capacity. O(1) when the
  /// width is unchanged and the last row was emitted (emit() leaves the buffer zero): a fill of a small
  /// shape does not pay for the width of the clip.
  void reset(int x0, int width);

  /// Adds the boundary piece from (xa, top of band) to (xb, bottom of band), band height h > 0,
  /// device x in [x0, x0 + width]. sign: +1 enter, -1 leave. Exact up to double rounding.
  void add_boundary(double xa, double xb, double h, double sign) noexcept;

  /// add_boundary for the consecutive pieces of one boundary chain inside the row (the planar path).
  /// Pieces that stay inside one column are summed before they reach the row: inside a column the area
  /// right of a piece is h·(c + 1 - mean x), additive over pieces, so a run of short pieces in one
  /// column (the side of a finely flattened curve) writes two cells once instead of once per piece (the
  /// same area, summed in another order). end_chain() must follow the chain's last piece in the row,
  /// before any add_boundary() or emit().
  void add_chain_piece(double xa, double xb, double h, double sign) noexcept {
    const double width = width_;
    // Callers pass clipped x; the clamp only guards against rounding.
    const double ua = std::clamp(xa - x0_, 0.0, width);
    const double ub = std::clamp(xb - x0_, 0.0, width);
    const double u0 = ua < ub ? ua : ub;
    const double u1 = ua < ub ? ub : ua;
    const int c0 = static_cast<int>(u0);
    int c1 = static_cast<int>(u1);
    if (c1 > c0 && static_cast<double>(c1) == u1) --c1;  // as accumulate_piece
    if (c0 == c1) {
      const double area = h * (static_cast<double>(c0 + 1) - 0.5 * (u0 + u1));
      if (c0 == run_column_ && sign == run_sign_) {
        run_area_ += area;
        run_height_ += h;
        return;
      }
      end_chain();
      run_column_ = c0;
      run_area_ = area;
      run_height_ = h;
      run_sign_ = sign;
      return;
    }
    end_chain();
    dirty_ = true;
    accumulate_piece_across(acc_.data(), u0, u1, c0, c1, h, sign);
    touch_range(c0, c1 + 1);
  }

  /// Writes the run of one-column pieces add_chain_piece() is summing, if any.
  void end_chain() noexcept {
    if (run_column_ < 0) return;
    dirty_ = true;
    acc_[static_cast<std::size_t>(run_column_)] += run_sign_ * run_area_;
    acc_[static_cast<std::size_t>(run_column_) + 1] += run_sign_ * (run_height_ - run_area_);
    touch_range(run_column_, run_column_ + 1);
    run_column_ = -1;
  }

  /// Converts the accumulated coverage of row `y` to 8-bit spans (round(area·255), area clamped to
  /// [0, 1] only against rounding), appends the non-zero ones to `out`, and clears the row.
  void emit(int y, std::vector<Span>& out);

  /// The plain per-pixel form of emit(): appends the 8-bit coverage of every column, zeros included
  /// (used by the reference path and its tests), and clears the row.
  void emit_all(std::vector<unsigned char>& out);

 private:
  /// Marks the cells first..last (first <= last) as written, a word of bits at a time rather than a bit
  /// per column: a long piece, or each run of a piece cut at many crossings, writes several columns.
  void touch_range(int first, int last) noexcept {
    const std::size_t w0 = static_cast<std::size_t>(first) >> 6;
    const std::size_t w1 = static_cast<std::size_t>(last) >> 6;
    const std::uint64_t from_first = ~std::uint64_t{0} << (first & 63);
    const std::uint64_t to_last = ~std::uint64_t{0} >> (63 - (last & 63));
    if (w0 == w1) {
      touched_[w0] |= from_first & to_last;
      return;
    }
    touched_[w0] |= from_first;
    for (std::size_t w = w0 + 1; w < w1; ++w) touched_[w] = ~std::uint64_t{0};
    touched_[w1] |= to_last;
  }

  // True from the first add_boundary() of a row until it is emitted: only then can acc_ hold non-zeros.
  bool dirty_ = false;
  // add_chain_piece's run of one-column pieces: its column (-1: none), area, height and sign.
  int run_column_ = -1;
  double run_area_ = 0.0;
  double run_height_ = 0.0;
  double run_sign_ = 0.0;
  std::vector<double> acc_;  // width + 2 entries: columns 0..width-1, the right side, and one past it
  // One bit per cell of acc_ that was written since the last emit: emit() visits only those (the coverage
  // is constant between them), skipping 64 untouched columns per word inside and between shapes.
  std::vector<std::uint64_t> touched_;
  int x0_ = 0;
  int width_ = 0;
};

}  // namespace curvescan::detail
