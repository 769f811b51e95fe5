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
  // The area right of a straight piece inside one column does not change when the piece is flipped
  // upside down, so order the ends left to right.
  double u0 = std::min(xa, xb) - x0_;
  double u1 = std::max(xa, xb) - x0_;
  const double width = width_;
  dirty_ = true;
  u0 = std::clamp(u0, 0.0, width);  // callers pass clipped x; the clamp only guards against rounding
  u1 = std::clamp(u1, 0.0, width);
  double* acc = acc_.data();
  const int c0 = static_cast<int>(u0);
  // Last column the piece really enters: a piece ending exactly on a column line does not enter the
  // column to the right of it.
  int c1 = static_cast<int>(u1);
  if (c1 > c0 && static_cast<double>(c1) == u1) --c1;

  if (c0 == c1) {
    // One column: the part right of the piece is a trapezoid of height h whose left side runs from u0 to
    // u1, so its area is h·(c0 + 1 - mean(u0, u1)); the rest of h carries to the next column.
    const double area = h * (static_cast<double>(c0 + 1) - 0.5 * (u0 + u1));
    acc[c0] += sign * area;
    acc[c0 + 1] += sign * (h - area);
    touch(c0);
    touch(c0 + 1);
    return;
  }
  // Several columns: cut the piece at each column line. Heights are proportional to the x travelled
  // (dy/dx constant); the last part takes the rest of h so that the row sum is h exactly.
  const double dydx = h / (u1 - u0);
  double first_x = static_cast<double>(c0 + 1) - u0;
  double h_used = std::min(first_x * dydx, h);
  double area = 0.5 * h_used * first_x;  // triangle right of the piece inside column c0
  acc[c0] += sign * area;
  acc[c0 + 1] += sign * (h_used - area);
  touch(c0);
  const double full = std::min(dydx, h);
  for (int c = c0 + 1; c < c1; ++c) {
    const double part = std::min(full, h - h_used);
    acc[c] += sign * 0.5 * part;
    acc[c + 1] += sign * 0.5 * part;
    touch(c);
    h_used += part;
  }
  const double last = std::max(h - h_used, 0.0);
  const double last_x = u1 - static_cast<double>(c1);
  area = last * (1.0 - 0.5 * last_x);
  acc[c1] += sign * area;
  acc[c1 + 1] += sign * (last - area);
  touch(c1);
  touch(c1 + 1);
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
