// The byte pass of coverage masks (dense_coverage.cpp) takes eight columns per step and writes a group of
// eight cells that are all zero (no boundary piece wrote them) as the carry's byte, without its prefix sum.
// These scenes are chosen to reach every case of that pass, against the plain reference scan
// (rasterize_reference) of the same edges:
//  - rings (an outer and an inner ellipse of opposite orientations, and of one orientation) from 1 to
//    4,100 columns wide: empty margins, full insides and empty holes of many groups, zero groups after
//    full and after partial coverage, up to the widest box accumulated densely (4,096 columns);
//  - boxes of every width from 1 to 40 columns, around the multiples of eight: the row's last columns
//    after the groups of eight, which run into the rows below or, in the last row, stop at its end;
//  - a box larger than its shape (margins of zero groups before and after the shape), a shape cut by the
//    box on all four sides (the clipper's vertical edges on the left side, coverage that stays full up to
//    the right side), and shallow slivers that cross many columns in one row.
//
// Metric: at most 1 step of 255 per pixel. Both compute the exact area in double up to the order of the
// sums, and the mask's float cells are off by less than 0.125 of a step (dense_coverage.h), so only a value
// within that of a rounding midpoint may round the other way, by one step. The masks start filled with 7,
// so a byte the pass leaves unwritten differs wherever the reference is not within a step of 7.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <span>
#include <vector>

#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/rasterizer.h"
#include "curvescan/text/coverage_mask.h"
#include "mask_against_reference.h"

namespace curvescan {
namespace {

constexpr double kTolerance = 0.1;  // the flattening tolerance of glyph rendering (glyph_bench)

using testing::MaskComparison;

MaskComparison compare(const Path& path, IntRect box, FillRule rule) {
  return testing::compare_mask_with_reference(path, box, rule, kTolerance);
}

/// A closed ellipse as exact conics, clockwise on screen (y down) or counter-clockwise.
void ellipse(PathBuilder& builder, Point centre, double rx, double ry, bool clockwise) {
  builder.arc(centre, rx, ry, 0.0, 0.0, clockwise ? 2.0 * std::numbers::pi : -2.0 * std::numbers::pi);
  builder.close();
}

Path built(PathBuilder& builder) {
  Result<Path> path = builder.build();
  REQUIRE(path.is_ok());
  return std::move(*path);
}

TEST_CASE("coverage masks of rings from 1 to 4100 columns wide match the reference scan",
          "[font][mask][oracle]") {
  for (const double width : {1.3, 6.0, 9.7, 33.0, 100.4, 250.0, 509.0, 511.5, 700.0, 1030.0, 4090.5}) {
    INFO("width " << width);
    for (const double offset : {0.0, 0.37}) {
      INFO("offset " << offset);
      // Short boxes: the width is what is tested, and the reference scan costs per pixel.
      const double height = std::min(width, 40.0);
      const Point centre{0.5 * width + offset, 0.5 * height + offset};
      for (const bool opposite : {true, false}) {
        PathBuilder b;
        ellipse(b, centre, 0.5 * width, 0.5 * height, true);
        ellipse(b, centre, 0.3 * width, 0.3 * height, !opposite);
        const Path ring = built(b);
        for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
          INFO((opposite ? "opposite" : "one orientation")
               << (rule == FillRule::kNonZero ? ", nonzero" : ", even-odd"));
          const MaskComparison c = compare(ring, pixel_box(ring), rule);
          CHECK(c.worst <= 1);
          // Every box here must take the dense path that is being tested (kMaxWidth: 4096 columns).
          CHECK(c.fast_path);
        }
      }
    }
  }
}

TEST_CASE("coverage masks of every width from 1 to 40 columns match the reference scan",
          "[font][mask][oracle]") {
  for (int columns = 1; columns <= 40; ++columns) {
    INFO(columns << " columns");
    for (const int rows : {1, 2, 5}) {
      INFO(rows << " rows");
      // A triangle whose slanted sides cross every column of the box, and an ellipse inside it.
      PathBuilder b;
      const double w = columns;
      const double h = rows;
      b.move_to({0.0, 0.0}).line_to({w, 0.3 * h}).line_to({0.4 * w, h});
      b.close();
      const IntRect box{0, 0, columns, rows};
      const MaskComparison c = compare(built(b), box, FillRule::kNonZero);
      CHECK(c.worst <= 1);
      CHECK(c.fast_path);
      PathBuilder e;
      ellipse(e, {0.5 * w, 0.5 * h}, 0.5 * w - 0.05, 0.5 * h - 0.05, false);
      CHECK(compare(built(e), box, FillRule::kNonZero).worst <= 1);
    }
  }
}

TEST_CASE(
    "coverage masks of shapes smaller and larger than their box, and of slivers, match the reference scan",
    "[font][mask][oracle]") {
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    {
      // A ring far inside a box of 300 columns: untouched blocks before, between and after.
      PathBuilder b;
      ellipse(b, {170.3, 30.2}, 60.0, 25.0, true);
      ellipse(b, {170.3, 30.2}, 40.0, 12.0, false);
      const MaskComparison c = compare(built(b), IntRect{-5, 0, 295, 61}, rule);
      CHECK(c.worst <= 1);
      CHECK(c.fast_path);
      CHECK(c.distinct > 20);
    }
    {
      // A ring cut by the box on every side: the clipper's left side, full coverage up to the right side.
      PathBuilder b;
      ellipse(b, {60.25, 40.5}, 70.0, 45.0, false);
      ellipse(b, {60.25, 40.5}, 20.0, 10.0, true);
      const MaskComparison c = compare(built(b), IntRect{3, 1, 117, 79}, rule);
      CHECK(c.worst <= 1);
      CHECK(c.fast_path);
      CHECK(c.distinct > 20);
    }
    {
      // Shallow slivers: every row piece crosses tens of columns.
      PathBuilder b;
      b.move_to({0.5, 0.2}).line_to({231.7, 6.9}).line_to({0.5, 3.1}).close();
      b.move_to({240.0, 7.2}).line_to({3.2, 10.6}).line_to({240.0, 9.8}).close();
      const MaskComparison c = compare(built(b), IntRect{0, 0, 241, 11}, rule);
      CHECK(c.worst <= 1);
      CHECK(c.fast_path);
      CHECK(c.distinct > 20);
    }
  }
}

}  // namespace
}  // namespace curvescan
