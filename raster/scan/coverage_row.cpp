// CoverageRow: see coverage_row.h for the accumulation scheme.
#include "coverage_row.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace curvescan::detail {

void CoverageRow::reset(int x0, int width) {
  x0_ = x0;
  const std::size_t cells = static_cast<std::size_t>(width) + 2;
  if (width == width_ && acc_.size() == cells && !dirty_) return;  // already all zero (see emit)
  width_ = width;
  acc_.assign(cells, 0.0);
  touched_.assign((cells + 63) / 64, 0);
  dirty_ = false;
}

void CoverageRow::add_boundary(double xa, double xb, double h, double sign) noexcept {
  dirty_ = true;
  const double width = width_;
  // Callers pass clipped x; the clamp only guards against rounding.
  const auto [c0, c1] = accumulate_piece(acc_.data(), std::clamp(xa - x0_, 0.0, width),
                                         std::clamp(xb - x0_, 0.0, width), h, sign);
  touch_range(c0, c1 + 1);
}

void CoverageRow::emit(int y, std::vector<Span>& out) {
  double* acc = acc_.data();
  double sum = 0.0;
  int run_start = 0;
  unsigned char run_value = 0;
  for (std::size_t word = 0; word < touched_.size(); ++word) {
    std::uint64_t bits = touched_[word];
    if (bits == 0) continue;
    touched_[word] = 0;
    while (bits != 0) {
      const int c = static_cast<int>(word * 64) + std::countr_zero(bits);
      bits &= bits - 1;
      sum += acc[c];
      acc[c] = 0.0;
      if (c >= width_) continue;  // the right side of the clip and one past it: cleared, never emitted
      const unsigned char value = coverage_to_u8(sum);
      if (value != run_value) {
        if (run_value != 0) out.push_back({x0_ + run_start, y, c - run_start, run_value});
        run_start = c;
        run_value = value;
      }
    }
  }
  dirty_ = false;  // every touched cell was cleared above
  // Past the last touched column the coverage stays constant: a shape that leaves the clip on the right
  // (its leave edges were dropped by the clipper) fills to the end of the row.
  if (run_value != 0) out.push_back({x0_ + run_start, y, width_ - run_start, run_value});
}

void CoverageRow::emit_all(std::vector<unsigned char>& out) {
  double sum = 0.0;
  for (int c = 0; c < width_; ++c) {
    sum += acc_[static_cast<std::size_t>(c)];
    out.push_back(coverage_to_u8(sum));
  }
  std::fill(acc_.begin(), acc_.end(), 0.0);
  std::fill(touched_.begin(), touched_.end(), 0);
  dirty_ = false;
}

}  // namespace curvescan::detail
