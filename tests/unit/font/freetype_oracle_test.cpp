// FreeType oracle: every glyph of a TrueType font (DejaVu Sans) and of a CFF font (Cantarell), unhinted,
// rendered by curvescan and by FreeType, compared as 8-bit masks in FreeType's own bitmap box
// (bitmap_left, bitmap_top, width x rows; curvescan's y axis flipped). Both start from the outline
// FreeType scales to 26.6 pixels (Font::freetype_scaled_glyph_path, FT_LOAD_NO_HINTING).
//
// Two comparisons, because FreeType's renderer differs from an exact-area fill of the curves in two
// documented ways that have nothing to do with area computation:
//  (a) its flattening is coarse. ftgrays.c gray_render_conic bisects until |p0 - 2p1 + p2| <= 1/4 px
//      per axis, so a chord strays up to 1/16 px per axis (sqrt(2)/16 = 0.088 px); gray_render_cubic
//      stops when |2p0 - 3p1 + p3| and |p0 - 3p2 + 2p3| are <= 1/2 px per axis, which lets a chord stray
//      up to (4/9)·(1/6 + 1/6) = 0.148 px per axis (0.21 px). A pixel crossed by such a chord (length up
//      to sqrt(2) inside the pixel) changes by up to 0.125 of its area for conics, 0.30 for cubics.
//  (b) its coverage is |integral of the winding number over the pixel| clamped to 1, not the area of
//      the non-zero region, so where two contours of a glyph overlap inside a pixel (DejaVu's accented
//      composites) it counts the overlap twice.
//
// "Same polygon" (the tight oracle): each contour flattened by curvescan's flattener, its vertices
// rounded to 1/64 px so FreeType can take them exactly (26.6), rendered by FreeType
// (FT_Outline_Get_Bitmap, the smooth rasterizer FT_Render_Glyph uses) and by curvescan; (b) is modelled
// on curvescan's side by rasterizing each contour alone and summing the coverages signed by
// orientation, clamped. What is left is the two area computations: quantization (curvescan
// round(255·a), FreeType min(255, floor(256·a)) - up to 1.5/255; the per-contour roundings of the sum add
// 0.5/255 each where contours share a pixel) and FreeType's 24.8 fixed point (1/256 px moves a coverage
// by <= 1/255). Thresholds: max |Δ| <= 4/255 per glyph (measured: 2/255 at every size, both fonts).
// Mean |Δ|: the two quantizations differ by ~0.5/255 on an average edge pixel and agree on empty and
// full pixels, so the mean is about 0.5/255 times the fraction of edge pixels: 0.30/255 for Cantarell at
// 8 px where most pixels are edge pixels, 0.03/255 at 200 px. Bound over all glyphs of a size: 0.35/255
// (the product's 0.25/255 goal holds from 12 px up); per glyph 1.5/255 (a glyph of two or three pixels, all
// on edges, has a mean equal to its largest quantization difference).
//
// "FT_Render_Glyph" (the honest end-to-end comparison): curvescan's real rendering (curves flattened
// within kFineTolerance, non-zero union) against FT_Render_Glyph (FT_RENDER_MODE_NORMAL), on glyphs
// without overlapping contours. The residual is FreeType's flattening (a): bound 0.125·255 = 32/255 for
// TrueType and 0.30·255 = 76/255 for CFF, plus the rounding of FreeType's integer bisections (each of up
// to ~6 levels halves in 1/256-px integers: <= 6/512 px, times sqrt(2) -> 4/255), our own chords
// (0.01 px · sqrt(2) -> 1/255) and quantization (1.5/255) -> 40/255 and 83/255. The worst glyph of each
// (font, size) is printed.
//
// Run time: every glyph at 8, 12, 16 and 32 px; a seeded sample of 300 glyphs per font at 72 and 200 px,
// whose bitmaps are up to 600 times larger (the suite also runs under ASan).
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "curvescan/curves/flatten.h"
#include "curvescan/text/coverage_mask.h"
#include "curvescan/text/font.h"
#include "font_files.h"

namespace {

using namespace curvescan;

// curvescan's flattening tolerance here (px): small enough that our own chords stay below 1/255.
constexpr double kFineTolerance = 0.01;
// The same-polygon comparison flattens more coarsely (fewer, longer edges exercise the rasterizers
// more); any polygon will do, since both sides get the same one.
constexpr double kPolygonTolerance = 0.1;

struct Stats {
  int max_abs = 0;
  double mean_abs = 0.0;
};

Stats difference(const std::vector<int>& ours, const unsigned char* theirs, int pitch, IntRect box) {
  Stats stats;
  long long sum = 0;
  for (int y = 0; y < box.y1; ++y) {
    for (int x = 0; x < box.x1; ++x) {
      const int delta = std::abs(ours[static_cast<std::size_t>(y * box.x1 + x)] - int{theirs[y * pitch + x]});
      stats.max_abs = std::max(stats.max_abs, delta);
      sum += delta;
    }
  }
  stats.mean_abs = static_cast<double>(sum) / (static_cast<double>(box.x1) * box.y1);
  return stats;
}

double round_to_64th(double v) {
  return std::round(v * 64.0) / 64.0;
}

// The contours of `device` flattened by curvescan's flattener, vertices rounded to 1/64 px, the closing
// vertex (equal to the first) left implicit.
std::vector<std::vector<Point>> rounded_polygons(const Path& device) {
  std::vector<std::vector<Point>> polygons;
  std::vector<Point> scratch;
  for (const PathElement& e : device) {
    if (e.verb == PathVerb::kMove) {
      polygons.push_back({e.start});
    } else if (e.verb != PathVerb::kClose) {
      scratch.clear();
      REQUIRE(flatten_bezier(e.points, kPolygonTolerance, scratch) == FlattenOutcome::kOk);
      polygons.back().insert(polygons.back().end(), scratch.begin(), scratch.end());
    }
  }
  for (std::vector<Point>& polygon : polygons) {
    for (Point& p : polygon) p = {round_to_64th(p.x), round_to_64th(p.y)};
    if (polygon.size() > 1 && polygon.back() == polygon.front()) polygon.pop_back();
  }
  return polygons;
}

Path polygon_path(const std::vector<std::vector<Point>>& polygons) {
  PathBuilder builder;
  for (const std::vector<Point>& polygon : polygons) {
    builder.move_to(polygon.front());
    for (std::size_t i = 1; i < polygon.size(); ++i) builder.line_to(polygon[i]);
    builder.close();
  }
  Result<Path> path = builder.build();
  REQUIRE(path.is_ok());
  return std::move(path).value();
}

double signed_area(const std::vector<Point>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    twice += polygon[i].to_vec().cross(polygon[(i + 1) % polygon.size()].to_vec());
  }
  return 0.5 * twice;
}

std::vector<int> render(MaskRenderer& renderer, const Path& path, IntRect box, double tolerance) {
  CoverageMask mask;
  REQUIRE(renderer.render(path, box, FillRule::kNonZero, tolerance, mask).is_ok());
  return {mask.coverage.begin(), mask.coverage.end()};
}

// FreeType's rendering of `polygons` (bitmap pixels, y down) into a rows x width A8 bitmap.
std::vector<unsigned char> freetype_polygon_bitmap(FT_Library library,
                                                   const std::vector<std::vector<Point>>& polygons,
                                                   IntRect box) {
  std::size_t points = 0;
  for (const auto& polygon : polygons) points += polygon.size();
  FT_Outline outline{};
  REQUIRE(FT_Outline_New(library, static_cast<FT_UInt>(points), static_cast<FT_Int>(polygons.size()),
                         &outline) == 0);
  std::size_t k = 0;
  for (std::size_t c = 0; c < polygons.size(); ++c) {
    for (const Point& p : polygons[c]) {
      // y up with the bitmap's bottom edge at 0 (FT_Outline_Get_Bitmap's frame), in 26.6.
      outline.points[k] = {std::lround(p.x * 64.0), std::lround((box.y1 - p.y) * 64.0)};
      outline.tags[k] = FT_CURVE_TAG_ON;
      ++k;
    }
    outline.contours[c] = static_cast<short>(k - 1);
  }
  // FT_Outline_New leaves only FT_OUTLINE_OWNER set (so FT_Outline_Done frees the arrays): non-zero fill.
  std::vector<unsigned char> pixels(static_cast<std::size_t>(box.x1) * static_cast<std::size_t>(box.y1), 0);
  FT_Bitmap bitmap{};
  bitmap.rows = static_cast<unsigned>(box.y1);
  bitmap.width = static_cast<unsigned>(box.x1);
  bitmap.pitch = box.x1;
  bitmap.buffer = pixels.data();
  bitmap.num_grays = 256;
  bitmap.pixel_mode = FT_PIXEL_MODE_GRAY;
  REQUIRE(FT_Outline_Get_Bitmap(library, &outline, &bitmap) == 0);
  FT_Outline_Done(library, &outline);
  return pixels;
}

struct GlyphResult {
  bool compared = false;
  bool overlapping = false;  // contours overlap inside some pixel: FreeType's accumulation differs there
  Stats polygon;             // same polygon: curvescan (winding-integral model) vs FreeType
  Stats rendered;            // curvescan's real rendering vs FT_Render_Glyph
};

GlyphResult compare_glyph(FT_Library library, FT_Face face, const Font& font, MaskRenderer& renderer,
                          GlyphId glyph, int ppem) {
  GlyphResult result;
  REQUIRE(FT_Load_Glyph(face, glyph, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) == 0);
  if (face->glyph->outline.n_points == 0) return result;
  REQUIRE(FT_Render_Glyph(face->glyph, FT_RENDER_MODE_NORMAL) == 0);
  const FT_Bitmap& bitmap = face->glyph->bitmap;
  const IntRect box{0, 0, static_cast<int>(bitmap.width), static_cast<int>(bitmap.rows)};
  if (box.empty()) return result;

  const Result<Path> outline = font.freetype_scaled_glyph_path(glyph, ppem);
  REQUIRE(outline.is_ok());
  // Pixels, y up, glyph origin at 0 -> bitmap pixels, y down, the bitmap's top-left corner at 0.
  const Affine to_bitmap{1.0,
                         0.0,
                         0.0,
                         -1.0,
                         -static_cast<double>(face->glyph->bitmap_left),
                         static_cast<double>(face->glyph->bitmap_top)};
  const Result<Path> device = outline->transformed(to_bitmap);
  REQUIRE(device.is_ok());

  const std::vector<std::vector<Point>> polygons = rounded_polygons(*device);
  const std::vector<int> union_of_contours = render(renderer, polygon_path(polygons), box, kFineTolerance);
  std::vector<int> winding_integral(union_of_contours.size(), 0);
  for (const std::vector<Point>& polygon : polygons) {
    const int sign = signed_area(polygon) < 0.0 ? -1 : 1;
    const std::vector<int> alone = render(renderer, polygon_path({polygon}), box, kFineTolerance);
    for (std::size_t i = 0; i < alone.size(); ++i) winding_integral[i] += sign * alone[i];
  }
  std::vector<int> model(winding_integral.size());
  for (std::size_t i = 0; i < model.size(); ++i) {
    model[i] = std::min(255, std::abs(winding_integral[i]));
    // Without overlaps the signed sum and the union agree up to the per-contour roundings (0.5 each).
    result.overlapping = result.overlapping || std::abs(model[i] - union_of_contours[i]) > 2;
  }
  const std::vector<unsigned char> freetype_polygon = freetype_polygon_bitmap(library, polygons, box);
  result.compared = true;
  result.polygon = difference(model, freetype_polygon.data(), box.x1, box);
  result.rendered =
      difference(render(renderer, *device, box, kFineTolerance), bitmap.buffer, bitmap.pitch, box);
  return result;
}

struct Worst {
  Stats stats;
  GlyphId glyph = 0;
  void take(const Stats& s, GlyphId g) {
    if (s.max_abs > stats.max_abs || (s.max_abs == stats.max_abs && s.mean_abs > stats.mean_abs)) {
      stats = s;
      glyph = g;
    }
  }
};

struct SweepSummary {
  int compared = 0, overlapping = 0;
  Worst polygon;
  double polygon_worst_mean = 0.0, polygon_mean_sum = 0.0;
  Worst rendered;  // glyphs without overlapping contours
  double rendered_mean_sum = 0.0;
};

SweepSummary sweep(const char* file, int ppem, const std::vector<GlyphId>& glyphs) {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  REQUIRE(FT_Init_FreeType(&library) == 0);
  REQUIRE(FT_New_Face(library, file, 0, &face) == 0);
  REQUIRE(FT_Set_Char_Size(face, 0, ppem * 64, 72, 72) == 0);
  const Result<Font> font = Font::open(file);
  REQUIRE(font.is_ok());
  MaskRenderer renderer;
  SweepSummary s;
  for (const GlyphId glyph : glyphs) {
    const GlyphResult r = compare_glyph(library, face, *font, renderer, glyph, ppem);
    if (!r.compared) continue;
    ++s.compared;
    s.polygon.take(r.polygon, glyph);
    s.polygon_worst_mean = std::max(s.polygon_worst_mean, r.polygon.mean_abs);
    s.polygon_mean_sum += r.polygon.mean_abs;
    if (r.overlapping) {
      ++s.overlapping;
    } else {
      s.rendered.take(r.rendered, glyph);
      s.rendered_mean_sum += r.rendered.mean_abs;
    }
  }
  FT_Done_Face(face);
  FT_Done_FreeType(library);
  const int clean = s.compared - s.overlapping;
  std::printf(
      "%s @ %3d px: %4d glyphs (%d with overlapping contours)\n"
      "  same polygon:    worst max |d| %d/255 (glyph %u), worst glyph mean %.3f/255, mean %.3f/255\n"
      "  FT_Render_Glyph: worst max |d| %d/255 (glyph %u), mean %.3f/255\n",
      file, ppem, s.compared, s.overlapping, s.polygon.stats.max_abs, s.polygon.glyph, s.polygon_worst_mean,
      s.polygon_mean_sum / std::max(1, s.compared), s.rendered.stats.max_abs, s.rendered.glyph,
      s.rendered_mean_sum / std::max(1, clean));
  return s;
}

std::vector<GlyphId> all_glyphs(const char* file) {
  const Result<Font> font = Font::open(file);
  REQUIRE(font.is_ok());
  std::vector<GlyphId> glyphs(font->glyph_count());
  for (std::size_t i = 0; i < glyphs.size(); ++i) glyphs[i] = static_cast<GlyphId>(i);
  return glyphs;
}

// A seeded sample of `count` glyph indices.
std::vector<GlyphId> sampled_glyphs(const char* file, std::size_t count, unsigned seed) {
  std::vector<GlyphId> glyphs = all_glyphs(file);
  std::mt19937 rng(seed);
  std::shuffle(glyphs.begin(), glyphs.end(), rng);
  glyphs.resize(std::min(count, glyphs.size()));
  return glyphs;
}

// Thresholds: see the header comment.
void check(const SweepSummary& s, bool cff) {
  CHECK(s.compared > 0);
  CHECK(s.polygon.stats.max_abs <= 4);
  CHECK(s.polygon_worst_mean <= 1.5);
  CHECK(s.polygon_mean_sum / s.compared <= 0.35);
  CHECK(s.rendered.stats.max_abs <= (cff ? 83 : 40));
}

}  // namespace

TEST_CASE("freetype oracle: every glyph at 8, 12, 16 and 32 px", "[font][oracle]") {
  for (const char* file : {kDejaVuSansFile, kCantarellFile}) {
    const std::vector<GlyphId> glyphs = all_glyphs(file);
    for (const int ppem : {8, 12, 16, 32}) check(sweep(file, ppem, glyphs), file == kCantarellFile);
  }
}

TEST_CASE("freetype oracle: a seeded sample of 300 glyphs at 72 and 200 px", "[font][oracle]") {
  for (const char* file : {kDejaVuSansFile, kCantarellFile}) {
    for (const int ppem : {72, 200}) {
      check(sweep(file, ppem, sampled_glyphs(file, 300, 20261121)), file == kCantarellFile);
    }
  }
}
