// Golden tests of the gallery (examples/figure/figures.h): every figure of the course notes and every
// scene is rendered by the same function the example program calls, and compared with its reviewed
// reference image in reference_images/figures/<name>.png through compare_to_golden.
//
// Threshold: per-channel, 1 level, no differing pixel allowed. The figures are drawn by the same code
// with the same font file (DejaVu Sans from Debian's fonts-dejavu-core, looked up without fallback, so a
// machine without it fails with a clear message instead of comparing another face) and curvescan's own
// exact-area rasterizer — FreeType only supplies the outlines, never pixels — so the output is
// deterministic and identical on every machine built alike. The one level absorbs a coverage or gradient
// value computed exactly on a rounding boundary that another CPU or compiler (FMA contraction) may round
// the other way; anything larger is a real change to review.
//
// Review done for the committed references (each PNG looked at in full): axes, ticks and labels legible
// and not clipped; every curve in its stated colour and shape (basis functions non-negative, peaks where
// expected, sums and products of the Cox–de Boor figure consistent, the knot-inserted curve identical to
// the original, the NURBS circle on its square, de Casteljau's last point on the curve, centripetal
// Catmull–Rom free of the uniform one's loop, C0/C1/C2 joins as classify_join reports, the triple knot
// passing through P3); the scenes: stars, gradient sky, halo, group-opacity hill, dashed closed B-spline,
// petals; text sizes, kerning on/off, gradient text, glyph control points; miter fallback vs miter-clip,
// caps against their end guides, dash patterns and dots; the teapot: all 32 patches present (rim, body,
// handle, spout, lid with its knob, bottom), boundaries dark and interior iso-curves blue, the perspective
// view foreshortened (the near side larger) and nothing clipped by the canvas; curve_representations: tan
// in three branches with no line across a pole, the lemniscate one figure eight with its node ringed at the
// origin, y² = x³ − x a closed oval and an open branch in two colours.
//
// After a deliberate change: run the test, open golden-reports/figures/<name>/index.html, and copy
// actual.png over the reference once reviewed. Or render all with `tools/render_examples.sh BUILD OUT`
// (the same pixels) and review/accept with `curvescan diff --expected
// reference_images/figures --actual OUT --report REPORT [--update]` (docs/diff.md).
#include "figure/figures.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "curvescan/curves/basis_matrix.h"
#include "curvescan/curves/bezier.h"
#include "curvescan/curves/bspline.h"
#include "curvescan/diff/image_diff.h"
#include "figure/graphs.h"

using namespace curvescan;

namespace {

std::filesystem::path references() {
  return std::filesystem::path(CURVESCAN_SOURCE_DIR) / "reference_images/figures";
}

}  // namespace

TEST_CASE("golden: every gallery figure matches its reviewed reference image", "[golden][figures]") {
  DiffOptions options;
  options.metric = PixelMetric::kPerChannel;
  options.channel_tolerance = 1;
  const std::filesystem::path reports =
      std::filesystem::path(CURVESCAN_BINARY_DIR) / "golden-reports/figures";
  for (const figure::FigureInfo& info : figure::all_figures()) {
    INFO("figure " << info.name);
    Result<Image> image = info.render();
    REQUIRE(image.is_ok());
    const Status status =
        compare_to_golden(*image, references() / (std::string(info.name) + ".png"), options, reports);
    INFO((status.is_ok() ? std::string() : status.error().message));
    CHECK(status.is_ok());
  }
}

TEST_CASE("golden: every figure reference image belongs to a registered figure", "[golden][figures]") {
  // A renamed or removed figure must take its reference with it, or the directory fills with images that
  // nothing checks any more.
  std::set<std::string> registered;
  for (const figure::FigureInfo& info : figure::all_figures()) {
    CHECK(registered.insert(std::string(info.name)).second);  // names are unique
  }
  for (const auto& entry : std::filesystem::directory_iterator(references())) {
    INFO("reference " << entry.path().filename().string());
    CHECK(entry.path().extension() == ".png");
    CHECK(registered.count(entry.path().stem().string()) == 1);
  }
}

TEST_CASE("golden: a figure renders the same image twice", "[golden][figures]") {
  // Determinism within one process (no state carried between renders: font, canvas, rasterizer) is what
  // makes a zero-pixel golden threshold meaningful. Two figures: a text-heavy and a gradient-heavy one.
  for (const char* name : {"text_specimen", "illustration"}) {
    INFO("figure " << name);
    const figure::FigureInfo* info = figure::find_figure(name);
    REQUIRE(info != nullptr);
    Result<Image> first = info->render();
    Result<Image> second = info->render();
    REQUIRE(first.is_ok());
    REQUIRE(second.is_ok());
    CHECK(*first == *second);
  }
}

// The figures plot basis and blending functions as exact curves (examples/figure/graphs.h). These tests
// hold each graph to the function it claims to be: every point (x, y) of it has y = f(x). The tolerance
// 1e-12 is a few hundred ulps of values of order 1: de Casteljau and the knot insertions of to_beziers
// each round at the 1e-16 level, far below it; a wrong control point would be off by 1e-2 or more.

namespace {

constexpr double kGraphTolerance = 1e-12;

/// Checks that every piece of `graph`, sampled at 31 parameters strictly inside it, lies on y = f(x).
/// (A piece's end points are left out: at a knot of multiplicity p + 1 the function jumps, and the piece
/// rightly ends at the one-sided limit, which the half-open convention does not give there.)
template <class F>
void check_graph(const std::vector<Bezier>& graph, F f) {
  REQUIRE_FALSE(graph.empty());
  for (const Bezier& piece : graph) {
    for (int k = 1; k < 32; ++k) {
      const Point p = piece.eval(k / 32.0);
      INFO("x = " << p.x);
      CHECK_THAT(p.y, Catch::Matchers::WithinAbs(f(p.x), kGraphTolerance));
    }
  }
}

}  // namespace

TEST_CASE("figure graphs: B-spline basis graphs lie on N_{i,p}, also on the end spans",
          "[golden][figures][graphs]") {
  const std::vector<std::vector<double>> knot_vectors{{0, 1, 2, 3, 4, 5, 6, 7, 8},
                                                      {0, 0, 0, 0, 0.25, 0.5, 0.5, 1, 1, 1, 1},
                                                      {0, 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1, 1},
                                                      {0, 0.3, 0.35, 1.2, 2.0, 2.0, 3.5, 4.0, 4.1}};
  for (const std::vector<double>& knots : knot_vectors) {
    for (int p = 1; p <= 3; ++p) {
      const std::size_t count = knots.size() - static_cast<std::size_t>(p) - 1;
      for (std::size_t i = 0; i < count; ++i) {
        INFO("degree " << p << ", function " << i << ", knots starting " << knots.front() << ", "
                       << knots[1]);
        const std::vector<Bezier> graph = figure::basis_function_graph(knots, p, i);
        // The graph spans exactly the support [u_i, u_{i+p+1}] ...
        const double lo = knots[i];
        const double hi = knots[i + static_cast<std::size_t>(p) + 1];
        if (!(lo < hi)) {
          CHECK(graph.empty());
          continue;
        }
        // (Greville abscissae are means of knots, so the ends are lo and hi up to rounding.)
        CHECK_THAT(graph.front().start().x, Catch::Matchers::WithinAbs(lo, kGraphTolerance));
        CHECK_THAT(graph.back().end().x, Catch::Matchers::WithinAbs(hi, kGraphTolerance));
        // ... and is the function itself, including on the first and last p spans, outside the curve's
        // domain, where bspline_basis extends the end polynomials instead (bspline.h).
        check_graph(graph, [&](double u) { return figure::basis_function(knots, p, i, u); });
        // Inside the domain [u_p, u_n], basis_function is the library's Cox–de Boor reference.
        const double domain_start = knots[static_cast<std::size_t>(p)];
        const double domain_end = knots[count];
        for (int k = 0; k <= 40; ++k) {
          const double u = domain_start + (domain_end - domain_start) * k / 40.0;
          CHECK_THAT(figure::basis_function(knots, p, i, u),
                     Catch::Matchers::WithinAbs(bspline_basis(knots, p, i, u), kGraphTolerance));
        }
      }
    }
  }
}

TEST_CASE("figure graphs: basis_function is the textbook N_{i,p} outside the domain",
          "[golden][figures][graphs]") {
  // Uniform knots 0..4, p = 1: N_{0,1} is the hat on [0, 2]; at u = 0.5 it is 0.5 (rising edge), while the
  // curve domain is [1, 3], so bspline_basis extends the falling edge 2 - u there and gives 1.5.
  const std::vector<double> knots{0, 1, 2, 3, 4};
  CHECK(figure::basis_function(knots, 1, 0, 0.5) == 0.5);
  CHECK(figure::basis_function(knots, 1, 0, 2.5) == 0.0);
  CHECK(figure::basis_function(knots, 1, 0, -1.0) == 0.0);
  CHECK(std::isnan(figure::basis_function(knots, 1, 0, std::nan(""))));
  // Partition of unity on the whole knot range for the degree-0 functions: exactly one is 1.
  for (double u : {0.0, 0.5, 1.0, 2.0, 3.999}) {
    double sum = 0.0;
    for (std::size_t i = 0; i < 4; ++i) sum += figure::basis_function(knots, 0, i, u);
    CHECK(sum == 1.0);
  }
}

TEST_CASE("figure graphs: Bernstein and blending graphs lie on their polynomials",
          "[golden][figures][graphs]") {
  for (int n : {1, 2, 3, 5, 10}) {
    for (int i = 0; i <= n; ++i) {
      INFO("B(" << n << ", " << i << ")");
      check_graph({figure::bernstein_graph(n, i)}, [&](double t) { return bernstein(n, i, t); });
    }
  }
  for (const BasisMatrix* m :
       {&kHermiteBasis, &kBezierBasis, &kUniformBSplineBasis, &kMidpointTangentBasis}) {
    for (int j = 0; j < 4; ++j) {
      INFO("blending function " << j);
      check_graph({figure::blending_graph(*m, j)},
                  [&](double t) { return blending_functions(*m, t)[static_cast<std::size_t>(j)]; });
    }
  }
  // A quadratic through three of its values is the quadratic.
  const auto f = [](double u) { return 0.5 * u * u - 1.5 * u + 0.25; };
  check_graph({figure::quadratic_graph(1.0, 3.0, f(1.0), f(2.0), f(3.0))}, f);
}
