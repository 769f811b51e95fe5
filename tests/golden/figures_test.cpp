// Golden tests of the gallery (examples/figure/figures.h): every figure of the course notes and every
// scene is rendered by the same function the example program calls, and compared with its reviewed
// reference image in tests/golden/reference_images/figures/<name>.png through compare_to_golden.
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
// caps against their end guides, dash patterns and dots.
//
// After a deliberate change: run the test, open golden-reports/figures/<name>/index.html, and copy
// actual.png over the reference once reviewed. Or render all with `tools/render_examples.sh BUILD OUT`
// (the same pixels) and review/accept with `curvescan diff --expected
// tests/golden/reference_images/figures --actual OUT --report REPORT [--update]` (docs/diff.md).
#include <catch2/catch.hpp>
#include <filesystem>
#include <set>
#include <string>

#include "curvescan/raster/image_diff.h"
#include "figure/figures.h"

using namespace curvescan;

namespace {

std::filesystem::path references() {
  return std::filesystem::path(CURVESCAN_SOURCE_DIR) / "tests/golden/reference_images/figures";
}

}  // namespace

TEST_CASE("golden: every gallery figure matches its reviewed reference image", "[golden][figures]") {
  DiffOptions options;
  options.metric = PixelMetric::kPerChannel;
  options.channel_tolerance = 1;
  const std::filesystem::path reports = std::filesystem::path(CURVESCAN_BINARY_DIR) / "golden-reports/figures";
  for (const figure::FigureInfo& info : figure::all_figures()) {
    INFO("figure " << info.name);
    Result<Image> image = info.render();
    REQUIRE(image.is_ok());
    const Status status = compare_to_golden(*image, references() / (std::string(info.name) + ".png"), options, reports);
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
