// The fuzz targets of curvescan: one plain function per kind of input, each taking arbitrary bytes.
//
// A target returns 0 for every input (libFuzzer's convention; the value is otherwise unused). Any crash,
// sanitizer report, hang (> 10 s) or memory blow-up (> 2 GiB) inside one is a bug in curvescan: every
// input, however hostile, must end in a result or a clean Error. The bodies are compiled by any compiler,
// so tests/fuzz_replay runs the committed corpora and regressions through the very same functions that
// libFuzzer drives (fuzz/libfuzzer_main.cpp). docs/fuzzing.md describes the targets and how to run them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace curvescan::fuzz {

/// SVG path data (the `d` attribute) and the other SVG attribute micro-syntaxes (numbers, lengths,
/// colours, transforms, style attributes, viewBox); a parsed path is also filled on a small canvas.
int fuzz_svg_path_data(const std::uint8_t* data, std::size_t size);
/// A whole SVG document rendered by render_svg_document, at a small size and with small limits.
int fuzz_svg_document(const std::uint8_t* data, std::size_t size);
/// The JSON curve spec of `curvescan curve` (docs/curve-spec.md): parsed, converted, flattened.
int fuzz_curve_spec(const std::uint8_t* data, std::size_t size);
/// A PNG file read by read_png.
int fuzz_png_read(const std::uint8_t* data, std::size_t size);
/// A font file: every glyph's outline to a Path and to a coverage mask at a small size.
int fuzz_font(const std::uint8_t* data, std::size_t size);
/// Bytes decoded into a scene (path with hostile coordinates, transform, fill rule, stroke style) that is
/// filled, stroked and clipped on a small canvas.
int fuzz_raster_stroke(const std::uint8_t* data, std::size_t size);
/// Two images (PNG files, or raw pixels) and diff options compared by compare_images.
int fuzz_image_diff(const std::uint8_t* data, std::size_t size);
/// A CSS style sheet: as a style attribute, and as the user style sheet of a fixed document's render.
int fuzz_css(const std::uint8_t* data, std::size_t size);
/// A formula of explicit and implicit curves: parsed, evaluated in double and interval arithmetic (the
/// inclusion property checked), and drawn as a small explicit and implicit curve.
int fuzz_expression(const std::uint8_t* data, std::size_t size);
/// A JPEG file decoded as an SVG <image> decodes it (libjpeg-turbo, within the pixel limit).
int fuzz_jpeg_read(const std::uint8_t* data, std::size_t size);
/// A gzip stream (an .svgz file or standard input) inflated by svg::gunzip within its size limit.
int fuzz_gzip_input(const std::uint8_t* data, std::size_t size);
/// The bytes of an SVG <image> through the GIF and WebP decoders and the svgz inflater.
int fuzz_image_read(const std::uint8_t* data, std::size_t size);
/// Text as `curvescan text` and SVG <text> lay it out: UTF-8 decoding, bidi runs, font fallback, HarfBuzz
/// shaping, the outlines filled on a small canvas (the first two bytes pick options and size).
int fuzz_text_layout(const std::uint8_t* data, std::size_t size);
/// The href of an SVG <image> as a data: URI: base64 or percent decoded, sniffed, loaded without files.
int fuzz_data_uri(const std::uint8_t* data, std::size_t size);
/// One command-line option value through the CLI's text parsers and validators (Accept-Language, lengths,
/// --files-from lists, --ignore regions, --features, CSS colours, number ranges).
int fuzz_cli_options(const std::uint8_t* data, std::size_t size);
/// The manifest of a `diff --report` directory: read, and the stale files it lists pruned, in a scratch
/// directory whose files outside the report and whose newly written files must survive it.
int fuzz_report_manifest(const std::uint8_t* data, std::size_t size);

using FuzzFunction = int (*)(const std::uint8_t*, std::size_t);

struct FuzzTarget {
  std::string_view name;  ///< as in fuzz/corpus/<name>/ and fuzz/run.sh
  FuzzFunction function;
};

/// Every target, in the order of the list above.
inline constexpr FuzzTarget kFuzzTargets[] = {
    {"svg_path_data", fuzz_svg_path_data},
    {"svg_document", fuzz_svg_document},
    {"curve_spec", fuzz_curve_spec},
    {"png_read", fuzz_png_read},
    {"font", fuzz_font},
    {"raster_stroke", fuzz_raster_stroke},
    {"image_diff", fuzz_image_diff},
    {"css", fuzz_css},
    {"expression", fuzz_expression},
    {"jpeg_read", fuzz_jpeg_read},
    {"gzip_input", fuzz_gzip_input},
    {"image_read", fuzz_image_read},
    {"text_layout", fuzz_text_layout},
    {"data_uri", fuzz_data_uri},
    {"cli_options", fuzz_cli_options},
    {"report_manifest", fuzz_report_manifest},
};

}  // namespace curvescan::fuzz
