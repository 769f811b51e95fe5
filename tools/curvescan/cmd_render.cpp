// `curvescan render IN.svg -o OUT.png`: an SVG document to a PNG (docs/svg.md), with rsvg-convert's
// options where they are sane: -w/--width, -h/--height, -z/--zoom, -b/--background, --dpi, '-' for
// standard input. CLI11 reserves -h for help, so this subcommand turns its help flag off and offers
// --help alone.
//
// Exit codes (exit_codes.h): 0 rendered; 3 bad input (malformed XML, no <svg> root), a limit exceeded or
// an I/O failure; 64 a bad command line. Nothing is written unless rendering succeeded; the PNG is encoded
// in memory, then written through output.h, so a failure never leaves a partial file.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "commands.h"
#include "curvescan/raster/limits.h"
#include "curvescan/raster/png_io.h"
#include "curvescan/svg/color.h"
#include "curvescan/svg/document.h"
#include "exit_codes.h"
#include "finite_number.h"
#include "input_file.h"
#include "large_stack.h"
#include "limit_options.h"
#include "output.h"

namespace curvescan::cli {
namespace {

constexpr const char* kCommand = "render";
// Deepest --max-depth accepted, and the render thread's stack: 64 KiB per nesting level covers the
// renderer's recursion (about 3 KiB per level measured in a release build) with room for sanitizers.
constexpr int kLargestMaxDepth = 4096;
constexpr std::size_t kStackBytesPerLevel = std::size_t{64} << 10;

struct RenderCommandOptions {
  std::string input_path;
  std::string output_path;
  std::optional<double> width, height;
  double zoom = 1.0;
  double dpi = 96.0;
  std::string background;
  double tolerance = kDefaultFlattenTolerance;
  std::string antialias = "default";
  bool verbose = false;
  bool quiet = false;
  bool allow_files = false;
  svg::DocumentLimits limits;
  RenderLimitOptions render_limits;
  std::int64_t max_input_mib = kDefaultMaxInputMiB;
};

int run_render(const RenderCommandOptions& options) {
  svg::RenderOptions render;
  render.width = options.width;
  render.height = options.height;
  render.zoom = options.zoom;
  render.dpi = options.dpi;
  render.tolerance = options.tolerance;
  render.antialias = options.antialias == "none" ? Antialias::kNone : Antialias::kExact;
  render.limits = options.limits;
  render.limits.render = options.render_limits.render_limits();
  // <image> files are read only beside the document, and only when asked (never from standard input).
  if (options.allow_files && options.input_path != "-") {
    render.resource_directory = std::filesystem::absolute(options.input_path).parent_path();
  }
  if (!options.background.empty()) {
    const Result<svg::Color> background = svg::parse_color(options.background);
    if (!background) return report_error(kCommand, "--background: " + background.error().message);
    render.background = *background;
  }
  const Result<std::string> text = read_input(options.input_path, input_size_bytes(options.max_input_mib));
  if (!text) return report_error(kCommand, text.error());
  const std::size_t stack_bytes = (static_cast<std::size_t>(options.limits.max_depth) + 64) * kStackBytesPerLevel;
  const Result<svg::RenderedDocument> rendered =
      run_on_large_stack(stack_bytes, [&] { return svg::render_svg_document(*text, render); });
  if (!rendered) return report_error(kCommand, options.input_path + ": " + rendered.error().message);
  // Warnings -- problems with the input and SVG features this renderer does not support, each named
  // once -- are printed unless -q; notes (elements outside SVG) only with -v.
  if (!options.quiet) {
    for (const std::string& warning : rendered->warnings)
      report_warning(kCommand, options.input_path + ": " + warning);
  }
  if (options.verbose) {
    for (const std::string& note : rendered->notes)
      report_warning(kCommand, options.input_path + ": " + note);
  }
  const Status written = write_png_output(options.output_path, rendered->image);
  if (!written) return report_error(kCommand, written.error());
  return kExitOk;
}

}  // namespace

void add_render_command(CLI::App& root, CommandResult& result) {
  auto o = std::make_shared<RenderCommandOptions>();
  CLI::App* command =
      root.add_subcommand("render", "Render an SVG document (docs/svg.md) to a PNG image, like rsvg-convert");
  command->set_help_flag();  // -h is --height here, as in rsvg-convert
  command->set_help_flag("--help", "Print this help message and exit");
  command->add_option("input", o->input_path, "SVG file, or - for standard input")->required();
  command->add_option("-o,--output", o->output_path, "output PNG file, or - for standard output")->required();
  command
      ->add_option("-w,--width", o->width,
                   "output width in pixels; alone, the height follows the aspect ratio; with -h, the "
                   "drawing is stretched to exactly W x H")
      ->check(kFiniteNumber)
      ->check(CLI::Range(1e-9, 1e9));
  command->add_option("-h,--height", o->height, "output height in pixels (see --width)")
      ->check(kFiniteNumber)
      ->check(CLI::Range(1e-9, 1e9));
  command->add_option("-z,--zoom", o->zoom, "scale factor (ignored on an axis given by -w or -h)")
      ->check(kFiniteNumber)
      ->check(CLI::Range(1e-9, 1e9))
      ->capture_default_str();
  command->add_option("-b,--background", o->background, "background CSS colour (default: transparent)");
  command->add_option("--dpi", o->dpi, "resolution for physical units (in, cm, mm, pt, pc)")
      ->check(kFiniteNumber)
      ->check(CLI::Range(1e-3, 1e6))
      ->capture_default_str();
  command->add_option("--tolerance", o->tolerance, "flattening tolerance in device pixels")
      ->check(kFiniteNumber)
      ->check(CLI::Range(1e-6, 100.0))
      ->capture_default_str();
  command->add_option("--antialias", o->antialias, "none: aliased edges; default: exact-area coverage")
      ->check(CLI::IsMember({"none", "default"}))
      ->capture_default_str();
  CLI::Option* verbose =
      command->add_flag("-v,--verbose", o->verbose, "also report elements outside SVG that were skipped");
  command->add_flag("-q,--quiet", o->quiet, "do not print warnings (errors are still printed)")
      ->excludes(verbose);
  command->add_flag("--allow-files", o->allow_files,
                    "let <image> read files in the document's directory and below (never the network)");
  command->add_option("--max-pixels", o->limits.max_pixels, "largest output image in pixels")
      ->check(CLI::Range(std::int64_t{1}, kMaxImagePixels))
      ->capture_default_str();
  command
      ->add_option("--max-elements", o->limits.max_elements,
                   "most elements rendered, <use> expansions included")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100'000'000}))
      ->capture_default_str();
  command->add_option("--max-depth", o->limits.max_depth, "deepest element nesting")
      ->check(CLI::Range(1, kLargestMaxDepth))
      ->capture_default_str();
  command->add_option("--max-use-depth", o->limits.max_use_depth, "deepest <use> nesting")
      ->check(CLI::Range(1, 10'000))
      ->capture_default_str();
  add_render_limit_options(*command, o->render_limits, /*with_dashes=*/true);
  add_input_size_option(*command, o->max_input_mib);
  command->callback([o, &result] { result.exit_code = run_render(*o); });
}

}  // namespace curvescan::cli
