// Rasterizer::Impl: the state shared by the optimised scan (rasterizer.cpp) and the plain reference scan
// (rasterizer_reference.cpp). The method is described in the essay at the top of rasterizer.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "coverage_row.h"
#include "curvescan/raster/rasterizer.h"
#include "edge_clip.h"

namespace curvescan {

namespace detail {

/// A piece of an edge inside a band [ya, yb] of a row: x at the top and bottom of the band.
struct BandPiece {
  double xa = 0.0;
  double xb = 0.0;
  int dir = 0;
  std::uint32_t edge = 0;  ///< index into Impl::edges
};

/// Whether winding number `w` is inside under `rule`.
[[nodiscard]] inline bool is_filled(int winding, FillRule rule) noexcept {
  return rule == FillRule::kNonZero ? winding != 0 : (winding & 1) != 0;
}

/// Walks the pieces of a band, given in left-to-right order with no two crossing inside the band, and
/// adds to `row` every piece across which the rule's filled state flips: +1 entering, -1 leaving.
inline void accumulate_band(const BandPiece* pieces, std::size_t count, double h, FillRule rule,
                            CoverageRow& row) noexcept {
  int winding = 0;
  bool filled = false;
  for (std::size_t i = 0; i < count; ++i) {
    winding += pieces[i].dir;
    const bool now = is_filled(winding, rule);
    if (now != filled) {
      row.add_boundary(pieces[i].xa, pieces[i].xb, h, now ? 1.0 : -1.0);
      filled = now;
    }
  }
}

}  // namespace detail

namespace detail {

/// Everything the scans need: the clipped edges and the scratch they reuse.
struct ScanState {
  IntRect clip;
  std::vector<detail::ClippedEdge> edges;  // clipped, top to bottom, horizontal ones dropped

  // Scratch reused across rasterize() calls, so that steady-state rendering does not allocate.
  detail::CoverageRow row;
  std::vector<std::uint32_t> order;         // edge indices sorted by y_top
  std::vector<std::uint32_t> active;        // edges meeting the current row
  std::vector<std::uint32_t> by_top;        // the active edges of a row with events, sorted by y_top
  std::vector<std::uint32_t> band_active;   // the edges covering the current band, kept in x order
  std::vector<double> events;               // heights inside the row where an edge starts or ends
  std::vector<double> crossings;            // heights inside a band where two edges cross
  std::vector<Span> spans;                  // spans waiting to be sent to the sink
  std::vector<detail::BandPiece> pieces;    // the pieces of the current band
  std::vector<detail::BandPiece> sub;       // the same pieces, re-sorted per sub-band between crossings
  std::vector<detail::BandPiece> sub_band;  // the pieces cut to one sub-band
  std::vector<unsigned char> row_coverage;  // reference path: one row of 8-bit coverage
};

}  // namespace detail

// The pimpl is the scan state; helpers in the .cpp files work on detail::ScanState (Impl is private).
struct Rasterizer::Impl : detail::ScanState {};
}  // namespace curvescan
