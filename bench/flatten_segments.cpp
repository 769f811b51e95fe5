// flatten_segments: how many segments each flattening strategy emits, how close that is to the fewest
// possible, whether it keeps the tolerance, and how long it takes. A plain program that prints a Markdown
// table (docs/flattening.md holds a copy); not a test.
//
// Strategies, all with vertices on the curve:
//  - ours:    flatten_bezier / flatten_rational (adaptive walk, exact chord-distance bound);
//  - halving: Cairo's decomposition (cairo-spline.c: _cairo_spline_decompose_into), split at t = 1/2 until
//             both inner control points are within tolerance of the chord segment; explicit stack here;
//  - Wang:    uniform parameter steps, n = ceil(sqrt(d(d-1)·M / (8·tol))), M = max|P_{i+2} - 2P_{i+1} + P_i|
//             (polynomial curves only: the formula bounds |C''|, which a rational curve does not have);
//  - greedy:  the LOWER BOUND: from each vertex the farthest curve point whose chord stays within
//             tolerance, by bisection on t; the chord's Hausdorff distance is measured as
//             sup_t dist(C(t), chord), which equals the Hausdorff distance because dist(C(t), chord) >=
//             |d(t)| >= the chord -> curve distance (proof in curves/src/flatness_bound.h), on 64 samples
//             refined by golden section around the worst one.
// Violations: the polyline is measured against the curve with the unit tests' dense measurement
// (tests/unit/flatten/hausdorff_measure.h); a curve counts when either direction exceeds tolerance by
// more than 1e-9 relative.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "../tests/unit/flatten/hausdorff_measure.h"
#include "curvescan/curves/bezier.h"
#include "curvescan/curves/flatten.h"
#include "curvescan/curves/rational_bezier.h"
#include "curvescan/text/coverage_mask.h"
#include "curvescan/text/font.h"

namespace {

using curvescan::Point;
using curvescan::Vec2;

struct Curve {
  std::vector<Point> ctrl;
  std::vector<double> weights;  // empty: polynomial
  [[nodiscard]] Point eval(double t) const {
    return weights.empty() ? curvescan::de_casteljau(ctrl, t)
                           : curvescan::rational_de_casteljau(ctrl, weights, t);
  }
};

struct Family {
  std::string name;
  std::vector<Curve> curves;
};

// ---- strategies -------------------------------------------------------------------------------------

std::vector<Point> ours(const Curve& c, double tol) {
  std::vector<Point> out{c.ctrl.front()};
  if (c.weights.empty()) {
    curvescan::flatten_bezier(c.ctrl, tol, out);
  } else {
    curvescan::flatten_rational(c.ctrl, c.weights, tol, out);
  }
  return out;
}

// Homogeneous control points so that one halving routine serves both kinds of curve.
struct H {
  double x, y, w;
};
std::vector<H> homogeneous(const Curve& c) {
  std::vector<H> h(c.ctrl.size());
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double w = c.weights.empty() ? 1.0 : c.weights[i];
    h[i] = {c.ctrl[i].x * w, c.ctrl[i].y * w, w};
  }
  return h;
}
Point project(const H& h) {
  return {h.x / h.w, h.y / h.w};
}

// Cairo's test: max squared distance of the inner control points to the chord segment.
double cairo_error_squared(const std::vector<H>& piece) {
  const Point a = project(piece.front()), d = project(piece.back());
  double worst = 0.0;
  for (std::size_t i = 1; i + 1 < piece.size(); ++i) {
    const double e = curvescan::testing::point_segment_distance(project(piece[i]), a, d);
    worst = std::max(worst, e * e);
  }
  return worst;
}

std::vector<Point> halving(const Curve& c, double tol) {
  std::vector<Point> out{c.ctrl.front()};
  std::vector<std::pair<std::vector<H>, int>> stack{{homogeneous(c), 0}};
  while (!stack.empty()) {
    auto [piece, depth] = std::move(stack.back());
    stack.pop_back();
    if (depth >= 40 || cairo_error_squared(piece) < tol * tol) {
      out.push_back(project(piece.back()));
      continue;
    }
    std::vector<H> left(piece.size()), right(piece.size()), work = piece;
    const std::size_t n = piece.size() - 1;
    left[0] = work[0];
    right[n] = work[n];
    for (std::size_t level = 1; level <= n; ++level) {
      for (std::size_t i = 0; i + level <= n; ++i) {
        work[i] = {0.5 * (work[i].x + work[i + 1].x), 0.5 * (work[i].y + work[i + 1].y),
                   0.5 * (work[i].w + work[i + 1].w)};
      }
      left[level] = work[0];
      right[n - level] = work[n - level];
    }
    stack.push_back({std::move(right), depth + 1});  // right first: the left piece is emitted first
    stack.push_back({std::move(left), depth + 1});
  }
  out.back() = c.ctrl.back();
  return out;
}

std::size_t wang_count(const Curve& c, double tol) {
  const double n = static_cast<double>(c.ctrl.size()) - 1.0;
  double m = 0.0;
  for (std::size_t i = 0; i + 2 < c.ctrl.size(); ++i) {
    m = std::max(m, (c.ctrl[i + 2] - c.ctrl[i + 1] - (c.ctrl[i + 1] - c.ctrl[i])).length());
  }
  return static_cast<std::size_t>(std::max(1.0, std::ceil(std::sqrt(n * (n - 1.0) * m / (8.0 * tol)))));
}

std::vector<Point> wang(const Curve& c, double tol) {
  const std::size_t count = wang_count(c, tol);
  std::vector<Point> out{c.ctrl.front()};
  for (std::size_t i = 1; i < count; ++i)
    out.push_back(c.eval(static_cast<double>(i) / static_cast<double>(count)));
  out.push_back(c.ctrl.back());
  return out;
}

// sup over t in [a, b] of dist(C(t), [C(a), C(b)]): 64 samples, then golden section around the worst.
double chord_hausdorff(const Curve& c, double a, double b) {
  const Point pa = c.eval(a), pb = c.eval(b);
  auto f = [&](double t) { return curvescan::testing::point_segment_distance(c.eval(t), pa, pb); };
  constexpr int kSamples = 64;
  const double h = (b - a) / kSamples;
  int best_i = 0;
  double best = 0.0;
  for (int i = 1; i < kSamples; ++i) {
    const double v = f(a + i * h);
    if (v > best) {
      best = v;
      best_i = i;
    }
  }
  double lo = a + (best_i - 1) * h, hi = a + (best_i + 1) * h;
  const double inv_phi = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int i = 0; i < 40; ++i) {
    const double x1 = hi - inv_phi * (hi - lo), x2 = lo + inv_phi * (hi - lo);
    const double f1 = f(x1), f2 = f(x2);
    best = std::max({best, f1, f2});
    if (f1 > f2) {
      hi = x2;
    } else {
      lo = x1;
    }
  }
  return best;
}

std::size_t greedy_count(const Curve& c, double tol) {
  std::size_t count = 0;
  double a = 0.0;
  while (true) {
    ++count;
    if (chord_hausdorff(c, a, 1.0) <= tol) return count;
    double lo = a, hi = 1.0;
    for (int i = 0; i < 36; ++i) {
      const double mid = 0.5 * (lo + hi);
      (chord_hausdorff(c, a, mid) <= tol ? lo : hi) = mid;
    }
    a = lo > a ? lo : hi;
  }
}

// ---- corpus -----------------------------------------------------------------------------------------

std::vector<Family> corpus() {
  std::mt19937_64 rng(512);
  std::uniform_real_distribution<double> coord(0.0, 512.0), unit(0.0, 1.0);
  std::vector<Family> families;
  Family cubics{"random cubics", {}};
  for (int i = 0; i < 1000; ++i)
    cubics.curves.push_back({{{coord(rng), coord(rng)},
                              {coord(rng), coord(rng)},
                              {coord(rng), coord(rng)},
                              {coord(rng), coord(rng)}},
                             {}});
  families.push_back(std::move(cubics));

  Family circles{"circles (4 conics each)", {}};
  for (int i = 0; i < 50; ++i) {
    const double r = 2.0 + 254.0 * unit(rng);
    const Point o{256.0, 256.0};
    for (int q = 0; q < 4; ++q) {
      const double a = q * std::numbers::pi / 2;
      auto at = [&](double angle, double radius) {
        return o + Vec2{std::cos(angle), std::sin(angle)} * radius;
      };
      circles.curves.push_back(
          {{at(a, r), at(a + std::numbers::pi / 4, r * std::sqrt(2.0)), at(a + std::numbers::pi / 2, r)},
           {1.0, std::sqrt(0.5), 1.0}});
    }
  }
  families.push_back(std::move(circles));

  Family s_curves{"S-curves", {}};
  for (int i = 0; i < 200; ++i) {
    const double w = 50.0 + 450.0 * unit(rng), h = 20.0 + 230.0 * unit(rng);
    s_curves.curves.push_back({{{0, 0}, {w * unit(rng), h}, {w - w * unit(rng), -h}, {w, 0}}, {}});
  }
  families.push_back(std::move(s_curves));

  Family cusps{"cusps", {}};
  for (int i = 0; i < 200; ++i) {
    // C'(1/2) = 3/4·(P3 + P2 - P1 - P0) = 0: a cusp at the middle.
    const Point p0{coord(rng), coord(rng)}, p1{coord(rng), coord(rng)}, p2{coord(rng), coord(rng)};
    cusps.curves.push_back({{p0, p1, p2, p0 + (p1 - p2)}, {}});
  }
  families.push_back(std::move(cusps));

  // TrueType-like quadratics, what glyph rendering mostly flattens: control points within a box of the
  // size of one outline arc at 12 px and at 100 px (DejaVu Sans arcs span ~1-4 px and ~10-30 px).
  for (const double size : {4.0, 30.0}) {
    Family quads{size < 10.0 ? "glyph quadratics 12 px" : "glyph quadratics 100 px", {}};
    for (int i = 0; i < 2000; ++i) {
      const Point p0{size * unit(rng), size * unit(rng)};
      quads.curves.push_back({{p0, p0 + Vec2{size * unit(rng), size * unit(rng)},
                               p0 + Vec2{size * unit(rng), -size * unit(rng)}},
                              {}});
    }
    families.push_back(std::move(quads));
  }
  return families;
}

// ---- measurement ------------------------------------------------------------------------------------

bool violates(const Curve& c, double tol, const std::vector<Point>& polyline) {
  const curvescan::testing::Measurement m =
      c.weights.empty() ? curvescan::testing::measure_bezier(c.ctrl, tol, polyline)
                        : curvescan::testing::measure_rational(c.ctrl, c.weights, tol, polyline);
  return m.hausdorff() > tol * (1.0 + 1e-9);
}

// Median over runs of the mean time per curve, in microseconds.
double time_per_curve(const Family& f, double tol,
                      const std::function<std::size_t(const Curve&, double)>& run) {
  std::vector<double> runs;
  std::size_t sink = 0;
  for (int r = 0; r < 5; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    for (const Curve& c : f.curves) sink += run(c, tol);
    const auto t1 = std::chrono::steady_clock::now();
    runs.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count() /
                   static_cast<double>(f.curves.size()));
  }
  std::sort(runs.begin(), runs.end());
  if (sink == 0) std::puts("");  // keeps the work observable
  return runs[runs.size() / 2];
}

/// --profile[=ROUNDS[:FAMILY]]: only `ours` at tol 0.1 on the families whose name starts with FAMILY
/// (default "glyph": the glyph-quadratic corpora), ROUNDS times, for `valgrind --tool=callgrind`
/// (instructions per curve and per segment: divide by the counts printed).
int profile(std::string_view arg) {
  const std::size_t colon = arg.find(':');
  const long rounds = arg.empty() ? 1 : std::atol(std::string(arg.substr(0, colon)).c_str());
  const std::string_view family = colon == std::string_view::npos ? "glyph" : arg.substr(colon + 1);
  const std::vector<Family> families = corpus();
  std::size_t curves = 0, segments = 0;
  for (long r = 0; r < rounds; ++r) {
    for (const Family& f : families) {
      if (!f.name.starts_with(family)) continue;
      for (const Curve& c : f.curves) {
        segments += ours(c, 0.1).size() - 1;
        ++curves;
      }
    }
  }
  std::printf("curves %zu segments %zu\n", curves, segments);
  return 0;
}

/// --glyphs=PPEM[:ROUNDS]: every glyph of DejaVu Sans at PPEM rendered ROUNDS times through the whole
/// fill pipeline (MaskRenderer, tolerance 0.1 px, as glyph_bench), for `valgrind --tool=callgrind`:
/// instructions per glyph of the pipeline (MaskRenderer::render) and of the flattener (flatten_bezier),
/// divided by the render count printed. --glyph-segments=PPEM: the glyphs' curves and the segments the
/// flattener emits for them (a separate run, so that it does not add flattener calls to a profile).
int glyphs(std::string_view arg, bool segments_only) {
  const std::size_t colon = arg.find(':');
  const double ppem = std::atof(std::string(arg.substr(0, colon)).c_str());
  const long rounds =
      colon == std::string_view::npos ? 1 : std::atol(std::string(arg.substr(colon + 1)).c_str());
  const auto font = curvescan::Font::open("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf");
  if (!font || !(ppem > 0.0)) {
    std::fprintf(stderr, "cannot open DejaVu Sans, or bad size\n");
    return 1;
  }
  std::vector<curvescan::Path> outlines;
  for (curvescan::GlyphId glyph = 0; glyph < font->glyph_count(); ++glyph) {
    const auto outline = font->freetype_scaled_glyph_path(glyph, ppem);
    if (!outline) continue;
    auto device = outline->transformed(curvescan::Affine::scale(1.0, -1.0));
    if (device && !device->empty()) outlines.push_back(std::move(*device));
  }
  if (segments_only) {
    std::size_t curves = 0, segments = 0;
    std::vector<Point> polyline;
    for (const curvescan::Path& path : outlines) {
      for (const curvescan::PathElement& element : path) {
        if (element.degree() < 2) continue;
        polyline.clear();
        if (element.is_rational()) {
          curvescan::flatten_rational(element.points, element.weights, 0.1, polyline);
        } else {
          curvescan::flatten_bezier(element.points, 0.1, polyline);
        }
        ++curves;
        segments += polyline.size();
      }
    }
    std::printf("glyphs %zu curves %zu segments %zu\n", outlines.size(), curves, segments);
    return 0;
  }
  curvescan::MaskRenderer renderer;
  curvescan::CoverageMask mask;
  std::size_t renders = 0;
  for (long r = 0; r < rounds; ++r) {
    for (const curvescan::Path& path : outlines) {
      if (!renderer.render(path, curvescan::pixel_box(path), curvescan::FillRule::kNonZero, 0.1, mask))
        return 1;
      ++renders;
    }
  }
  std::printf("renders %zu\n", renders);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string_view(argv[1]).starts_with("--glyphs=")) {
    return glyphs(std::string_view(argv[1]).substr(9), false);
  }
  if (argc > 1 && std::string_view(argv[1]).starts_with("--glyph-segments=")) {
    return glyphs(std::string_view(argv[1]).substr(17), true);
  }
  if (argc > 1 && std::string_view(argv[1]).starts_with("--profile")) {
    const std::string_view arg(argv[1]);
    return profile(arg.size() > 10 ? arg.substr(10) : std::string_view());
  }
  const std::array<double, 4> tolerances{0.01, 0.1, 0.25, 1.0};
  std::puts(
      "| corpus | tol px | greedy LB | ours | ×LB | halving (Cairo) | ×LB | Wang | ×LB | violations "
      "ours / halving / Wang | µs/curve ours / halving / Wang |");
  std::puts("|---|---|---|---|---|---|---|---|---|---|---|");
  for (const Family& f : corpus()) {
    const bool polynomial = f.curves.front().weights.empty();
    for (const double tol : tolerances) {
      std::size_t lb = 0, n_ours = 0, n_half = 0, n_wang = 0, v_ours = 0, v_half = 0, v_wang = 0;
      for (const Curve& c : f.curves) {
        lb += greedy_count(c, tol);
        const auto a = ours(c, tol), b = halving(c, tol);
        n_ours += a.size() - 1;
        n_half += b.size() - 1;
        v_ours += violates(c, tol, a);
        v_half += violates(c, tol, b);
        if (polynomial) {
          const auto w = wang(c, tol);
          n_wang += w.size() - 1;
          v_wang += violates(c, tol, w);
        }
      }
      const double t_ours =
          time_per_curve(f, tol, [](const Curve& c, double t) { return ours(c, t).size(); });
      const double t_half =
          time_per_curve(f, tol, [](const Curve& c, double t) { return halving(c, t).size(); });
      auto ratio = [lb](std::size_t n) { return static_cast<double>(n) / static_cast<double>(lb); };
      if (polynomial) {
        const double t_wang =
            time_per_curve(f, tol, [](const Curve& c, double t) { return wang(c, t).size(); });
        std::printf(
            "| %s | %g | %zu | %zu | %.3f | %zu | %.3f | %zu | %.3f | %zu / %zu / %zu | %.2f / %.2f / %.2f "
            "|\n",
            f.name.c_str(), tol, lb, n_ours, ratio(n_ours), n_half, ratio(n_half), n_wang, ratio(n_wang),
            v_ours, v_half, v_wang, t_ours, t_half, t_wang);
      } else {
        std::printf(
            "| %s | %g | %zu | %zu | %.3f | %zu | %.3f | n/a | n/a | %zu / %zu / n/a | %.2f / %.2f / n/a |\n",
            f.name.c_str(), tol, lb, n_ours, ratio(n_ours), n_half, ratio(n_half), v_ours, v_half, t_ours,
            t_half);
      }
      std::fflush(stdout);
    }
  }
  return 0;
}
