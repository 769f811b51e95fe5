// Fuzz target text_layout: arbitrary bytes as the text of `curvescan text` or an SVG <text> — decoded as
// UTF-8 (invalid sequences are a clean Error), split into bidi paragraphs and runs (UAX #9, fribidi),
// given fallback faces per character, shaped by HarfBuzz run by run, and the outlines filled on a small
// canvas. The first byte picks the layout's options (base direction, bidi override, vertical lines,
// small capitals, kerning, fallback), the second the size; the rest is the text.
//
// The primary face is DejaVu Sans (the font the tests use); fallback asks fontconfig, which the process
// asks once: the FontFallback and its opened faces live across inputs, as in one long render. The canvas
// is 64 x 64 pixels and the sizes small, so that one input stays fast; glyphs beyond the canvas are
// clipped, which is also what is driven.
#include "curvescan/text/text_layout.h"

#include <array>
#include <optional>
#include <string_view>

#include "curvescan/raster/canvas.h"
#include "curvescan/text/font.h"
#include "curvescan/text/font_fallback.h"
#include "curvescan/text/utf8.h"
#include "fuzz_targets.h"

namespace curvescan::fuzz {
namespace {

constexpr const char* kPrimaryFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr int kCanvasSize = 64;
constexpr std::array<double, 4> kSizes = {0.5, 6.0, 16.0, 48.0};

struct Faces {
  std::optional<Font> primary;
  std::optional<FontFallback> fallback;
};

// Opened on the first input, and destroyed at exit before LeakSanitizer's final check (fontconfig's
// configuration, kept alive to the end, is otherwise reported as leaked). No primary face when the font
// is not installed: the target then only decodes.
Faces& faces() {
  static Faces opened = [] {
    Faces faces;
    if (Result<Font> font = Font::open(kPrimaryFontFile)) faces.primary.emplace(std::move(*font));
    return faces;
  }();
  if (opened.primary && !opened.fallback) {
    opened.fallback.emplace(*opened.primary, FontQuery{opened.primary->family_name()});
  }
  return opened;
}

}  // namespace

int fuzz_text_layout(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const std::uint8_t options = data[0];
  const std::string_view utf8(reinterpret_cast<const char*>(data + 2), size - 2);
  const Result<std::u32string> text = decode_utf8(utf8);
  Faces& font = faces();
  if (!text || !font.primary) return 0;

  TextStyle style;
  style.size = kSizes[data[1] % kSizes.size()];
  style.direction = std::array{TextDirection::kAuto, TextDirection::kLeftToRight, TextDirection::kRightToLeft,
                               TextDirection::kAuto}[options & 3];
  style.bidi_override = (options & 4) != 0;
  style.vertical = (options & 8) != 0;
  style.caps = std::array{CapsVariant::kNormal, CapsVariant::kSmallCaps, CapsVariant::kAllSmallCaps,
                          CapsVariant::kNormal}[(options >> 4) & 3];
  style.kerning = (options & 64) == 0;
  const Point origin{4.0, kCanvasSize / 2.0};
  const Result<TextLayout> layout = (options & 128) != 0 ? layout_text(*font.fallback, *text, origin, style)
                                                         : layout_text(*font.primary, *text, origin, style);
  if (!layout) return 0;

  PathBuilder builder;
  if (!append_text_outlines(*font.primary, *layout, builder)) return 0;
  const Result<Path> path = builder.build();
  if (!path) return 0;
  Result<Canvas> canvas = Canvas::create(kCanvasSize, kCanvasSize);
  if (!canvas) return 0;
  (void)canvas->fill(*path, Paint::solid({0.0, 0.0, 0.0, 1.0}), FillRule::kNonZero);
  return 0;
}

}  // namespace curvescan::fuzz
