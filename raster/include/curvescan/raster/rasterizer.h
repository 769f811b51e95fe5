// Rasterizer: line edges in device space -> coverage spans.
//
// Interface fixed by the skeleton; the algorithm and its essay live in raster/scan/rasterizer.cpp.
// Input is straight edges in device pixels (doubles, finite: Path guarantees it). Edges are clipped to
// the clip box in double before anything else, so coordinates far outside the canvas (±1e9) keep their
// winding. Memory grows with the number of edges and the clip width, never with the clip area.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <utility>

#include "curvescan/curves/point.h"
#include "curvescan/raster/path.h"

namespace curvescan {

// Span: the seam between the rasterizer and the compositor (after plutovg's span struct).
//
// The rasterizer knows geometry and coverage, the compositor knows pixels; they meet only here.
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

/// An integer pixel rectangle [x0, x1) x [y0, y1).
struct IntRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  [[nodiscard]] bool empty() const noexcept { return x1 <= x0 || y1 <= y0; }
  bool operator==(const IntRect&) const = default;
};

/// What the last rasterize() call did, in elementary steps that do not depend on the machine (so a test
/// can bound the work of an input where a clock could not). See the cost model in raster/scan/rasterizer.cpp.
struct RasterizerStats {
  std::uint64_t pieces_visited = 0;  ///< edge pieces gathered, sorted past, walked or sampled
  std::uint64_t crossings = 0;       ///< pairs of pieces crossing inside a band, resolved exactly
  std::uint64_t sampled_bands = 0;   ///< bands over the crossing budget, resolved by sub-scanlines
  std::uint64_t sampled_rows = 0;    ///< rows over the band budget, resolved by sub-scanlines
  std::uint64_t planar_fills = 0;    ///< 1 when the fill's boundary was found by the whole-fill sweep
  std::uint64_t sweep_crossings = 0;  ///< crossings of monotone chains that sweep resolved
};

/// Accumulates edges, then resolves coverage under a fill rule and emits spans.
/// Reusable: reset() keeps the allocated memory.
class Rasterizer {
 public:
  Rasterizer() = default;
  explicit Rasterizer(IntRect clip) { reset(clip); }

  /// Forgets all edges; coverage will be produced for pixels inside `clip` only.
  void reset(IntRect clip);
  /// Adds the directed edge a -> b (device pixels). Edge direction gives the winding sign.
  void add_line(Point a, Point b);
  /// Adds the directed edges points[0] -> points[1] -> ... -> points.back() of an open polyline (repeat
  /// the first point to close it): the same edges as add_line on each consecutive pair, in order, with
  /// less work per edge when the points lie inside the clip box (path_edges.cpp adds each contour so).
  void add_polyline(std::span<const Point> points);
  /// Resolves the edges added since reset() and sends the covered spans to `sink`.
  void rasterize(FillRule rule, Antialias antialias, SpanSink& sink);
  /// Resolves the edges added since reset() with exact-area anti-aliasing into `mask`, the 8-bit coverage
  /// of every pixel of the clip box, row-major (clip width · height bytes, each written: 0 where nothing
  /// is covered): what rasterize(rule, Antialias::kExact, ...) sends as spans, up to float rounding (at
  /// most one step on values at a rounding midpoint). Made for small boxes such as glyph bitmaps: a planar
  /// fill of a box up to 4096 columns and 2^22 pixels is accumulated densely, with no spans. Writes
  /// nothing when `mask` has another size.
  void rasterize_mask(FillRule rule, std::span<std::uint8_t> mask);
  /// The plain reference of rasterize(), kept beside it so that a test can hold the optimised scan to it:
  /// the same method (see the essay in scan/rasterizer.cpp) without shortcuts — every edge tested on every
  /// row, all pairwise crossings, full sorts, aliased pixels tested one centre at a time — emitting one
  /// span per covered pixel. Same coverage up to double rounding; O(rows · edges²): for tests only.
  void rasterize_reference(FillRule rule, Antialias antialias, SpanSink& sink);

  /// The rows [first, second) of the clip box that the edges added since reset() reach; {0, 0} when none.
  [[nodiscard]] std::pair<int, int> edge_rows() const noexcept;
  /// Moves what lies below the rows `cuts` (device, ascending, each inside the clip box's rows) into
  /// `lower`, in one pass over the edges: `lower[k]` (lower.size() == cuts.size()) is reset to the clip
  /// box's columns and the rows from cuts[k] to the next cut or the clip box's bottom, and this rasterizer
  /// keeps the rows above cuts[0]. An edge crossing a cut is cut there, as the clip box cuts edges, every
  /// cut point taken on the original edge, so the parts of one edge still meet and each pixel's coverage
  /// comes from the same geometry: the parts can be rasterized independently (on several threads) into
  /// disjoint rows.
  void split_at_rows(std::span<const int> cuts, std::span<Rasterizer> lower);
  /// How many edges (after clipping) the rasterizer holds.
  [[nodiscard]] std::size_t edge_count() const noexcept;

  /// The clip box given to reset() (empty for a default-constructed rasterizer): pixels outside it get no
  /// coverage, so callers may skip detail there (path_edges.cpp flattens only curves that meet it).
  [[nodiscard]] IntRect clip() const noexcept;
  /// Work done by the last rasterize() (zero before the first).
  [[nodiscard]] RasterizerStats stats() const noexcept;
  /// Bounds the work of a row of n active pieces to about `factor`·n·⌈log2(n + 2)⌉ piece visits, plus a
  /// pool of 2^26 visits shared by the rows of one fill: past it, bands or rows are resolved by 16
  /// sub-scanlines, exact in x and sampled in y, instead of exactly (error bound in scan/rasterizer.cpp).
  /// Default 16, the cost of that fallback; 0 samples every row cut into bands and every band holding a
  /// crossing (for tests); +infinity never samples. NaN or negative: 0.
  void set_crossing_budget(double factor);
  /// Bounds the crossings the whole-fill sweep resolves (scan/rasterizer_planar.cpp) to `factor`·n + 4096
  /// for n edges (the n term scaled down for edges longer than 16 rows on average, where the row scan
  /// resolves crossings more cheaply); a fill with more is scanned row by row (same coverage up to
  /// rounding, within the bound of set_crossing_budget). Default 32; 0 sends every fill with a crossing
  /// to the row scan (for tests of it). NaN or negative: 0.
  void set_sweep_crossing_budget(double factor);

 private:
  struct Impl;
  // Implementation state lives in src/ (see rasterizer.cpp); kept behind a pointer so the public
  // header does not change as the algorithm is tuned.
  struct ImplDeleter {
    void operator()(Impl* impl) const noexcept;
  };
  std::unique_ptr<Impl, ImplDeleter> impl_;
};

}  // namespace curvescan
