// The one-pass link and chain build (link_edges_into_chains, raster/scan/rasterizer_planar.cpp) held to its
// plain reference, kept here: link_contour_edges then build_planar_chains, two passes over the edges: the
// same links on every edge and the same chains in the same order, their extents compared bit for bit (the
// sign of a zero included).
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "curvescan/raster/rasterizer.h"
#include "scan/edge_clip.h"
#include "scan/rasterizer_impl.h"

using namespace curvescan;
using namespace curvescan::detail;

namespace {

// The reference: the two passes the library made before it fused them. Links first: a downward edge
// continues into the next one, an upward edge into the previous one. Then the chains: from every edge not
// linked from above, a walk down to the chain's bottom, taking the x extent of its vertices on the way.
void link_contour_edges(ScanState& s) {
  const std::size_t count = s.edges.size();
  ClippedEdge* edges = s.edges.data();
  // A downward edge continues into the next one, an upward edge into the previous one: each consecutive
  // pair (p, q) is linked when both go the same way and share the joint, in one pass that also clears
  // the links of an earlier scan (q's before the pair is looked at; p's below was cleared a step
  // earlier and can only have been set by the pair before it when p goes upward, which excludes a
  // downward link here).
  if (count == 0) return;
  edges[0].below = ClippedEdge::kNoEdge;
  edges[0].linked_above = false;
  for (std::size_t i = 1; i < count; ++i) {
    ClippedEdge& p = edges[i - 1];
    ClippedEdge& q = edges[i];
    q.below = ClippedEdge::kNoEdge;
    q.linked_above = false;
    if (p.dir != q.dir) continue;
    if (p.dir > 0) {
      if (q.y_top == p.y_bot && q.x_top == p.x_bot) {
        p.below = static_cast<std::uint32_t>(i);
        q.linked_above = true;
      }
    } else if (p.y_top == q.y_bot && p.x_top == q.x_bot) {
      q.below = static_cast<std::uint32_t>(i - 1);
      p.linked_above = true;
    }
  }
}

void build_planar_chains(ScanState& s) {
  const ClippedEdge* const edges = s.edges.data();
  const ClippedEdge* const end = edges + s.edges.size();
  std::vector<PlanarChain>& chains = s.planar_chains;
  chains.clear();
  for (const ClippedEdge* head = edges; head != end; ++head) {
    if (head->linked_above) continue;
    // Down to its bottom, taking the x extent of its vertices on the way (each edge's bottom, and the
    // head's top): the neighbour checks' cheap certificate (in_order_by_extent).
    const ClippedEdge* e = head;
    double x_min = head->x_top;
    double x_max = x_min;
    while (true) {
      x_min = std::min(x_min, e->x_bot);
      x_max = std::max(x_max, e->x_bot);
      if (e->below == ClippedEdge::kNoEdge) break;
      e = edges + e->below;
    }
    PlanarChain& chain = chains.emplace_back();
    const auto i = static_cast<std::uint32_t>(head - edges);
    chain.head = i;
    chain.cursor = i;
    chain.top = head->y_top;
    chain.bottom = e->y_bot;
    chain.x_min = x_min;
    chain.x_max = x_max;
    chain.dir = head->dir;
  }
}

std::uint64_t bits(double v) {
  return std::bit_cast<std::uint64_t>(v);
}

/// Loads the contours as Canvas::fill hands them over (a polyline, closed by one line), or edge by edge.
void load(ScanState& s, const std::vector<std::vector<Point>>& shape, IntRect clip, bool by_polyline) {
  s.clip = clip;
  s.edges.clear();
  for (const std::vector<Point>& contour : shape) {
    if (by_polyline) {
      clip_polyline(contour, clip, s.edges);
      clip_edge(contour.back(), contour.front(), clip, s.edges);
    } else {
      for (std::size_t i = 0; i < contour.size(); ++i) {
        clip_edge(contour[i], contour[(i + 1) % contour.size()], clip, s.edges);
      }
    }
  }
}

/// Both builds from the same edges, compared field by field.
void check_same(const std::vector<std::vector<Point>>& shape, IntRect clip, bool by_polyline) {
  ScanState reference;
  load(reference, shape, clip, by_polyline);
  link_contour_edges(reference);
  build_planar_chains(reference);

  ScanState fused;
  load(fused, shape, clip, by_polyline);
  // Stale links from an earlier scan must be overwritten, as link_contour_edges overwrites them.
  for (ClippedEdge& e : fused.edges) {
    e.below = 7;
    e.linked_above = true;
  }
  fused.planar_chains.resize(3);
  link_edges_into_chains(fused);

  REQUIRE(fused.edges.size() == reference.edges.size());
  for (std::size_t i = 0; i < reference.edges.size(); ++i) {
    INFO("edge " << i);
    CHECK(fused.edges[i].below == reference.edges[i].below);
    CHECK(fused.edges[i].linked_above == reference.edges[i].linked_above);
  }
  REQUIRE(fused.planar_chains.size() == reference.planar_chains.size());
  for (std::size_t i = 0; i < reference.planar_chains.size(); ++i) {
    INFO("chain " << i);
    const PlanarChain& a = fused.planar_chains[i];
    const PlanarChain& b = reference.planar_chains[i];
    CHECK(a.head == b.head);
    CHECK(a.cursor == b.cursor);
    CHECK(bits(a.top) == bits(b.top));
    CHECK(bits(a.bottom) == bits(b.bottom));
    CHECK(bits(a.x_min) == bits(b.x_min));
    CHECK(bits(a.x_max) == bits(b.x_max));
    CHECK(a.dir == b.dir);
    CHECK(a.open_piece == b.open_piece);
    CHECK(a.checked_right == b.checked_right);
    CHECK(a.boundary == b.boundary);
    CHECK(a.blocks_built == b.blocks_built);
  }
}

}  // namespace

TEST_CASE("one-pass links and chains: the two passes' result on seeded random contours", "[raster][planar]") {
  std::mt19937 rng(20261128);
  constexpr IntRect kClip{0, 0, 64, 48};
  for (int trial = 0; trial < 400; ++trial) {
    // Vertices on a coarse grid that reaches past the clip on every side: repeated points, horizontal
    // edges (dropped), joints shared exactly, edges cut at the clip's rows and columns.
    std::uniform_int_distribution<int> xs(-4, 17);
    std::uniform_int_distribution<int> ys(-3, 13);
    std::uniform_int_distribution<int> sizes(2, 40);
    std::uniform_int_distribution<int> contours(1, 4);
    std::vector<std::vector<Point>> shape(static_cast<std::size_t>(contours(rng)));
    for (std::vector<Point>& contour : shape) {
      const int n = sizes(rng);
      for (int k = 0; k < n; ++k) contour.push_back({5.0 * xs(rng), 5.0 * ys(rng)});
    }
    check_same(shape, kClip, trial % 2 == 0);
  }
}

TEST_CASE("one-pass links and chains: fine regular polygons, both orientations", "[raster][planar]") {
  constexpr IntRect kClip{0, 0, 512, 512};
  for (const int n : {3, 4, 10, 1000, 10007}) {
    for (const double turn : {1.0, -1.0}) {
      std::vector<Point> polygon;
      for (int k = 0; k < n; ++k) {
        const double a = turn * 2.0 * std::numbers::pi * k / n;
        polygon.push_back({256.0 + 250.0 * std::cos(a), 256.0 + 250.0 * std::sin(a)});
      }
      check_same({polygon}, kClip, true);
    }
  }
}

TEST_CASE("one-pass links and chains: zeros of either sign keep build_planar_chains' extent",
          "[raster][planar]") {
  // std::min and std::max keep the first of two equal values; -0.0 and 0.0 are equal. Chains running
  // up and down through vertices at x = +0 and -0 (inside a clip starting at column 0).
  constexpr IntRect kClip{0, 0, 8, 8};
  const std::vector<std::vector<Point>> shapes[] = {
      {{{0.0, 1.0}, {-0.0, 2.0}, {0.0, 3.0}, {-0.0, 4.0}, {3.0, 5.0}, {2.0, 0.5}}},
      {{{-0.0, 1.0}, {0.0, 2.0}, {-0.0, 3.0}, {0.0, 4.0}, {3.0, 5.0}, {2.0, 0.5}}},
      {{{2.0, 0.5}, {3.0, 5.0}, {0.0, 4.0}, {-0.0, 3.0}, {0.0, 2.0}, {-0.0, 1.0}}},
      {{{2.0, 0.5}, {3.0, 5.0}, {-0.0, 4.0}, {0.0, 3.0}, {-0.0, 2.0}, {0.0, 1.0}}},
  };
  for (const std::vector<std::vector<Point>>& shape : shapes) {
    check_same(shape, kClip, true);
    check_same(shape, kClip, false);
  }
}
