// CoverageRow marks the cells a boundary piece writes a word of 64 bits at a time (touch_range), and
// emit() visits only the marked cells: a cell written but not marked would be left out of the row's
// prefix sum and left non-zero for the next row. Pieces ending at, just before and just after the word
// boundaries (columns 63/64, 127/128), one-column pieces, pieces across several words and chain pieces
// summed in one column are held to the plain per-column form (emit_all, which reads every cell) and must
// leave the row all zero.
//
// Metric: both forms sum the same cells in the same left-to-right order, so the 8-bit coverage must be
// identical (difference 0), and the row after emit() must read zero in every column (a count of 0).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "scan/coverage_row.h"

using curvescan::Span;
using curvescan::detail::CoverageRow;

namespace {

constexpr int kWidth = 300;

/// The per-column coverage of emit()'s spans (columns outside every span are 0).
std::vector<unsigned char> columns_of(const std::vector<Span>& spans) {
  std::vector<unsigned char> out(kWidth, 0);
  for (const Span& s : spans) {
    for (int x = s.x; x < s.x + s.len; ++x) out[static_cast<std::size_t>(x)] = s.coverage;
  }
  return out;
}

/// The same pieces into two rows; emit() of one against emit_all() of the other, then the first row's
/// columns after emit() (which must have cleared every written cell).
template <class AddPieces>
void check_row(AddPieces add_pieces) {
  CoverageRow sparse;
  CoverageRow dense;
  sparse.reset(0, kWidth);
  dense.reset(0, kWidth);
  add_pieces(sparse);
  add_pieces(dense);
  std::vector<Span> spans;
  sparse.emit(0, spans);
  std::vector<unsigned char> expected;
  dense.emit_all(expected);
  CHECK(columns_of(spans) == expected);
  std::vector<unsigned char> left_over;
  sparse.emit_all(left_over);
  std::size_t non_zero = 0;
  for (const unsigned char v : left_over) non_zero += v != 0 ? 1 : 0;
  CHECK(non_zero == 0);
}

}  // namespace

TEST_CASE("coverage row: pieces at the word boundaries of the written-cell marks") {
  // Enter at a, leave at b (a < b): a band of height 1 filled between them, the ends slanted by `slant`.
  for (const double a : {0.0, 0.5, 62.5, 63.0, 63.5, 64.0, 64.5, 126.9, 127.5, 128.0, 190.25}) {
    for (const double b : {63.75, 64.0, 64.25, 127.0, 128.5, 192.0, 255.5, 299.0, 300.0}) {
      if (!(a < b)) continue;
      for (const double slant : {0.0, 0.75, 3.0, 70.0}) {
        CAPTURE(a, b, slant);
        check_row([&](CoverageRow& row) {
          row.add_boundary(a, std::min(a + slant, b), 1.0, 1.0);
          row.add_boundary(b, std::max(b - slant, a), 1.0, -1.0);
        });
      }
    }
  }
}

TEST_CASE("coverage row: random pieces and chain runs across several words") {
  std::mt19937 rng(2026);  // seeded: the same pieces every run
  std::uniform_real_distribution<double> x(0.0, kWidth);
  std::uniform_real_distribution<double> step(-2.0, 2.0);
  for (int trial = 0; trial < 200; ++trial) {
    CAPTURE(trial);
    const std::uint32_t seed = static_cast<std::uint32_t>(rng());
    check_row([seed, &x, &step](CoverageRow& row) {
      std::mt19937 pieces(seed);  // the same pieces into both rows
      for (int k = 0; k < 8; ++k) {
        const double xa = x(pieces);
        const double xb = x(pieces);
        row.add_boundary(xa, xb, 0.125, k % 2 == 0 ? 1.0 : -1.0);
      }
      // A chain of short pieces, some summed inside one column (add_chain_piece's run), some across.
      double cx = x(pieces);
      for (int k = 0; k < 16; ++k) {
        const double nx = std::clamp(cx + step(pieces), 0.0, static_cast<double>(kWidth));
        row.add_chain_piece(cx, nx, 1.0 / 16, 1.0);
        cx = nx;
      }
      row.end_chain();
    });
  }
}
