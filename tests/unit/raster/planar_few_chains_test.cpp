// The whole-fill sweep of a fill of few chains (raster/scan/rasterizer_planar_few.cpp) against the general
// sweep (rasterizer_planar.cpp) on the same chains, with crossings not resolved (the first crossing ends
// both) and resolved: the same outcome, the same crossings resolved, and where the fill is taken, the same
// boundary pieces, field for field and in the same order, and the same "filled right of every chain"
// flag: so the accumulation, and every byte of output, is the same. Exact equality, no tolerance: the two
// make the same comparisons on the same doubles.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "scan/edge_clip.h"
#include "scan/rasterizer_impl.h"

using namespace curvescan;
using namespace curvescan::detail;

namespace {

using Contour = std::vector<Point>;
using Shape = std::vector<Contour>;

struct Proof {
  bool planar = false;
  bool open_right = false;
  std::uint64_t crossings = 0;
  std::vector<PlanarPiece> pieces;
};

void load(ScanState& s, const Shape& shape, IntRect clip) {
  s.clip = clip;
  s.edges.clear();
  for (const Contour& contour : shape) {
    for (std::size_t i = 0; i < contour.size(); ++i) {
      clip_edge(contour[i], contour[(i + 1) % contour.size()], clip, s.edges);
    }
  }
  link_edges_into_chains(s);
}

/// The few-chain sweep and the general one on the same chains of `shape` under `rule`, crossings
/// resolved up to `crossing_budget` per edge (Rasterizer::set_sweep_crossing_budget).
std::pair<Proof, Proof> both_proofs(const Shape& shape, FillRule rule, IntRect clip, double crossing_budget) {
  ScanState s;
  s.sweep_crossing_budget = crossing_budget;
  load(s, shape, clip);
  REQUIRE(!s.planar_chains.empty());
  REQUIRE(s.planar_chains.size() <= kFewChains);
  s.stats = {};
  const bool few = prove_planar_few(s, rule);
  Proof a{few, s.planar_open_right, s.stats.sweep_crossings, s.planar_pieces};
  link_edges_into_chains(s);  // the chains fresh again
  s.stats = {};
  const bool general = sweep_planar_chains(s, rule);
  Proof b{general, s.planar_open_right, s.stats.sweep_crossings, s.planar_pieces};
  return {a, b};
}

/// The two proofs agree, field for field; returns whether they proved the fill planar.
bool proofs_agree(const Shape& shape, IntRect clip, double crossing_budget) {
  bool planar = true;
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    INFO((rule == FillRule::kNonZero ? "nonzero" : "even-odd") << ", crossing budget " << crossing_budget);
    const auto [a, b] = both_proofs(shape, rule, clip, crossing_budget);
    CHECK(a.planar == b.planar);
    CHECK(a.crossings == b.crossings);
    planar = planar && a.planar;
    if (!a.planar || !b.planar) continue;
    CHECK(a.open_right == b.open_right);
    REQUIRE(a.pieces.size() == b.pieces.size());
    for (std::size_t i = 0; i < a.pieces.size(); ++i) {
      INFO("piece " << i);
      CHECK(a.pieces[i].first_edge == b.pieces[i].first_edge);
      CHECK(a.pieces[i].y0 == b.pieces[i].y0);
      CHECK(a.pieces[i].y1 == b.pieces[i].y1);
      CHECK(a.pieces[i].sign == b.pieces[i].sign);
    }
  }
  return planar;
}

/// proofs_agree with crossings not resolved (`planar`: whether the fill is planar) and resolved (every fill
/// here then takes the sweep).
void check_same(const Shape& shape, IntRect clip, bool planar) {
  CHECK(proofs_agree(shape, clip, 0.0) == planar);
  CHECK(proofs_agree(shape, clip, kDefaultSweepCrossingBudget));
}

Contour polygon(Point centre, double rx, double ry, int n, double turn = 0.0, bool reversed = false) {
  Contour c;
  for (int i = 0; i < n; ++i) {
    const double a = turn + 2.0 * std::numbers::pi * (reversed ? -i : i) / n;
    c.push_back({centre.x + rx * std::cos(a), centre.y + ry * std::sin(a)});
  }
  return c;
}

Contour rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

constexpr IntRect kClip{0, 0, 64, 64};

}  // namespace

TEST_CASE("the few-chain proof leaves the general sweep's pieces", "[raster][planar]") {
  SECTION("a circle, a triangle, a rectangle") {
    check_same({polygon({20, 20}, 12, 12, 64)}, kClip, true);
    check_same({{{5, 3}, {40, 30}, {2, 50}}}, kClip, true);
    check_same({rect(3.5, 4.25, 50.75, 40)}, kClip, true);
  }
  SECTION("a ring, both orientations of the hole, and two rings nested") {
    check_same({polygon({30, 30}, 20, 18, 40), polygon({30, 30}, 10, 9, 40, 0.1, true)}, kClip, true);
    check_same({polygon({30, 30}, 20, 18, 40), polygon({30, 30}, 10, 9, 40, 0.1)}, kClip, true);
    check_same({polygon({30, 30}, 25, 25, 48), polygon({30, 30}, 18, 18, 48, 0.2),
                polygon({30, 30}, 11, 11, 48, 0.3, true), polygon({30, 30}, 4, 4, 48, 0.4)},
               kClip, true);
  }
  SECTION("shapes that nearly touch, touch at a vertex, share a side, coincide") {
    check_same({{{5, 5}, {20, 30}, {5, 55}}, {{20.000001, 30}, {40, 5}, {40, 55}}}, kClip, true);
    check_same({{{5, 5}, {20, 30}, {5, 55}}, {{20, 30}, {40, 5}, {40, 55}}}, kClip, true);
    check_same({rect(5, 5, 20, 40), rect(20, 10, 35, 50)}, kClip, true);
    check_same({{{5, 3}, {40, 30}, {2, 50}}, {{5, 3}, {40, 30}, {2, 50}}}, kClip, true);
    check_same({{{5, 3}, {40, 30}, {2, 50}}, {{2, 50}, {40, 30}, {5, 3}}}, kClip, true);
  }
  SECTION("clipped: vertical sides on the clip's left side, open on its right") {
    check_same({polygon({2, 30}, 20, 20, 32)}, kClip, true);
    check_same({polygon({60, 30}, 20, 20, 32)}, kClip, true);
    check_same({rect(-10, 5, 80, 20), rect(-5, 30, 70, 50)}, kClip, true);
  }
  SECTION("a crossing: both proofs stop") {
    check_same({{{5, 5}, {40, 40}, {40, 5}, {5, 40}}}, kClip, false);
    check_same({polygon({20, 30}, 15, 15, 24), polygon({30, 30}, 15, 15, 24)}, kClip, false);
  }
  SECTION("random polygons of up to 16 chains, planar or not") {
    std::mt19937 rng(20261128);
    std::uniform_real_distribution<double> coordinate(-4.0, 68.0);
    std::uniform_int_distribution<int> sides(3, 8);
    int planar = 0;
    int crossing = 0;
    for (int round = 0; round < 300; ++round) {
      Shape shape(static_cast<std::size_t>(1 + round % 3));
      for (Contour& contour : shape) {
        const int n = sides(rng);
        for (int i = 0; i < n; ++i) contour.push_back({coordinate(rng), coordinate(rng)});
      }
      ScanState s;
      load(s, shape, kClip);
      if (s.planar_chains.empty() || s.planar_chains.size() > kFewChains) continue;
      INFO("round " << round);
      if (proofs_agree(shape, kClip, 0.0)) {
        ++planar;
      } else {
        ++crossing;
      }
      proofs_agree(shape, kClip, kDefaultSweepCrossingBudget);
    }
    CHECK(planar > 30);  // both kinds are reached
    CHECK(crossing > 30);
  }
}
