// Span: the seam between the rasterizer and the compositor (after plutovg's span struct).
//
// The rasterizer knows geometry and coverage, the compositor knows pixels; they meet only here.
#pragma once

#include <cstdint>
#include <span>

namespace curvescan {

/// A horizontal run of pixels [x, x + len) on row y that all have the same coverage
/// (0..255; 255 = the pixel is entirely inside the shape).
struct Span {
  int x = 0;
  int y = 0;
  int len = 0;
  std::uint8_t coverage = 0;
};

/// Receives spans, row by row, top to bottom, left to right within a row; no two spans overlap.
class SpanSink {
 public:
  virtual ~SpanSink() = default;
  virtual void blend(std::span<const Span> spans) = 0;
};

}  // namespace curvescan
