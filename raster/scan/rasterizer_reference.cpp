// The plain reference scan: the method of the essay in rasterizer.cpp, written without shortcuts so that
// it is obviously correct, and slow. Every row looks at every edge; the bands of a row are cut at every
// edge end and every pairwise crossing inside the row (no inversion tracking); each band is fully sorted
// by x at mid-height; coverage is emitted pixel by pixel. Aliased pixels count the winding number at their
// centre directly over all edges. Only the clipper and the per-piece accumulation are shared with the
// optimised scan; both have their own exact oracle tests.
#include <algorithm>
#include <cmath>

#include "curvescan/raster/rasterizer.h"
#include "rasterizer_impl.h"

namespace curvescan {

namespace {

using detail::BandPiece;
using detail::ClippedEdge;

/// Appends the height in (lo, hi) where edges e and f cross, if they do (strict sign change).
void push_crossing(const ClippedEdge& e, const ClippedEdge& f, double lo, double hi,
                   std::vector<double>& out) {
  const double d_lo = e.x_at(lo) - f.x_at(lo);
  const double d_hi = e.x_at(hi) - f.x_at(hi);
  if ((d_lo < 0.0 && d_hi > 0.0) || (d_lo > 0.0 && d_hi < 0.0)) {
    const double y = lo + (hi - lo) * (d_lo / (d_lo - d_hi));
    if (y > lo && y < hi) out.push_back(y);
  }
}

}  // namespace

void Rasterizer::rasterize_reference(FillRule rule, Antialias antialias, SpanSink& sink) {
  if (!impl_ || impl_->clip.empty() || impl_->edges.empty()) return;
  Impl& s = *impl_;
  const IntRect clip = s.clip;
  const int width = clip.x1 - clip.x0;
  s.row.reset(clip.x0, width);
  s.spans.clear();
  for (int y = clip.y0; y < clip.y1; ++y) {
    const double ya = y;
    const double yb = ya + 1.0;
    if (antialias == Antialias::kNone) {
      const double yc = ya + 0.5;
      for (int x = clip.x0; x < clip.x1; ++x) {
        const double xc = x + 0.5;
        int winding = 0;
        for (const ClippedEdge& e : s.edges) {
          if (e.y_top <= yc && yc < e.y_bot && e.x_at(yc) <= xc) winding += e.dir;
        }
        if (detail::is_filled(winding, rule)) s.spans.push_back({x, y, 1, 255});
      }
      continue;
    }

    s.active.clear();
    for (std::uint32_t i = 0; i < s.edges.size(); ++i) {
      if (s.edges[i].y_top < yb && s.edges[i].y_bot > ya) s.active.push_back(i);
    }
    s.events = {ya, yb};
    for (std::size_t a = 0; a < s.active.size(); ++a) {
      const ClippedEdge& e = s.edges[s.active[a]];
      if (e.y_top > ya) s.events.push_back(e.y_top);
      if (e.y_bot < yb) s.events.push_back(e.y_bot);
      for (std::size_t b = a + 1; b < s.active.size(); ++b) {
        const ClippedEdge& f = s.edges[s.active[b]];
        const double lo = std::max({ya, e.y_top, f.y_top});
        const double hi = std::min({yb, e.y_bot, f.y_bot});
        if (hi > lo) push_crossing(e, f, lo, hi, s.events);
      }
    }
    std::sort(s.events.begin(), s.events.end());
    for (std::size_t k = 0; k + 1 < s.events.size(); ++k) {
      const double ba = s.events[k];
      const double bb = s.events[k + 1];
      if (!(bb > ba)) continue;
      const double bm = 0.5 * (ba + bb);
      s.pieces.clear();
      for (const std::uint32_t i : s.active) {
        const ClippedEdge& e = s.edges[i];
        if (e.y_top <= ba && e.y_bot >= bb) s.pieces.push_back({e.x_at(ba), e.x_at(bb), e.dir, i});
      }
      std::sort(s.pieces.begin(), s.pieces.end(), [&](const BandPiece& p, const BandPiece& q) {
        return s.edges[p.edge].x_at(bm) < s.edges[q.edge].x_at(bm);
      });
      detail::for_each_boundary(s.pieces.data(), s.pieces.size(), rule, [&](const BandPiece& p, double sign) {
        s.row.add_boundary(p.xa, p.xb, bb - ba, sign);
      });
    }
    s.row_coverage.clear();
    s.row.emit_all(s.row_coverage);
    for (int x = 0; x < width; ++x) {
      const unsigned char value = s.row_coverage[static_cast<std::size_t>(x)];
      if (value != 0) s.spans.push_back({clip.x0 + x, y, 1, value});
    }
  }
  if (!s.spans.empty()) sink.blend(s.spans);
  s.spans.clear();
}

}  // namespace curvescan
