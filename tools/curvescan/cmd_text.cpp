// `curvescan text [TEXT] [-i FILE] --font FILE|FAMILY --size PX -o OUT.png`: UTF-8 text drawn with a
// font's own outlines through curvescan's rasterizer (docs/text.md).
//
// Pipeline: decode UTF-8 (utf8.h) -> shape and lay out lines, with per-character font fallback
// (text_layout.h, font_fallback.h) -> glyph outlines as pieces of one paint each (text_ink.h: the
// plain glyphs in --color, the layers of COLR colour glyphs in their palette colours, bitmap glyphs'
// images, SVG glyphs' documents) -> Canvas::fill of each piece in order with the non-zero rule (an SVG
// glyph's document drawn by the SVG renderer, text_svg_glyphs.h). Unless --width/--height are given, the
// canvas is the text's extent (the union of the line boxes and the outlines' tight bounds) plus --margin on
// every side, rounded out to whole pixels (an SVG glyph's extent is its document's ink, which may reach
// beyond its outline).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "commands.h"
#include "css_colour_option.h"
#include "curvescan/raster/canvas.h"
#include "curvescan/raster/image_pattern.h"
#include "curvescan/raster/limits.h"
#include "curvescan/raster/png_io.h"
#include "curvescan/svg/color.h"
#include "curvescan/text/color_glyph.h"
#include "curvescan/text/font_fallback.h"
#include "curvescan/text/text_ink.h"
#include "curvescan/text/text_layout.h"
#include "curvescan/text/utf8.h"
#include "exit_codes.h"
#include "feature_list.h"
#include "finite_number.h"
#include "input_file.h"
#include "limit_options.h"
#include "option_range.h"
#include "output.h"
#include "output_is_input.h"
#include "text_font.h"
#include "text_svg_glyphs.h"

namespace curvescan::cli {
namespace {

constexpr const char* kCommand = "text";
// Default largest canvas: 2^24 pixels (4096 x 4096; a line of text rarely needs more, and --max-pixels
// raises it to the 2^26 of `render`).
constexpr std::int64_t kDefaultMaxTextPixels = std::int64_t{1} << 24;

struct TextOptions {
  std::string text;
  bool text_given = false;  // a text argument was given, even an empty one ('')
  std::string input_path;  // -i: read the text from this file ("-" = stdin)
  std::string font = "sans-serif";
  bool quiet = false;  // -q: no warnings (errors are still reported)
  int weight = 400;
  bool italic = false;
  double size = 32.0;
  double line_height = 0.0;
  double margin = -1.0;       // < 0: a quarter of the size
  int width = 0, height = 0;  // 0: sized to the text
  std::string color = "black";
  std::string background = "transparent";
  bool no_kerning = false;
  bool no_ligatures = false;
  std::string features;   // --features: OpenType features (feature_list.h)
  bool vertical = false;  // --vertical: lines top to bottom, characters upright
  std::string direction = "auto";  // each line's base direction (UAX #9): auto, ltr or rtl
  double tolerance = kDefaultFlattenTolerance;
  std::string output_path;
  std::int64_t max_pixels = kDefaultMaxTextPixels;
  std::size_t max_text_length = kMaxTextCharacters;
  RenderLimitOptions render_limits;
  std::int64_t max_input_mib = kDefaultMaxInputMiB;
};

// Memory of one character's layout at its peak, an upper bound: its UTF-8 (at most 4 bytes) and UTF-32
// (4) copies, its PositionedGlyph (40 bytes, twice while the vector grows), and HarfBuzz's buffer
// entries (hb_glyph_info_t and hb_glyph_position_t, 20 bytes each, with the out-buffer GSUB uses and
// their growth: up to 4 x 40). 4 + 4 + 80 + 160 = 248; 256 keeps a margin. Counted against --max-memory
// before the layout is made (docs/limits.md).
constexpr std::int64_t kLayoutBytesPerCharacter = 256;
// Each character without a glyph is named on its own line up to this many, then counted: a text of
// private-use or unassigned characters would otherwise print a line for each of thousands.
constexpr std::size_t kMaxMissingCharactersNamed = 100;

std::string mib_text(std::int64_t bytes) {
  constexpr std::int64_t kMiB = std::int64_t{1} << 20;
  return std::to_string((bytes + kMiB - 1) / kMiB) + " MiB";
}

// The bytes of the Paths text_ink makes of `layout`: each distinct glyph's outline (a colour glyph's:
// all its layers) is built once (its size does not depend on where it is drawn), and counted for every
// place it is drawn.
Result<std::int64_t> outline_bytes(const Font& primary, const TextLayout& layout) {
  std::map<std::pair<const Font*, GlyphId>, std::int64_t> per_glyph;
  std::int64_t total = 0;
  const auto bytes_of = [](const Font& face, GlyphId glyph) -> Result<std::int64_t> {
    const Result<Path> outline = face.glyph_path(glyph);
    if (!outline) return outline.error();
    return static_cast<std::int64_t>(outline->points().size() * sizeof(Point) +
                                     outline->verbs().size() * sizeof(PathVerb) +
                                     outline->weights().size() * sizeof(double));
  };
  for (const PositionedGlyph& glyph : layout.glyphs) {
    const Font& face = glyph.font != nullptr ? *glyph.font : primary;
    auto [entry, added] = per_glyph.try_emplace({&face, glyph.glyph}, 0);
    if (added) {
      std::vector<GlyphId> drawn{glyph.glyph};
      const ColorGlyphKind kind = color_glyph_kind(face, glyph.glyph);
      if (kind == ColorGlyphKind::kBitmap) drawn.clear();  // its image is counted once decoded
      if (kind == ColorGlyphKind::kLayers) {
        drawn.clear();
        for (const ColorGlyphLayer& layer : color_glyph_layers(face, glyph.glyph))
          drawn.push_back(layer.glyph);
      }
      for (const GlyphId id : drawn) {
        const Result<std::int64_t> bytes = bytes_of(face, id);
        if (!bytes) return bytes.error();
        entry->second += *bytes;
      }
    }
    total += entry->second;
  }
  return total;
}

std::string code_point_name(char32_t c) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "U+%04X", static_cast<unsigned>(c));
  return buffer;
}

Result<Paint> paint_of(const std::string& option, const std::string& text) {
  const Result<Color> color = svg::parse_color(text);
  if (!color) return Error{ErrorKind::kInvalidArgument, option + ": " + color.error().message};
  return Paint::solid(*color);
}

// The text to draw: the argument, or the file's content without one trailing line break (as `echo`
// and editors add one).
Result<std::string> text_of(const TextOptions& options) {
  if (!options.input_path.empty() && !options.text.empty()) {
    return Error{ErrorKind::kInvalidArgument, "give the text either as an argument or with -i, not both"};
  }
  if (options.input_path.empty()) return options.text;
  // max_text_length characters of up to 4 UTF-8 bytes each, within --max-input-size.
  const std::size_t max_bytes = std::min(input_size_bytes(options.max_input_mib), 4 * options.max_text_length + 2);
  Result<std::string> content = read_input(options.input_path, max_bytes);
  if (!content && content.error().kind == ErrorKind::kLimitExceeded &&
      max_bytes < input_size_bytes(options.max_input_mib)) {
    return Error{ErrorKind::kLimitExceeded, "the text of '" + options.input_path + "' has more than " +
                                                std::to_string(options.max_text_length) +
                                                " characters, the text length limit (raise --max-text-length)"};
  }
  if (!content) return content;
  std::string text = std::move(content).value();
  if (text.ends_with('\n')) text.pop_back();
  if (text.ends_with('\r')) text.pop_back();
  return text;
}

// Where the text came from, as messages name it.
std::string text_source(const TextOptions& options) {
  if (options.input_path.empty()) return "the text argument";
  if (options.input_path == "-") return "the text on standard input";
  return "the text of '" + options.input_path + "'";
}

// decode_utf8's refusal ("not valid UTF-8: byte ... at offset ..."), naming the text and how to fix it. A
// text that starts with a UTF-16 byte order mark (FF FE or FE FF) is UTF-16, the usual reason.
std::string invalid_utf8_message(const TextOptions& options, const std::string& utf8,
                                 const std::string& why) {
  const bool utf16 = utf8.starts_with("\xFF\xFE") || utf8.starts_with("\xFE\xFF");
  return text_source(options) + " is " + why +
         (utf16 ? "; it starts with a UTF-16 byte order mark: convert it with iconv -f UTF-16 -t UTF-8"
                : "; give the text in UTF-8 (iconv -f ENCODING -t UTF-8 converts it from another encoding)");
}

// What to say when there is nothing to draw: no text argument (or an empty one), or an empty -i file.
std::string empty_text_message(const TextOptions& options) {
  if (options.input_path.empty()) {
    return options.text_given
               ? "the text argument is empty: nothing to draw"
               : "no text to draw: give it as an argument, or with -i FILE (- for standard input)";
  }
  return text_source(options) + " is empty (a final line break is not drawn): nothing to draw";
}

// A side in pixels: whole below 1e15, exponent form above.
std::string pixels_text(double value) {
  char text[64];
  std::snprintf(text, sizeof text, std::fabs(value) < 1e15 ? "%.0f" : "%.3g", value);
  return text;
}

// Why a canvas of width x height pixels cannot be made: what set its size (--width and --height, or the
// text's extent at --size with its margins), the limit it passes, and what changes it. Raising
// --max-pixels does not help a side beyond kMaxImageDimension, nor a total beyond kMaxImagePixels.
std::string canvas_refusal(const TextOptions& options, double margin, double width, double height) {
  const std::string size = pixels_text(width) + " x " + pixels_text(height) + " pixels";
  const bool given = options.width > 0 && options.height > 0;
  char size_and_margin[96];
  std::snprintf(size_and_margin, sizeof size_and_margin, "--size %g with margins of %g", options.size,
                margin);
  std::string made = given ? "--width and --height ask for " + size
                           : "the text at " + std::string(size_and_margin) + " pixels needs " + size;
  if (!given && options.width > 0) made += " (the width from --width)";
  if (!given && options.height > 0) made += " (the height from --height)";
  if (width > kMaxImageDimension || height > kMaxImageDimension) {
    // --width and --height are at most kMaxImageDimension (their validators): the text's extent did this.
    const std::string what = width > kMaxImageDimension ? "shorter lines" : "fewer lines";
    return made + ", beyond the limit of " + std::to_string(kMaxImageDimension) +
           " pixels per side (use a smaller --size, --margin or --line-height, or " + what + ")";
  }
  const double area = width * height;  // both sides at most 32767: exact
  const std::string smaller = given ? "a smaller --width or --height" : "a smaller --size or --margin";
  const std::string advice =
      area <= static_cast<double>(kMaxImagePixels)
          ? "raise --max-pixels, up to " + std::to_string(kMaxImagePixels) + ", or use " + smaller
          : "--max-pixels goes up to " + std::to_string(kMaxImagePixels) + "; use " + smaller;
  return made + ", " + pixels_text(area) + " in all, beyond the limit of " +
         std::to_string(options.max_pixels) + " pixels (" + advice + ")";
}

// Every mandatory line break of UAX #14 (section 5.4: classes BK, CR, LF and NL — CR LF as one break, a
// lone CR, NEL U+0085, VT, FF, LINE SEPARATOR U+2028, PARAGRAPH SEPARATOR U+2029) becomes the U+000A that
// layout breaks lines at (text_layout.h), so a file from any system, or text pasted with Unicode's own
// separators, draws as the lines it holds rather than as .notdef boxes.
void normalize_line_breaks(std::u32string& text) {
  std::size_t out = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char32_t c = text[i];
    if (c == U'\r' && i + 1 < text.size() && text[i + 1] == U'\n') continue;  // the LF follows
    const bool mandatory_break = c == U'\r' || c == U'\u0085' || c == U'\v' || c == U'\f' || c == U'\u2028' ||
                                 c == U'\u2029';
    text[out++] = mandatory_break ? U'\n' : c;
  }
  text.resize(out);
}

int run_text(const TextOptions& options) {
  // A PNG written to a terminal is noise that can leave it in a strange state; `render` refuses it too.
  if (options.output_path == "-" && isatty(STDOUT_FILENO)) {
    return report_usage_error(kCommand,
                              "standard output is a terminal; name a PNG file with -o, or redirect");
  }
  if (const auto input = input_named_by_output(options.output_path, {options.input_path, options.font}))
    return report_usage_error(kCommand, output_is_input_message(options.output_path, *input));
  if (!(options.size > 0.0 && options.size <= kMaxTextSize)) {
    return report_error(kCommand, "--size must be in (0, " + std::to_string(static_cast<int>(kMaxTextSize)) +
                                      "] pixels (the text size limit, docs/text.md)");
  }
  const Result<Paint> ink = paint_of("--color", options.color);
  if (!ink) return report_error(kCommand, ink.error());
  const Result<Paint> background = paint_of("--background", options.background);
  if (!background) return report_error(kCommand, background.error());

  // No text at all is a malformed command line, as is an empty argument; an empty file is a bad input.
  if (options.input_path.empty() && (!options.text_given || options.text.empty())) {
    return report_usage_error(kCommand, empty_text_message(options));
  }
  const Result<std::string> utf8 = text_of(options);
  if (!utf8) return report_error(kCommand, utf8.error());
  if (utf8->empty()) return report_error(kCommand, empty_text_message(options));
  Result<std::u32string> text = decode_utf8(*utf8);
  if (!text) return report_error(kCommand, invalid_utf8_message(options, *utf8, text.error().message));
  normalize_line_breaks(*text);
  if (text->size() > options.max_text_length) {
    return report_error(kCommand, "the text has " + std::to_string(text->size()) + " characters, above the text " +
                                      "length limit of " + std::to_string(options.max_text_length) +
                                      " (raise --max-text-length)");
  }
  if (const Status size = check_input_file(options.font, options.max_input_mib); !size) {
    return report_error(kCommand, size.error());
  }

  const Result<Font> font = open_font_argument(options.font, options.weight, options.italic);
  if (!font) return report_error(kCommand, font.error());

  TextStyle style;
  style.size = options.size;
  style.line_height = options.line_height;
  style.kerning = !options.no_kerning;
  style.ligatures = !options.no_ligatures;
  style.vertical = options.vertical;
  style.features = parse_feature_list(options.features).value();  // the option's validator checked it
  style.direction = options.direction == "ltr"   ? TextDirection::kLeftToRight
                    : options.direction == "rtl" ? TextDirection::kRightToLeft
                                                 : TextDirection::kAuto;
  // Characters the font lacks come from the installed faces fontconfig ranks next for the family
  // (the font file's own family name when --font is a file); .notdef only where none has them.
  const bool family_lookup = !std::filesystem::is_regular_file(options.font);
  FontFallback fallback(*font, {family_lookup ? options.font : font->family_name(), options.weight, options.italic});
  const std::int64_t memory_limit = options.render_limits.render_limits().max_memory_bytes;
  const std::int64_t layout_bytes = static_cast<std::int64_t>(text->size()) * kLayoutBytesPerCharacter;
  if (layout_bytes > memory_limit) {
    return report_error(kCommand, "laying out " + std::to_string(text->size()) + " characters needs " +
                                      mib_text(layout_bytes) + ", beyond the memory limit of " +
                                      mib_text(memory_limit) + " per render (raise --max-memory)");
  }
  // The outlines are built, then the layout is dropped: only the pieces live on into the fill.
  std::vector<TextInkPiece> pieces;
  std::int64_t path_bytes = 0;
  Rect extent;
  {
    Result<TextLayout> layout = layout_text(fallback, *text, {0.0, 0.0}, style);
    if (!layout) return report_error(kCommand, layout.error());
    // Lines of both directions form one block, each line at its own start, as pango-view sets them.
    align_lines_at_start(*layout);
    const std::u32string& missing_characters = options.quiet ? std::u32string{} : layout->missing_characters;
    for (const char32_t missing : missing_characters.substr(0, kMaxMissingCharactersNamed)) {
      // The character itself too, unless it is a control character a terminal would act on.
      std::string character;
      if (missing >= 0x20 && !(missing >= 0x7F && missing <= 0x9F)) {
        character = " '";
        append_utf8(character, missing);
        character += "'";
      }
      report_warning(kCommand, "no glyph for " + code_point_name(missing) + character + " in '" +
                                   font->family_name() +
                                   "' or any installed fallback font; drawn as the font's .notdef glyph");
    }
    if (missing_characters.size() > kMaxMissingCharactersNamed) {
      report_warning(kCommand, std::to_string(missing_characters.size() - kMaxMissingCharactersNamed) +
                                   " more characters have no glyph either (not listed)");
    }
    const Result<std::int64_t> outlines = outline_bytes(*font, *layout);
    if (!outlines) return report_error(kCommand, outlines.error());
    path_bytes = *outlines;
    // While building: the layout, the builder's Path (its vectors up to twice their size while they
    // grow) and the copy build() returns.
    if (layout_bytes + 3 * path_bytes > memory_limit) {
      return report_error(kCommand, "the outlines of " + std::to_string(layout->glyphs.size()) + " glyphs need " +
                                        mib_text(layout_bytes + 3 * path_bytes) + " to build, beyond the memory limit of " +
                                        mib_text(memory_limit) + " per render (raise --max-memory)");
    }
    Result<TextInk> ink_pieces = text_ink(*font, *layout, options.max_pixels);
    if (!ink_pieces) return report_error(kCommand, ink_pieces.error());
    for (const std::string& warning : options.quiet ? std::vector<std::string>{} : ink_pieces->warnings) {
      report_warning(kCommand, warning);
    }
    pieces = std::move(ink_pieces->pieces);
    // Bitmap colour glyphs: each image (shared by the pieces of one glyph drawn again) and the copy its
    // paint makes while it is drawn.
    std::set<const ColorGlyphBitmap*> counted;
    for (const TextInkPiece& piece : pieces) {
      if (piece.bitmap && counted.insert(piece.bitmap.get()).second)
        path_bytes += image_memory_bytes(piece.bitmap->image.width(), piece.bitmap->image.height());
    }
    extent = layout->line_box();
  }

  // An SVG glyph is drawn from its document, whose ink may reach beyond the glyph's outline (a glow, a
  // flourish): the canvas holds that ink, not the outline the document replaces.
  SvgGlyphPainter svg_glyphs(memory_limit, options.quiet);
  for (const TextInkPiece& piece : pieces) {
    std::optional<Rect> ink_box = piece.path.tight_bounds();
    if (piece.svg_document) {
      Result<std::optional<Rect>> drawn = svg_glyphs.ink_box(piece);
      if (!drawn) return report_error(kCommand, drawn.error());
      ink_box = *drawn;
    }
    if (!ink_box) continue;
    extent.include({ink_box->x0, ink_box->y0});
    extent.include({ink_box->x1, ink_box->y1});
  }
  const double margin = options.margin >= 0.0 ? options.margin : 0.25 * options.size;
  const double left = std::floor(extent.x0 - margin), top = std::floor(extent.y0 - margin);
  const double width = options.width > 0 ? options.width : std::ceil(extent.x1 + margin) - left;
  const double height = options.height > 0 ? options.height : std::ceil(extent.y1 + margin) - top;
  if (!(width <= kMaxImageDimension && height <= kMaxImageDimension &&
        width * height <= static_cast<double>(options.max_pixels))) {
    return report_error(kCommand, canvas_refusal(options, margin, width, height));
  }
  // From here on the Path and the copy fill() makes of it in device space are held beside the canvas.
  const std::int64_t held_bytes = 2 * path_bytes;
  const std::int64_t canvas_bytes =
      image_memory_bytes(static_cast<std::int64_t>(width), static_cast<std::int64_t>(height));
  if (held_bytes + canvas_bytes > memory_limit) {
    return report_error(kCommand, "a " + std::to_string(static_cast<long long>(width)) + " x " +
                                      std::to_string(static_cast<long long>(height)) + " canvas and the text's outlines need " +
                                      mib_text(held_bytes + canvas_bytes) + ", beyond the memory limit of " +
                                      mib_text(memory_limit) + " per render (raise --max-memory)");
  }
  Result<Canvas> canvas = Canvas::create(static_cast<int>(width), static_cast<int>(height),
                                         options.render_limits.render_limits());
  if (!canvas) return report_error(kCommand, canvas.error());
  canvas->set_held_memory_bytes(held_bytes);
  canvas->clear(*background);
  FillOptions fill;
  fill.tolerance = options.tolerance;
  const Color ink_color = svg::parse_color(options.color).value();  // paint_of checked it
  for (const TextInkPiece& piece : pieces) {
    if (piece.svg_document) {
      if (const Status drawn =
              svg_glyphs.draw(*canvas, piece, Affine::translate(-left, -top), ink_color.a, *ink, fill);
          !drawn) {
        return report_error(kCommand, drawn.error());
      }
      continue;
    }
    // A palette colour fades with a translucent --color, as the layers of a colour glyph do in browsers.
    const Color layer{piece.color.r, piece.color.g, piece.color.b, piece.color.a * ink_color.a};
    const Paint paint = piece.bitmap
                            ? image_pattern_paint(piece.bitmap->image, piece.image_to_user,
                                                  PatternExtend::kPad, PatternFilter::kBilinear, ink_color.a)
                        : piece.foreground ? *ink
                                           : Paint::solid(layer);
    if (const Status filled =
            canvas->fill(piece.path, paint, FillRule::kNonZero, Affine::translate(-left, -top), fill);
        !filled) {
      return report_error(kCommand, filled.error());
    }
  }
  if (const Status written = write_png_output(options.output_path, canvas->image()); !written) {
    return report_error(kCommand, written.error());
  }
  return kExitOk;
}

}  // namespace

void add_text_command(CLI::App& root, CommandResult& result) {
  auto o = std::make_shared<TextOptions>();
  CLI::App* command = root.add_subcommand(
      "text",
      "Draw UTF-8 text with a font's own outlines (FreeType, HarfBuzz shaping) to a PNG (docs/text.md).\n"
      "Examples:\n"
      "  curvescan text 'Hello, world' -o hello.png\n"
      "  curvescan text --font DejaVuSerif.ttf --size 64 --color navy --background white 'Ångström' -o a.png\n"
      "  curvescan text -i poem.txt --font 'Noto Sans Arabic' --direction rtl -o poem.png");
  command->set_help_flag("-h,--help", "print this help and exit");
  command->footer(std::string(kLimitsHelp) + "\n" + kExitCodesHelp);
  // Each option names its value in words and states its unit, range and default (help_formatter.h).
  CLI::Option* text_argument = command->add_option(
      "text", o->text, "the text to draw, UTF-8; \\n in the shell's $'...' makes several lines (or -i)");
  command
      ->add_option("-i,--input", o->input_path,
                   "read the text from this file, UTF-8; - reads standard input (not with a text argument)")
      ->type_name("FILE")
      ->excludes(text_argument);
  command->add_option("-o,--output", o->output_path, "output PNG file; - writes standard output")
      ->type_name("FILE")
      ->required();
  command
      ->add_option("--font", o->font,
                   "a font file (TrueType, OpenType), or a family name list that fontconfig resolves")
      ->type_name("FONT")
      ->capture_default_str();
  command
      ->add_option("--weight", o->weight,
                   "weight for a family lookup, 1 to 1000: 400 is regular, 700 bold")
      ->type_name("WEIGHT")
      ->check(number_in_range(1, 1000))
      ->capture_default_str();
  command->add_flag("--italic", o->italic, "look for an italic face of the family");
  command->add_flag("-q,--quiet", o->quiet, "do not print warnings (errors are still printed)");
  // (0, kMaxTextSize]: CLI::Range is closed at both ends, and a size of 0 draws nothing.
  const CLI::Validator text_size(
      [](std::string& text) -> std::string {
        try {
          const double value = std::stod(text);
          if (value > 0.0 && value <= kMaxTextSize) return {};
        } catch (const std::exception&) {
          return {};  // not a finite number: kFiniteNumber and the option's own conversion report it
        }
        return "'" + text + "' is out of range: give a number more than 0 and at most " +
               std::to_string(static_cast<int>(kMaxTextSize)) + " pixels";
      },
      "");
  command
      ->add_option("--size", o->size,
                   "em size in pixels, more than 0 and at most " + std::to_string(static_cast<int>(kMaxTextSize)))
      ->type_name("PIXELS")
      ->check(kFiniteNumber)
      ->check(text_size)
      ->capture_default_str();
  command
      ->add_option("--line-height", o->line_height,
                   "baseline-to-baseline distance in pixels, 0 to 1e6 (default: the font's)")
      ->type_name("PIXELS")
      ->check(kFiniteNumber)
      ->check(number_in_range(0.0, 1e6));
  command
      ->add_option("--margin", o->margin, "space around the text in pixels, 0 to 1e6 (default: a quarter of --size)")
      ->type_name("PIXELS")
      ->check(kFiniteNumber)
      ->check(number_in_range(0.0, 1e6));
  const std::string largest_side = std::to_string(kMaxImageDimension);
  command
      ->add_option("--width", o->width,
                   "canvas width in pixels, 1 to " + largest_side + " (default: the text's extent plus margins)")
      ->type_name("PIXELS")
      ->check(number_in_range(1, kMaxImageDimension));
  command
      ->add_option("--height", o->height,
                   "canvas height in pixels, 1 to " + largest_side + " (default: the text's extent plus margins)")
      ->type_name("PIXELS")
      ->check(number_in_range(1, kMaxImageDimension));
  command
      ->add_option("--color", o->color, "text colour in CSS: a name, #rgb, #rrggbb, #rrggbbaa, rgb(), hsl()")
      ->type_name("COLOUR")
      ->check(kCssColour)
      ->capture_default_str();
  command->add_option("--background", o->background, "background colour in CSS, as --color")
      ->type_name("COLOUR")
      ->check(kCssColour)
      ->capture_default_str();
  command->add_flag("--no-kerning", o->no_kerning, "turn the font's kerning off");
  command->add_flag("--no-ligatures", o->no_ligatures, "turn standard ligatures off");
  command
      ->add_option("--features", o->features,
                   "OpenType features of the font, by their four-letter tags, separated by commas: a tag turns "
                   "a feature on, -tag turns it off, tag=N picks alternate N; e.g. smcp,-liga,ss01,salt=2 "
                   "(default: none beyond the font's usual ones)")
      ->type_name("LIST")
      ->check(kFeatureList);
  command->add_flag("--vertical", o->vertical,
                    "vertical lines, as in Chinese and Japanese: each line runs top to bottom, the next one to "
                    "its left, every character upright with the font's vertical forms where it has them");
  command
      ->add_option("--direction", o->direction,
                   "each line's base direction: auto (from its first strong letter), ltr or rtl; right-to-left "
                   "lines are aligned on the right")
      ->type_name("DIRECTION")
      ->check(one_of({"auto", "ltr", "rtl"}))
      ->capture_default_str();
  command
      ->add_option("--tolerance", o->tolerance,
                   "flattening tolerance: the largest distance between a curve and its line segments, in "
                   "pixels, 1e-6 to 100")
      ->type_name("PIXELS")
      ->check(kFiniteNumber)
      ->check(number_in_range(1e-6, 100.0))
      ->capture_default_str();
  command
      ->add_option("--max-pixels", o->max_pixels,
                   "largest output image in pixels, 1 to " + std::to_string(kMaxImagePixels))
      ->type_name("PIXELS")
      ->check(number_in_range(std::int64_t{1}, kMaxImagePixels))
      ->capture_default_str();
  command
      ->add_option("--max-text-length", o->max_text_length,
                   "most characters of text, 1 to " + std::to_string(kMaxTextCharacters))
      ->type_name("N")
      ->check(number_in_range(std::size_t{1}, kMaxTextCharacters))
      ->capture_default_str();
  add_render_limit_options(*command, o->render_limits, /*with_dashes=*/false);
  add_input_size_option(*command, o->max_input_mib);
  command->callback([o, text_argument, &result] {
    o->text_given = text_argument->count() > 0;
    result.exit_code = run_text(*o);
  });
}

}  // namespace curvescan::cli
