// Cairo oracle for strokes: a seeded corpus of 252 stroke scenes — every join (miter, round, bevel) × cap
// (butt, round, square) × dash pattern (solid, even, odd-length, zero-length dots with a negative offset)
// on lines, polylines, quadratics, cubics, arcs, closed polygons and closed curves, widths 0.5 to 100 px,
// one scene in ten under a non-uniform transform — rendered by curvescan and by Cairo (A8,
// CAIRO_ANTIALIAS_DEFAULT), compared as coverage masks with issue 4's metrics and thresholds
// (stroke_scene.h, MaskComparison): far pixels identical, edge pixels max |Δ| <= 20/255 and mean
// <= 4/255, totals within a flat 0.5 % (the fill oracle's 1/255 per edge pixel only below 3.1 px² of
// coverage, where 8-bit rounding is that coarse).
//
// Both render at tolerance 0.02 px so that flattening is far below the pixel metric: curvescan's outline
// is then within 0.02 px of the exact stroke (<= 5/255 of a pixel), and the differences measure Cairo's
// 15-sub-row sampling (17/255 on straight edges) and Cairo's stroker.
//
// Cairo is not strongly correct (Nehab 2020): where the half-width exceeds a curve's radius of curvature
// its offset curves fold and leave notches or spikes, and a cusp inside a curve gets no round cap; and it
// cuts dash ends across the chords of its polyline, not on the curve's normal, which on a wide stroke
// puts a dash end's far corners h·(chord turn)/2 off (up to 255/255 on the 40-100 px dashed curves here).
// On such a scene the Cairo bounds can fail; the swept-area reference (stroke_scene.h, which dashes too)
// then arbitrates: the scene passes only if curvescan is within the same bounds of the reference and
// Cairo is not.
//
// Cairo's totals are off on thin strokes (0.5-2 px): it samples coverage on 15 sub-rows per pixel, and
// its round caps and dots are inscribed pen polygons (short of the disc by ~step²/6 of its area); there
// it is 0.5-1.1 % off the exact area, while curvescan (exact-area rasterizer, area-exact round pieces) is
// within 0.07 % of the reference; on straight butt or square lines, whose exact area is a sum of
// rectangles, curvescan and the reference agree to 0.000 %. Such a scene fails only the totals against
// Cairo and is arbitrated when curvescan is within all bounds of the reference and Cairo's total is the
// farther from the reference's (both may be within 0.5 % of it, on either side).
//
// Arbitrated scenes are counted, reported, and limited to a fifth of the corpus (measured: 41 of 252:
// 27 wide dashed curves and 2 wide cubics where Cairo's pixels are off, 12 thin strokes where its totals
// are). Every scene is held to the bounds: the three former known defects (115, 129, 174: wide dashed
// curves, a short dash across a bend tighter than the half-width, 23-63/255 off the reference) came from
// dash ends cut on an interpolated tangent; with dash ends on the curve and its exact tangent
// (dasher.cpp) they are within 1/255 of the reference.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cstdio>
#include <random>

#include "stroke_scene.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

constexpr double kTolerance = 0.02;

// (ours - other) / other.
double relative_gap(double ours, double other) {
  return other > 0.0 ? (ours - other) / other : 0.0;
}

std::vector<StrokeScene> make_stroke_corpus() {
  std::mt19937 rng(20261121);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto in = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  const auto point = [&] { return Point{in(12, 116), in(12, 116)}; };
  const double widths[] = {0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 40.0, 100.0};
  const LineJoin joins[] = {LineJoin::kMiter, LineJoin::kRound, LineJoin::kBevel};
  const LineCap caps[] = {LineCap::kButt, LineCap::kRound, LineCap::kSquare};
  const char* geometry_names[] = {"line", "polyline",       "quadratic",   "cubic",
                                  "arc",  "closed polygon", "closed curve"};
  std::vector<StrokeScene> corpus;
  for (int i = 0; i < 252; ++i) {
    StrokeScene s;
    using C = SceneCommand;
    const int geometry = i % 7;
    s.commands.push_back({C::kMove, {point()}});
    switch (geometry) {
      case 0:
        s.commands.push_back({C::kLine, {point()}});
        break;
      case 1:
        for (int k = 0, n = 2 + static_cast<int>(in(0, 5)); k < n; ++k)
          s.commands.push_back({C::kLine, {point()}});
        break;
      case 2:
        s.commands.push_back({C::kQuad, {point(), point()}});
        break;
      case 3:
        s.commands.push_back({C::kCubic, {point(), point(), point()}});
        break;
      case 4: {
        const double a0 = in(-3, 3), sweep = (in(0, 1) < 0.5 ? -1 : 1) * in(0.3, 6.0);
        s.commands[0] = {C::kArc, {Point{in(44, 84), in(44, 84)}}, in(8, 40), a0, a0 + sweep};
        s.commands[0].kind = C::kArc;
        // cairo_arc and PathBuilder::arc both start a subpath at the arc's start with no current point.
        break;
      }
      case 5:
        for (int k = 0, n = 2 + static_cast<int>(in(0, 4)); k < n; ++k)
          s.commands.push_back({C::kLine, {point()}});
        s.commands.push_back({C::kClose});
        break;
      default:
        s.commands.push_back({C::kCubic, {point(), point(), point()}});
        s.commands.push_back({C::kQuad, {point(), point()}});
        s.commands.push_back({C::kClose});
        break;
    }
    s.style.width = widths[(i * 5 + i / 7) % 8];
    s.style.join = joins[(i / 7) % 3];
    s.style.cap = caps[(i / 21) % 3];
    s.style.miter_limit = i % 2 == 0 ? 4.0 : 10.0;
    switch ((i / 63) % 4) {
      case 0:
        break;
      case 1:
        s.style.dash_array = {12, 6};
        s.style.dash_offset = in(-20, 20);
        break;
      case 2:
        s.style.dash_array = {9, 4, 2};
        s.style.dash_offset = in(-20, 20);
        break;
      default:
        s.style.dash_array = {0, 8};
        s.style.dash_offset = -3;
        break;
    }
    if (i % 10 == 9) {
      const Affine skewed{in(0.6, 1.4), in(-0.3, 0.3), in(-0.4, 0.4), in(0.6, 1.4), 0, 0};
      s.transform = Affine::translate(64, 64) * skewed * Affine::translate(-64, -64);
    }
    s.name = std::string(geometry_names[geometry]) + " width " + std::to_string(s.style.width) + " join " +
             std::to_string(static_cast<int>(s.style.join)) + " cap " +
             std::to_string(static_cast<int>(s.style.cap)) + " dash " + std::to_string((i / 63) % 4) +
             (i % 10 == 9 ? " transformed" : "");
    corpus.push_back(std::move(s));
  }
  return corpus;
}

}  // namespace

TEST_CASE("stroke corpus matches Cairo within the fill oracle's bounds", "[oracle][stroke]") {
  const std::vector<StrokeScene> corpus = make_stroke_corpus();
  REQUIRE(corpus.size() >= 200);
  int arbitrated = 0, arbitrated_dashed = 0;
  int ref_worst_max = 0;
  double ref_worst_total = 0.0;
  double ref_sum_mean = 0.0;
  int worst_max = 0;
  std::size_t worst_scene = 0;
  double sum_mean = 0.0, worst_total = 0.0;
  for (std::size_t i = 0; i < corpus.size(); ++i) {
    const StrokeScene& scene = corpus[i];
    const CoverageMask ours = render_scene_curvescan(scene, kTolerance);
    const CoverageMask cairo = render_scene_cairo(scene, kTolerance);
    const MaskComparison m = compare_masks(ours, cairo);
    if (!m.within_bounds()) {
      const CoverageMask reference = render_scene_reference(scene);
      const MaskComparison vs_ref = compare_masks(ours, reference);
      const MaskComparison cairo_vs_ref = compare_masks(cairo, reference);
      // Cairo is off when it fails the reference's bounds, or when only the totals of the two renderers
      // disagree (each may be within 0.5 % of the reference, on either side) and Cairo's is the farther.
      const bool cairo_off = !cairo_vs_ref.within_bounds() ||
                             (m.within_pixel_bounds() && std::abs(vs_ref.total_other - m.total_other) >
                                                             std::abs(vs_ref.total_other - m.total_ours));
      const bool arbitrated_ok = vs_ref.within_bounds() && cairo_off;
      INFO("scene " << i << " (" << scene.name << "): far " << m.far_mismatches << " max " << m.max_diff
                    << " mean " << m.mean_diff << " total " << m.total_ours << " vs Cairo " << m.total_other
                    << " | vs reference: ours max " << vs_ref.max_diff << " far " << vs_ref.far_mismatches
                    << " mean " << vs_ref.mean_diff << " total " << vs_ref.total_ours << " vs "
                    << vs_ref.total_other << ", Cairo max " << cairo_vs_ref.max_diff << " far "
                    << cairo_vs_ref.far_mismatches);
      CHECK(arbitrated_ok);
      if (arbitrated_ok) {
        ++arbitrated;
        if (!scene.style.dash_array.empty()) ++arbitrated_dashed;
        std::printf(
            "Stroke oracle: scene %zu (%s) arbitrated by the swept reference: Cairo max %d/255, far %d; "
            "curvescan max %d/255, mean %.2f/255, far %d; totals vs the reference's: curvescan %+.3f %%, "
            "Cairo %+.3f %%\n",
            i, scene.name.c_str(), cairo_vs_ref.max_diff, cairo_vs_ref.far_mismatches, vs_ref.max_diff,
            vs_ref.mean_diff, vs_ref.far_mismatches,
            100.0 * relative_gap(vs_ref.total_ours, vs_ref.total_other),
            100.0 * relative_gap(m.total_other, vs_ref.total_other));
        if (vs_ref.total_ours >= MaskComparison::kResolvedTotal) {
          ref_worst_total =
              std::max(ref_worst_total, std::abs(relative_gap(vs_ref.total_ours, vs_ref.total_other)));
        }
        ref_worst_max = std::max(ref_worst_max, vs_ref.max_diff);
        ref_sum_mean += vs_ref.mean_diff;
      }
      continue;
    }
    if (m.max_diff > worst_max) {
      worst_max = m.max_diff;
      worst_scene = i;
    }
    sum_mean += m.mean_diff;
    if (m.total_ours >= MaskComparison::kResolvedTotal)
      worst_total = std::max(worst_total, std::abs(m.total_ours - m.total_other) / m.total_ours);
  }
  // Arbitration is the exception: at most a fifth of the corpus (measured: the wide dashed curves, where
  // Cairo cuts dash ends across its chords, and wide curves where its offsets fold).
  CHECK(arbitrated <= static_cast<int>(corpus.size() / 5));
  const int held = static_cast<int>(corpus.size()) - arbitrated;
  std::printf(
      "Stroke oracle: %zu scenes, %d arbitrated by the reference (%d dashed): worst max |d| vs reference "
      "%d/255, mean %.3f/255, worst total %.4f %%\n",
      corpus.size(), arbitrated, arbitrated_dashed, ref_worst_max,
      arbitrated > 0 ? ref_sum_mean / arbitrated : 0.0, 100.0 * ref_worst_total);
  std::printf(
      "Stroke oracle: %d scenes vs Cairo: worst max |d| %d/255 (scene %zu, %s); mean edge |d| %.3f/255; "
      "worst total %.4f %%\n",
      held, worst_max, worst_scene, corpus[worst_scene].name.c_str(), sum_mean / held, 100.0 * worst_total);
}
