// Glyph masks (MaskRenderer, coverage_mask.h) against the plain reference scan (rasterize_reference, which
// resolves every row from scratch) fed the same edges (add_path_edges with uniform quadratic steps, as
// MaskRenderer): the whole glyph path of the mask — the inline one-segment test and
// flatten_quadratic_bezier_uniform, the planar proof, the dense
// accumulation in 255ths (dense_coverage.h) and its byte pass — or the row scan where the proof fails.
//
// Scenes: real outlines (DejaVu Sans: TrueType quadratics; Cantarell: CFF cubics) at 4 px (features far
// below a pixel, several contours inside one pixel), 12, 32 and 100 px, each
//  - alone, under both fill rules;
//  - with a copy of itself shifted by a fraction of a pixel: contours that overlap and cross, as variable
//    fonts leave them (winding 2 under the overlap, crossings inside pixels);
//  - with its mirror image about the box's vertical centre line, which runs the other way round: reversed
//    contours over the original ones (winding 0 where they overlap under nonzero).
//
// Metric: at most 1 step of 255 per pixel. Both compute the exact area in double up to the order of the
// sums, and the mask's float cells are off by less than 0.125 of a step (dense_coverage.h), so only a
// value sitting within that of a rounding midpoint may round the other way, by one step.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "coverage_mask.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/rasterizer.h"
#include "curvescan/text/coverage_mask.h"
#include "curvescan/text/font.h"
#include "font_files.h"
#include "glyph_outlines.h"
#include "scan/path_edges.h"

namespace curvescan {
namespace {

constexpr double kTolerance = 0.1;  // the flattening tolerance glyph rendering uses (glyph_bench)

/// Appends every contour of `path` mapped by `transform` to `builder`.
void append_path(PathBuilder& builder, const Path& path, const Affine& transform) {
  const std::span<const Point> points = path.points();
  std::size_t next = 0;
  const auto take = [&] { return transform.apply(points[next++]); };
  for (const PathVerb verb : path.verbs()) {
    switch (verb) {
      case PathVerb::kMove:
        builder.move_to(take());
        break;
      case PathVerb::kLine:
        builder.line_to(take());
        break;
      case PathVerb::kQuad: {
        const Point c = take();
        builder.quad_to(c, take());
        break;
      }
      case PathVerb::kCubic: {
        const Point c1 = take();
        const Point c2 = take();
        builder.cubic_to(c1, c2, take());
        break;
      }
      case PathVerb::kClose:
        builder.close();
        break;
      default:
        FAIL("a glyph outline holds only moves, lines, quadratics, cubics and closes");
    }
  }
}

/// The largest difference between the mask MaskRenderer writes and the reference scan of the same edges,
/// over the path's own pixel box (moved to the origin).
int mask_difference(const Path& path, FillRule rule) {
  const IntRect found = pixel_box(path);
  const Result<Path> moved = path.transformed(Affine::translate(-found.x0, -found.y0));
  REQUIRE(moved.is_ok());
  const IntRect box{0, 0, found.x1 - found.x0, found.y1 - found.y0};
  MaskRenderer renderer;
  CoverageMask mask;
  REQUIRE(renderer.render(*moved, box, rule, kTolerance, mask).is_ok());

  Rasterizer rasterizer(box);
  std::vector<Point> scratch;
  detail::add_path_edges(*moved, kTolerance, rasterizer, scratch, SIZE_MAX, detail::QuadraticSteps::kUniform);
  testing::CoverageMask reference(box.x1, box.y1);
  testing::MaskSink sink(reference);
  rasterizer.rasterize_reference(rule, Antialias::kExact, sink);
  REQUIRE(sink.violations == 0);
  REQUIRE(mask.coverage.size() == reference.values.size());
  int worst = 0;
  for (std::size_t i = 0; i < reference.values.size(); ++i) {
    worst = std::max(worst, std::abs(int{mask.coverage[i]} - int{reference.values[i]}));
  }
  return worst;
}

void check_font(const char* file, double pixels_per_em, int glyph_stride) {
  const int checked = testing::for_each_glyph_outline(
      file, pixels_per_em, glyph_stride, [&](GlyphId glyph, const Path& device) {
        const IntRect box = pixel_box(device);
        const double centre = 0.5 * (box.x0 + box.x1);
        PathBuilder overlapping;
        append_path(overlapping, device, Affine::translate(0.0, 0.0));
        append_path(overlapping, device, Affine::translate(0.37, 0.21 * pixels_per_em / 12.0));
        PathBuilder reversed;
        append_path(reversed, device, Affine::translate(0.0, 0.0));
        append_path(reversed, device, Affine{-1.0, 0.0, 0.0, 1.0, 2.0 * centre, 0.0});  // mirror: reversed
        const Result<Path> overlapping_path = overlapping.build();
        const Result<Path> reversed_path = reversed.build();
        REQUIRE(overlapping_path.is_ok());
        REQUIRE(reversed_path.is_ok());
        for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
          INFO(file << " glyph " << glyph << " at " << pixels_per_em << " px, "
                    << (rule == FillRule::kNonZero ? "nonzero" : "even-odd"));
          CHECK(mask_difference(device, rule) <= 1);
          CHECK(mask_difference(*overlapping_path, rule) <= 1);
          CHECK(mask_difference(*reversed_path, rule) <= 1);
        }
      });
  CHECK(checked > 30);
}

TEST_CASE("glyph masks match the reference scan: tiny, overlapping, reversed, both rules",
          "[font][mask][oracle]") {
  // A sample of glyphs per size, fewer at the large sizes (the reference scan resolves every row from
  // scratch and the suite also runs under ASan).
  for (const char* file : {kDejaVuSansFile, kCantarellFile}) {
    check_font(file, 4.0, 5);
    check_font(file, 12.0, 5);
    check_font(file, 32.0, 11);
    check_font(file, 100.0, 37);
  }
}

}  // namespace
}  // namespace curvescan
