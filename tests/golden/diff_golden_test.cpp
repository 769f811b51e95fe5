// A golden test through compare_to_golden (image_diff.h), the pattern the golden scenes follow: render
// with Canvas, compare with a reviewed PNG under reference_images/, and on failure find the
// rendered image, the diff and the HTML report in the directory named by the failure message.
//
// The scene exercises every stage the diff must see: exact conic arcs (a ring, even-odd, PathBuilder::arc
// as Umetani, *Parametric Curve*, section 4.1's NURBS circle), a cubic, translucent paint over opaque paint, and transparent
// background left around the shapes.
//
// To (re)make the golden after a deliberate change: run the test, review <report dir>/conic_ring/actual.png
// (and index.html), copy it over the golden, and commit it with the reason.
#include <catch2/catch.hpp>
#include <numbers>

#include "curvescan/diff/image_diff.h"
#include "curvescan/raster/canvas.h"
#include "curvescan/raster/path_builder.h"

using namespace curvescan;

namespace {

Image render_conic_ring() {
  Result<Canvas> canvas = Canvas::create(96, 64);
  REQUIRE(canvas.is_ok());
  constexpr double kTurn = 2.0 * std::numbers::pi;
  Result<Path> ring = PathBuilder()
                          .arc({34.0, 32.0}, 26.0, 26.0, 0.0, 0.0, kTurn)
                          .close()
                          .arc({34.0, 32.0}, 14.5, 14.5, 0.0, 0.0, kTurn)
                          .close()
                          .build();
  REQUIRE(ring.is_ok());
  REQUIRE(canvas->fill(*ring, Paint::solid(Color::from_rgba8(200, 40, 30, 255)), FillRule::kEvenOdd).is_ok());
  Result<Path> wave = PathBuilder()
                          .move_to({40.3, 60.0})
                          .cubic_to({52.0, 2.0}, {70.0, 70.0}, {92.6, 6.2})
                          .line_to({92.6, 60.0})
                          .close()
                          .build();
  REQUIRE(wave.is_ok());
  REQUIRE(canvas->fill(*wave, Paint::solid({0.1, 0.3, 0.9, 0.6}), FillRule::kNonZero).is_ok());
  return std::move(*canvas).take_image();
}

}  // namespace

TEST_CASE("golden: conic ring and translucent cubic wave", "[golden][diff]") {
  const std::filesystem::path golden =
      std::filesystem::path(CURVESCAN_SOURCE_DIR) / "reference_images/diff/conic_ring.png";
  const std::filesystem::path reports = std::filesystem::path(CURVESCAN_BINARY_DIR) / "golden-reports";
  // Per-channel metric, 1 level of tolerance: the rasterizer is exact-area and deterministic, but a
  // coverage computed exactly on a .5 boundary may round either way under another compiler's floating-point
  // contraction (FMA); anything larger is a real change.
  DiffOptions options;
  options.metric = PixelMetric::kPerChannel;
  options.channel_tolerance = 1;
  const Status status = compare_to_golden(render_conic_ring(), golden, options, reports);
  INFO((status.is_ok() ? std::string() : status.error().message));
  CHECK(status.is_ok());
}
