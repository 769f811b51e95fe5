// add_path_edges (raster/scan/path_edges.h) against its plain reference add_path_edges_reference: the fast
// walk (flat arrays, whole contours through Rasterizer::add_polyline, no curve cull and the direct
// quadratic flattener when the path lies inside the clip) must add the same edges in the same order and
// return the same count. Checked through what the rasterizer makes of them: the spans of both fills must
// be identical (exact: the same edges give the same doubles), on every glyph of a TrueType font
// (quadratics) and of a CFF font (cubics), in their own box (the fast path) and in boxes that cut them
// (the cull path), and on paths with every verb, huge coordinates and edge budgets.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/rasterizer.h"
#include "curvescan/text/coverage_mask.h"
#include "curvescan/text/font.h"
#include "font_files.h"
#include "glyph_outlines.h"
// Private to raster/ (not API); reached by path, as the flatten tests reach curves/src.
#include "scan/path_edges.h"

namespace curvescan {
namespace {

class RecordingSink final : public SpanSink {
 public:
  void blend(std::span<const Span> spans) override {
    recorded.insert(recorded.end(), spans.begin(), spans.end());
  }
  std::vector<Span> recorded;
};

struct Fill {
  std::size_t edges = 0;
  std::vector<Span> spans;
};

template <class AddEdges>
Fill fill(AddEdges add_edges, const Path& path, IntRect clip, double tolerance, std::size_t max_edges) {
  Rasterizer rasterizer(clip);
  std::vector<Point> scratch;
  Fill result;
  result.edges = add_edges(path, tolerance, rasterizer, scratch, max_edges);
  RecordingSink sink;
  rasterizer.rasterize(FillRule::kNonZero, Antialias::kExact, sink);
  result.spans = std::move(sink.recorded);
  return result;
}

void require_same_fill(const Path& path, IntRect clip, double tolerance, std::size_t max_edges = SIZE_MAX) {
  const auto fast_walk = [](const Path& p, double t, Rasterizer& r, std::vector<Point>& s, std::size_t m) {
    return detail::add_path_edges(p, t, r, s, m);  // QuadraticSteps::kFewest, the reference's polylines
  };
  const Fill fast = fill(fast_walk, path, clip, tolerance, max_edges);
  const Fill reference = fill(detail::add_path_edges_reference, path, clip, tolerance, max_edges);
  REQUIRE(fast.edges == reference.edges);
  REQUIRE(fast.spans.size() == reference.spans.size());
  for (std::size_t i = 0; i < fast.spans.size(); ++i) {
    const Span& a = fast.spans[i];
    const Span& b = reference.spans[i];
    INFO("span " << i);
    REQUIRE((a.x == b.x && a.y == b.y && a.len == b.len && a.coverage == b.coverage));
  }
}

void check_font(const char* file, double pixels_per_em, int glyph_stride) {
  const int checked = testing::for_each_glyph_outline(
      file, pixels_per_em, glyph_stride, [&](GlyphId glyph, const Path& device) {
        INFO(file << " glyph " << glyph << " at " << pixels_per_em << " px");
        const IntRect box = pixel_box(device);
        // Its own box: the path lies inside the clip (fast path). The left half and the lower right
        // quarter: the path crosses the clip (clip cull, edges clipped on both sides).
        const int mid_x = box.x0 + (box.x1 - box.x0) / 2;
        const int mid_y = box.y0 + (box.y1 - box.y0) / 2;
        for (const IntRect clip :
             {box, IntRect{box.x0, box.y0, mid_x, box.y1}, IntRect{mid_x, mid_y, box.x1, box.y1}}) {
          require_same_fill(device, clip, 0.1);
        }
      });
  CHECK(checked > 100);
}

TEST_CASE("add_path_edges equals its reference on every glyph of DejaVu Sans and Cantarell",
          "[font][path_edges]") {
  // Every glyph at 12 px; every 7th at 100 px (the fills are ~70 times larger; the suite runs under ASan).
  for (const char* file : {kDejaVuSansFile, kCantarellFile}) {
    check_font(file, 12.0, 1);
    check_font(file, 100.0, 7);
  }
}

Path every_verb_path(double scale, Vec2 shift) {
  const auto at = [&](double x, double y) { return Point{scale * x + shift.x, scale * y + shift.y}; };
  const std::vector<Point> quartic{at(20, 0), at(40, 30), at(10, 40), at(0, 20)};
  const std::vector<Point> rational{at(5, 5), at(30, -10), at(2, 1)};
  const std::vector<double> weights{1.0, 0.5, 2.0, 1.0};
  PathBuilder builder;
  builder.move_to(at(2, 2))
      .line_to(at(30, 3))
      .line_to(at(30, 3))  // zero length: counted by neither, an edge of neither
      .quad_to(at(40, 20), at(30, 35))
      .cubic_to(at(20, 45), at(5, 30), at(3, 20))
      .conic_to(at(-5, 10), at(2, 2), 0.7)
      .close()
      .move_to(at(10, 10))
      .bezier_to(quartic)
      .rational_bezier_to(rational, weights)  // not closed: the fill closes it
      .move_to(at(12, 12))
      .quad_to(at(14, 30), at(16, 12))
      .line_to(at(12, 12));  // ends at its start: no closing edge
  return *builder.build();
}

TEST_CASE("add_path_edges equals its reference on every verb, inside and across the clip",
          "[font][path_edges]") {
  const IntRect clip{0, 0, 48, 48};
  for (const double scale : {1.0, 0.5, 3.0, 1e9}) {
    for (const Vec2 shift : {Vec2{4, 4}, Vec2{-20, 10}, Vec2{30, -25}, Vec2{1e12, 0}}) {
      INFO("scale " << scale << " shift " << shift.x << ", " << shift.y);
      require_same_fill(every_verb_path(scale, shift), clip, 0.1);
      require_same_fill(every_verb_path(scale, shift), clip, 1e-3);
    }
  }
  // Fixed-size verbs only (the flat-array walk) as well as the general ones (the Iterator walk).
  const Path conics = *PathBuilder()
                           .move_to({4, 24})
                           .conic_to({4, 4}, {24, 4}, 0.70710678118654757)
                           .conic_to({44, 4}, {44, 24}, 0.70710678118654757)
                           .conic_to({44, 44}, {24, 44}, 0.70710678118654757)
                           .conic_to({4, 44}, {4, 24}, 0.70710678118654757)
                           .close()
                           .build();
  require_same_fill(conics, clip, 0.01);
  require_same_fill(conics, {10, 10, 20, 30}, 0.01);
}

TEST_CASE("add_path_edges equals its reference past the edge budget", "[font][path_edges]") {
  // Every verb (the general walk), and a glyph of quadratics and lines (the walk for fixed-size verbs
  // inside the clip, or the general one when the clip cuts it).
  const Path path = every_verb_path(1.0, {4, 4});
  const Result<Font> font = Font::open(kDejaVuSansFile);
  REQUIRE(font.is_ok());
  const Result<Path> outline = font->freetype_scaled_glyph_path(font->glyph_for(U'g'), 40.0);
  REQUIRE(outline.is_ok());
  const Path glyph = *outline->transformed(Affine::scale(1.0, -1.0));
  const IntRect glyph_box = pixel_box(glyph);
  for (const std::size_t max_edges : {0, 1, 2, 3, 5, 8, 13, 21, 34, 55, 89}) {
    INFO("max_edges " << max_edges);
    require_same_fill(path, {0, 0, 48, 48}, 0.01, max_edges);
    require_same_fill(path, {0, 0, 20, 48}, 0.01, max_edges);
    require_same_fill(glyph, glyph_box, 0.01, max_edges);
    require_same_fill(glyph, {glyph_box.x0, glyph_box.y0, glyph_box.x1 - 5, glyph_box.y1}, 0.01, max_edges);
  }
}

TEST_CASE("add_path_edges equals its reference on contours longer than one hand-over", "[font][path_edges]") {
  // A seeded star of 20001 vertices, and a circle flattened to ~10^4 edges: both cross the 4096-vertex
  // point where add_path_edges hands a contour to the rasterizer in pieces.
  std::mt19937_64 rng(4096);
  std::uniform_real_distribution<double> radius(5.0, 60.0);
  PathBuilder star;
  constexpr int kVertices = 20001;
  for (int i = 0; i < kVertices; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / kVertices;
    const Point p{64.0 + radius(rng) * std::cos(angle), 64.0 + radius(rng) * std::sin(angle)};
    if (i == 0) {
      star.move_to(p);
    } else {
      star.line_to(p);
    }
  }
  require_same_fill(*star.build(), {0, 0, 128, 128}, 0.1);
  const Path circle = *PathBuilder()
                           .move_to({4, 64})
                           .conic_to({4, 4}, {64, 4}, 0.70710678118654757)
                           .conic_to({124, 4}, {124, 64}, 0.70710678118654757)
                           .conic_to({124, 124}, {64, 124}, 0.70710678118654757)
                           .conic_to({4, 124}, {4, 64}, 0.70710678118654757)
                           .build();
  require_same_fill(circle, {0, 0, 128, 128}, 1e-5);
}

}  // namespace
}  // namespace curvescan
