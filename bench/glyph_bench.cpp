// Glyph rasterization throughput: curvescan (MaskRenderer, coverage_mask.h) against FreeType's own
// FT_Render_Glyph (FT_RENDER_MODE_NORMAL), on every glyph of DejaVu Sans at 12, 32 and 100 px,
// unhinted, in one process. Reported as ratios of total times (FreeType / curvescan: above 1 means
// curvescan is faster).
//
// Outline extraction is excluded from both sides. FreeType: each glyph is loaded once
// (FT_Load_Glyph, FT_LOAD_NO_HINTING) and then rendered again and again from its slot — FT_Render_Glyph
// leaves the outline in place (ft_smooth_render translates it back), so resetting the slot's format to
// FT_GLYPH_FORMAT_OUTLINE makes the next call a full render again, bitmap allocation included.
// curvescan: each glyph's outline is converted once (Font::freetype_scaled_glyph_path, the same 26.6
// outline, flipped to y down); each render then computes the pixel box, allocates and clears the mask,
// flattens (tolerance 0.1 px, about FreeType's conic accuracy, see tests/unit/font/freetype_oracle_test.cpp),
// rasterizes and writes the coverage — what FT_Render_Glyph does.
//
// Timing: thread CPU time (the machine is shared); per glyph the best of 3 rounds of a batch of calls,
// summed over the glyphs. Run: glyph_bench [font file].
// Profile: glyph_bench --profile=PPEM [--iterations=N] [font file] renders every glyph N times (default
// 3) with curvescan only, no FreeType rendering and no timing, for valgrind --tool=callgrind
// (deterministic instruction counts; the outlines are converted once, outside the loop).
#include <ft2build.h>
#include FT_FREETYPE_H

#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "curvescan/text/coverage_mask.h"
#include "curvescan/text/font.h"

namespace {

using namespace curvescan;

constexpr double kTolerance = 0.1;
constexpr int kRounds = 3;

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Calls per batch: enough that one batch lasts ~20 µs at the size (CPU-clock resolution is ~1 µs).
int batch_for(int ppem) {
  return ppem <= 12 ? 16 : ppem <= 32 ? 8 : 4;
}

// Best-of-rounds time of one call of `render`.
template <class Render>
double best_time(Render&& render, int batch) {
  render();  // warm: first-call allocations, caches
  double best = 1e30;
  for (int round = 0; round < kRounds; ++round) {
    const double start = thread_seconds();
    for (int i = 0; i < batch; ++i) render();
    best = std::min(best, (thread_seconds() - start) / batch);
  }
  return best;
}

struct SizeResult {
  double freetype = 0.0, curvescan = 0.0;  // seconds, summed over glyphs
  int glyphs = 0;
  double freetype_g = 0.0, curvescan_g = 0.0;  // the glyph 'g'
};

SizeResult run_size(const char* file, int ppem) {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  if (FT_Init_FreeType(&library) != 0 || FT_New_Face(library, file, 0, &face) != 0 ||
      FT_Set_Char_Size(face, 0, ppem * 64, 72, 72) != 0) {
    std::fprintf(stderr, "cannot open %s with FreeType\n", file);
    std::exit(1);
  }
  const Result<Font> font = Font::open(file);
  if (!font) {
    std::fprintf(stderr, "%s\n", font.error().message.c_str());
    std::exit(1);
  }
  const GlyphId g_glyph = font->glyph_for(U'g');
  MaskRenderer renderer;
  CoverageMask mask;
  SizeResult result;
  const int batch = batch_for(ppem);
  for (GlyphId glyph = 0; glyph < font->glyph_count(); ++glyph) {
    if (FT_Load_Glyph(face, glyph, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) != 0 ||
        face->glyph->format != FT_GLYPH_FORMAT_OUTLINE || face->glyph->outline.n_points == 0) {
      continue;
    }
    const Result<Path> outline = font->freetype_scaled_glyph_path(glyph, ppem);
    if (!outline) continue;
    const Result<Path> device = outline->transformed(Affine::scale(1.0, -1.0));
    if (!device) continue;

    FT_GlyphSlot slot = face->glyph;
    const double ft = best_time(
        [&] {
          slot->format = FT_GLYPH_FORMAT_OUTLINE;
          if (FT_Render_Glyph(slot, FT_RENDER_MODE_NORMAL) != 0) std::exit(1);
        },
        batch);
    const double ours = best_time(
        [&] {
          if (!renderer.render(*device, pixel_box(*device), FillRule::kNonZero, kTolerance, mask))
            std::exit(1);
        },
        batch);
    result.freetype += ft;
    result.curvescan += ours;
    ++result.glyphs;
    if (glyph == g_glyph) {
      result.freetype_g = ft;
      result.curvescan_g = ours;
    }
  }
  FT_Done_Face(face);
  FT_Done_FreeType(library);
  return result;
}

/// --profile: every glyph's device outline at `ppem`, rendered `iterations` times by curvescan only.
int profile(const char* file, int ppem, long iterations) {
  const Result<Font> font = Font::open(file);
  if (!font) {
    std::fprintf(stderr, "%s\n", font.error().message.c_str());
    return 1;
  }
  std::vector<Path> outlines;
  for (GlyphId glyph = 0; glyph < font->glyph_count(); ++glyph) {
    const Result<Path> outline = font->freetype_scaled_glyph_path(glyph, ppem);
    if (!outline || outline->empty()) continue;
    Result<Path> device = outline->transformed(Affine::scale(1.0, -1.0));
    if (device) outlines.push_back(std::move(*device));
  }
  MaskRenderer renderer;
  CoverageMask mask;
  for (long i = 0; i < iterations; ++i) {
    for (const Path& path : outlines) {
      if (!renderer.render(path, pixel_box(path), FillRule::kNonZero, kTolerance, mask)) return 1;
    }
  }
  std::printf("%zu glyphs at %d px, %ld iterations\n", outlines.size(), ppem, iterations);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const char* file = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  int profile_ppem = 0;
  long iterations = 3;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.starts_with("--profile=")) {
      profile_ppem = std::atoi(arg.c_str() + 10);
    } else if (arg.starts_with("--iterations=")) {
      iterations = std::atol(arg.c_str() + 13);
    } else {
      file = argv[i];
    }
  }
  if (profile_ppem > 0) return profile(file, profile_ppem, iterations);
  std::printf("glyph rasterization, %s, unhinted, outline extraction excluded from both sides\n", file);
  std::printf("%6s %7s %14s %14s %8s   %12s %12s\n", "ppem", "glyphs", "FreeType (ms)", "curvescan (ms)",
              "FT/cs", "'g' FT (us)", "'g' cs (us)");
  for (const int ppem : {12, 32, 100}) {
    const SizeResult r = run_size(file, ppem);
    std::printf("%6d %7d %14.2f %14.2f %8.2f   %12.2f %12.2f\n", ppem, r.glyphs, 1e3 * r.freetype,
                1e3 * r.curvescan, r.freetype / r.curvescan, 1e6 * r.freetype_g, 1e6 * r.curvescan_g);
  }
  return 0;
}
