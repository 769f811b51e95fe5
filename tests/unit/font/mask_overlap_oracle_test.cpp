// Coverage masks (Rasterizer::rasterize_mask, the path of every glyph bitmap) against the plain reference
// scan (rasterize_reference) on the same edges, on the inputs where a shortcut that trusts the plain
// signed-area accumulation would go wrong: overlapping contours of one orientation (winding 2), of opposite
// orientations (winding +1 beside -1), a contour drawn twice, nested contours of one orientation under
// even-odd, edges a hair apart, and every glyph of two fonts at subpixel offsets, tiny and huge.
//
// Metric: at most 1 step of 255 per pixel. Both compute the exact area in double up to the order of the
// sums, and the mask's float cells are off by less than 0.125 of a step (dense_coverage.h), so only a value
// within that of a rounding midpoint may round the other way, by one step.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <span>
#include <vector>

#include "coverage_mask.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/rasterizer.h"
#include "curvescan/text/coverage_mask.h"
#include "curvescan/text/font.h"
#include "font_files.h"
#include "glyph_outlines.h"
#include "mask_against_reference.h"

namespace curvescan {
namespace {

constexpr double kTolerance = 0.1;  // the flattening tolerance of glyph rendering (glyph_bench)

using testing::MaskComparison;

/// The mask of `path` over its own pixel box against the reference scan of the same edges.
MaskComparison compare(const Path& path, FillRule rule) {
  return testing::compare_mask_with_reference(path, pixel_box(path), rule, kTolerance);
}

/// A closed polygon through `points`, in order.
void polygon(PathBuilder& builder, std::initializer_list<Point> points) {
  bool first = true;
  for (const Point p : points) {
    if (first) {
      builder.move_to(p);
    } else {
      builder.line_to(p);
    }
    first = false;
  }
  builder.close();
}

/// An axis-aligned rectangle, clockwise on screen (y down) or counter-clockwise.
void rectangle(PathBuilder& builder, double x0, double y0, double x1, double y1, bool clockwise) {
  if (clockwise) {
    polygon(builder, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
  } else {
    polygon(builder, {{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}});
  }
}

Path built(PathBuilder& builder) {
  Result<Path> path = builder.build();
  REQUIRE(path.is_ok());
  return std::move(*path);
}

TEST_CASE("coverage masks of overlapping, stacked and twice-drawn contours match the reference scan",
          "[font][mask][oracle]") {
  // Offsets that put the edges at integer, half and irregular positions inside pixels.
  for (const double offset : {0.0, 0.5, 0.3125, 0.71}) {
    INFO("offset " << offset);
    for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
      INFO((rule == FillRule::kNonZero ? "nonzero" : "even-odd"));
      const double o = offset;
      {
        PathBuilder b;  // one orientation, overlapping: winding 2 in the middle
        rectangle(b, 1.2 + o, 1.1 + o, 6.7 + o, 5.3 + o, true);
        rectangle(b, 3.4 + o, 2.9 + o, 9.1 + o, 8.6 + o, true);
        CHECK(compare(built(b), rule).worst <= 1);
      }
      {
        PathBuilder b;  // opposite orientations, overlapping: +1, -1 and 0 side by side
        rectangle(b, 1.2 + o, 1.1 + o, 6.7 + o, 5.3 + o, true);
        rectangle(b, 3.4 + o, 2.9 + o, 9.1 + o, 8.6 + o, false);
        CHECK(compare(built(b), rule).worst <= 1);
      }
      {
        PathBuilder b;  // a triangle drawn twice: nonzero fills it once, even-odd not at all
        polygon(b, {{1.3 + o, 0.7}, {8.9, 3.2 + o}, {2.1, 7.8 + o}});
        polygon(b, {{1.3 + o, 0.7}, {8.9, 3.2 + o}, {2.1, 7.8 + o}});
        CHECK(compare(built(b), rule).worst <= 1);
      }
      {
        PathBuilder b;  // nested, one orientation: winding 2 inside the inner one (even-odd: a hole)
        rectangle(b, 0.5 + o, 0.5 + o, 9.5 + o, 9.5 + o, true);
        rectangle(b, 3.3 + o, 3.6 + o, 6.2 + o, 5.9 + o, true);
        CHECK(compare(built(b), rule).worst <= 1);
      }
      {
        PathBuilder b;  // nested, opposite orientations: a hole under both rules
        rectangle(b, 0.5 + o, 0.5 + o, 9.5 + o, 9.5 + o, true);
        rectangle(b, 3.3 + o, 3.6 + o, 6.2 + o, 5.9 + o, false);
        CHECK(compare(built(b), rule).worst <= 1);
      }
      {
        PathBuilder b;  // a small contour inside one pixel, on top of a filled region (winding 2 there)
        rectangle(b, 0.5 + o, 0.5 + o, 9.5 + o, 9.5 + o, true);
        polygon(b, {{4.2 + o, 4.1}, {4.8 + o, 4.3}, {4.4 + o, 4.9}});
        CHECK(compare(built(b), rule).worst <= 1);
      }
      for (const double gap : {0.0, 1e-12, 1e-9, 1e-6, -1e-9, -1e-6}) {
        INFO("gap " << gap);
        // Two rectangles side by side whose shared side is a hair apart (or overlapping by a hair),
        // in one orientation and in opposite ones, and one on top of the other.
        for (const bool same : {true, false}) {
          PathBuilder b;
          rectangle(b, 1.25 + o, 1.5, 4.5 + o, 7.75, true);
          rectangle(b, 4.5 + o + gap, 2.5, 8.25 + o, 6.5 + o, same);
          CHECK(compare(built(b), rule).worst <= 1);
        }
        PathBuilder b;
        rectangle(b, 1.25 + o, 1.5, 7.5 + o, 7.75, true);
        rectangle(b, 1.25 + o + gap, 1.5 + gap, 7.5 + o, 7.75 + gap, false);
        CHECK(compare(built(b), rule).worst <= 1);
      }
    }
  }
}

TEST_CASE("coverage masks of random overlapping triangles match the reference scan", "[font][mask][oracle]") {
  std::mt19937 random(20261127);
  std::uniform_real_distribution<double> coordinate(0.0, 12.0);
  for (int scene = 0; scene < 300; ++scene) {
    PathBuilder b;
    const int triangles = 1 + scene % 4;
    for (int t = 0; t < triangles; ++t) {
      polygon(b, {{coordinate(random), coordinate(random)},
                  {coordinate(random), coordinate(random)},
                  {coordinate(random), coordinate(random)}});
    }
    const Path path = built(b);
    for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
      INFO("scene " << scene << (rule == FillRule::kNonZero ? " nonzero" : " even-odd"));
      CHECK(compare(path, rule).worst <= 1);
    }
  }
}

/// Every stride-th glyph of `file` at `pixels_per_em`, moved by (dx, dy): alone, under its own copy
/// (every contour drawn twice) and under its mirror image (reversed contours over the original ones).
/// Returns how many of the glyphs alone were proven planar (nonzero).
int check_glyphs(const char* file, double pixels_per_em, int stride, double dx, double dy, int& visited) {
  int fast = 0;
  visited =
      testing::for_each_glyph_outline(file, pixels_per_em, stride, [&](GlyphId glyph, const Path& device) {
        const Result<Path> moved = device.transformed(Affine::translate(dx, dy));
        REQUIRE(moved.is_ok());
        INFO(file << " glyph " << glyph << " at " << pixels_per_em << " px + (" << dx << ", " << dy << ")");
        for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
          const MaskComparison alone = compare(*moved, rule);
          CHECK(alone.worst <= 1);
          if (rule == FillRule::kNonZero && alone.fast_path) ++fast;
        }
        const Result<Path> doubled_path = [&] {
          PathBuilder b;
          for (int copy = 0; copy < 2; ++copy) {
            const std::span<const Point> points = moved->points();
            std::size_t next = 0;
            for (const PathVerb verb : moved->verbs()) {
              switch (verb) {
                case PathVerb::kMove:
                  b.move_to(points[next++]);
                  break;
                case PathVerb::kLine:
                  b.line_to(points[next++]);
                  break;
                case PathVerb::kQuad:
                  b.quad_to(points[next], points[next + 1]);
                  next += 2;
                  break;
                case PathVerb::kCubic:
                  b.cubic_to(points[next], points[next + 1], points[next + 2]);
                  next += 3;
                  break;
                case PathVerb::kClose:
                  b.close();
                  break;
                default:
                  break;
              }
            }
          }
          return b.build();
        }();
        REQUIRE(doubled_path.is_ok());
        for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
          CHECK(compare(*doubled_path, rule).worst <= 1);
        }
      });
  return fast;
}

TEST_CASE("glyph masks at subpixel offsets, tiny and huge, alone and drawn twice, match the reference scan",
          "[font][mask][oracle]") {
  struct Size {
    double pixels_per_em;
    int stride;
  };
  // Fewer glyphs at the large sizes: the reference resolves every row from scratch (O(rows · edges²)).
  for (const char* file : {kDejaVuSansFile, kCantarellFile}) {
    for (const Size size :
         {Size{2.0, 7}, Size{5.0, 7}, Size{12.0, 3}, Size{32.0, 13}, Size{100.0, 61}, Size{1000.0, 997}}) {
      for (const auto& [dx, dy] : {std::pair{0.0, 0.0}, std::pair{0.25, 0.5}, std::pair{0.73, 0.11}}) {
        int visited = 0;
        const int fast = check_glyphs(file, size.pixels_per_em, size.stride, dx, dy, visited);
        CHECK(visited >= (size.pixels_per_em > 100.0 ? 2 : 4));
        // Almost every glyph alone is proven planar (contours that do not overlap), so the oracle above
        // checks the planar path and not only the row scan. The few that are not hold overlapping or
        // crossing contours (measured: 72 of the 6,190 glyphs of DejaVu Sans at 12 px, none of Cantarell's).
        if (size.pixels_per_em >= 12.0) CHECK(fast * 10 >= visited * 9);
      }
    }
  }
}

}  // namespace
}  // namespace curvescan
