// DenseCoverage: exact-area accumulation for a whole pixel box at once, written out as an 8-bit mask.
//
// CoverageRow accumulates one row at a time and hands it on as spans, visiting only the cells a piece
// touched: right for a canvas, where the compositor wants runs. A coverage mask (a glyph bitmap) wants
// every pixel of a small box instead, so here every row of the box has its own accumulation row, each
// boundary piece is added once to the rows it crosses (no per-row bookkeeping of live pieces or touched
// cells), and one pass per row turns the prefix sums into bytes — four columns at a time with SSE2 (eight
// with AVX2 where the processor has it, chosen at run time), the accumulate of font-rs (Raph Levien,
// "Inside the fastest font renderer in the world", 2016). With AVX2 a group of eight cells that are all
// zero (the inside of a stem or a counter, a margin: no piece wrote them) is written as the carry's byte
// without a prefix sum or a clearing store, as FreeType fills the spans between its cells.
//
// The cells are floats holding 255 times the coverage deltas, so that the pass that writes the bytes
// needs neither a scale nor a rounding add per column (the sum starts at one half): half the memory
// traffic of doubles and four lanes per SSE register. What that costs: each cell holds a sum of a few
// piece contributions, each rounded to 2^-24 relative, and the prefix sum across a row of w columns adds
// at most w roundings of partial sums in [-255, 511]; the box is limited to kMaxWidth columns, so a pixel
// is off by less than 4096 · 511 · 2^-24 < 0.125 of one 8-bit step (5e-4 of a pixel's area), which can
// still move a value that sits on a rounding midpoint by one step.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "coverage_row.h"
#include "edge_clip.h"

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

  /// Adds the boundary piece of a chain between heights y0 and y1, with `sign` +1 (the filled region
  /// starts right of it) or -1 (it ends there): edge `first` holds y0 (y_top <= y0 < y_bot), and the piece
  /// runs down the `below` links to the edge holding y1. Each edge's part is cut at the row lines
  /// (add_edge_part). One call per piece rather than per edge: the box's constants are read once, and at a
  /// joint (linked edges meet exactly: the next edge's x_top is this one's x_bot) the joint's column is
  /// carried over instead of computed again. The same row pieces, sums and order as one add_edge_part per
  /// edge with its own columns. Always inlined into its one loop (accumulate_planar_dense): the box's
  /// constants then stay in registers from piece to piece and the call's saves and restores go (a glyph at 12
  /// px has about nine pieces; measured 1.2 % of a 12 px glyph mask, docs/benchmarks.md).
  [[gnu::always_inline]] void add_chain_piece(const ClippedEdge* edges, std::uint32_t first, double y0,
                                              double y1, double sign) noexcept {
    const double scaled_sign = 255.0 * sign;  // the cells hold 255 · coverage (header)
    const ClippedEdge* edge = edges + first;
    double y = y0 > edge->y_top ? y0 : edge->y_top;
    double u = column(edge->x_at(y));
    // The edges above the one holding y1 end inside the piece: their parts end at their bottoms, where
    // x_at gives x_bot.
    while (edge->y_bot < y1) {
      const double u_end = column(edge->x_bot);
      if (y < edge->y_bot) add_edge_part(*edge, y, edge->y_bot, u, u_end, scaled_sign);
      // The next edge's part starts at its top, the joint: x_at there is its x_top, this edge's x_bot.
      edge = edges + edge->below;
      y = edge->y_top;
      u = u_end;
    }
    // The last edge's part ends at y1 (x_at(y1): x_bot at the edge's bottom, inside it the interpolation;
    // y1 is below y, so not above the edge's top).
    if (!(y < y1)) return;  // a piece of no height: nothing to add
    const double x_end = y1 < edge->y_bot ? edge->x_top + (y1 - edge->y_top) * edge->dxdy : edge->x_bot;
    add_edge_part(*edge, y, y1, u, column(x_end), scaled_sign);
  }

  /// Writes round(255 · coverage) of every pixel of the box into `mask` (row-major, width · height
  /// bytes) and clears the cells.
  void write_mask(std::span<std::uint8_t> mask) noexcept;

 private:
  /// Box column of device x, clamped to [0, width] against rounding: a min and a max, no branches.
  [[nodiscard]] double column(double x) const noexcept {
    const double u = x - static_cast<double>(x0_);
    const double at_least_zero = u > 0.0 ? u : 0.0;
    const double width = width_;
    return at_least_zero < width ? at_least_zero : width;
  }

  /// Adds the part between heights y and y_end (y_top <= y < y_end <= y_bot) of boundary edge `e`, whose
  /// box columns at those heights are u and u_end, with scaled_sign = 255 · sign. The part is cut at the
  /// row lines, each cut's x computed as ClippedEdge::x_at computes it (exact at the edge's ends, so a
  /// chain's edges meet) and clamped to the box against rounding. The rows' cells are reached by a stride
  /// and the clamp is branch-free: a glyph at 12 px has about a hundred such row pieces, and their fixed
  /// cost is most of the accumulation.
  [[gnu::always_inline]] void add_edge_part(const ClippedEdge& e, double y, double y_end, double u,
                                            double u_end, double scaled_sign) noexcept {
    const double x_top = e.x_top;
    const double y_top = e.y_top;
    const double dxdy = e.dxdy;
    // Clipped edges lie inside the box's rows, so floor(y) is a row of the box (an int; computed without
    // std::floor, a library call on baseline x86-64).
    const int truncated = static_cast<int>(y);
    int row = static_cast<double>(truncated) > y ? truncated - 1 : truncated;
    float* cells = cells_.data() + static_cast<std::size_t>(row - y0_) * stride_;
    // The part lies inside one column (a stem, and most short edges of a curve): then every row piece is a
    // one-column piece of that column (accumulate_piece's second case; a piece on the column's right line
    // adds the same sums there as accumulate_piece adds one column further right), so the ordering,
    // column and case tests are made once for the edge instead of once per row.
    const double u_low = u < u_end ? u : u_end;
    const double u_high = u < u_end ? u_end : u;
    const int c = static_cast<int>(u_low);  // u_low >= 0: truncation is the floor
    const double right = static_cast<double>(c + 1);
    if (u_high <= right) {
      const auto one_column = [&](double ua, double ub, double h) noexcept {
        const double area = h * (right - 0.5 * (ua + ub));
        cells[c] += static_cast<float>(scaled_sign * area);
        cells[c + 1] += static_cast<float>(scaled_sign * (h - area));
      };
      // The first row, which the part may enter below its top.
      const double first_bottom = static_cast<double>(row) + 1.0;
      if (first_bottom >= y_end) {
        one_column(u, u_end, y_end - y);
        return;
      }
      const double u_first = column(x_top + (first_bottom - y_top) * dxdy);
      one_column(u, u_first, first_bottom - y);
      cells += stride_;
      ++row;
      // The rows the part crosses whole (bottom above y_end; a stem's or a steep side's many rows): the
      // area right of the piece is right - u_top - dxdy / 2 and the carry 1 minus it, so the area steps by
      // -dxdy per row and each row is two adds (the same area up to the rounding of the steps, below
      // 1e-10 over 4096 rows).
      const int end_truncated = static_cast<int>(y_end);
      const int last_row = (static_cast<double>(end_truncated) < y_end ? end_truncated : end_truncated - 1);
      if (row < last_row) {
        const float full = static_cast<float>(scaled_sign);
        double area = scaled_sign * (right - 0.5 * dxdy - u_first);
        const double step = -scaled_sign * dxdy;
        for (; row < last_row; ++row) {
          const float part = static_cast<float>(area);
          cells[c] += part;
          cells[c + 1] += full - part;
          area += step;
          cells += stride_;
        }
      }
      // The last row, which the part may leave above its bottom (its top x as x_at computes it).
      const double last_top = static_cast<double>(row);
      const double u_last = last_top > first_bottom ? column(x_top + (last_top - y_top) * dxdy) : u_first;
      one_column(u_last, u_end, y_end - last_top);
      return;
    }
    while (true) {
      const double row_bottom = static_cast<double>(row) + 1.0;
      if (row_bottom >= y_end) {
        accumulate_piece(cells, u, u_end, y_end - y, scaled_sign);
        return;
      }
      // Strictly inside the edge's y range: x_at's interpolation, without its end tests.
      const double u_next = column(x_top + (row_bottom - y_top) * dxdy);
      accumulate_piece(cells, u, u_next, row_bottom - y, scaled_sign);
      y = row_bottom;
      u = u_next;
      cells += stride_;
      ++row;
    }
  }

  // height rows of stride_ cells: the width, the right side and one past it, rounded up to a multiple of 4
  std::vector<float> cells_;
  int x0_ = 0;
  int y0_ = 0;
  int width_ = 0;
  int height_ = 0;
  std::size_t stride_ = 4;
};

}  // namespace curvescan::detail
