// `curvescan render [FILE...]`: SVG documents to PNG images (docs/svg.md), a drop-in for rsvg-convert's
// PNG use: the same flags with the same spelling, defaults and meaning (-w/-h lengths, -a, -z/-x/-y,
// -d/-p, -b, --left/--top/--page-width/--page-height, -f png, -u, -?/--help, -v/--version), standard
// input when no FILE or "-" is given, standard output when no -o is given, gzip-compressed input. Where
// rsvg-convert draws several inputs onto one image, curvescan renders each into its own file in
// --output-dir, on a thread pool (render_batch.h). curvescan's own options are long ones.
//
// Exit codes (exit_codes.h): 0 rendered; 3 bad input (malformed XML, no <svg> root), a limit exceeded or
// an I/O failure (in a batch: any file failed); 64 a bad command line. Nothing is written unless rendering
// succeeded; the PNG is encoded in memory, then written through output.h, so a failure never leaves a
// partial file.
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "command_line_text.h"
#include "commands.h"
#include "css_colour_option.h"
#include "curvescan/raster/limits.h"
#include "curvescan/svg/color.h"
#include "curvescan/svg/document.h"
#include "curvescan/svg/length.h"
#include "exit_codes.h"
#include "finite_number.h"
#include "input_file.h"
#include "limit_options.h"
#include "option_range.h"
#include "output.h"
#include "output_is_input.h"
#include "render_batch.h"
#include "render_file.h"

namespace curvescan::cli {
namespace {

constexpr const char* kCommand = "render";
constexpr int kLargestMaxDepth = 4096;
/// -u/--unlimited: the input size limit it sets (MiB), as rsvg-convert's flag lifts libxml2's limits.
constexpr std::int64_t kUnlimitedInputMiB = 2048;

struct RenderCommandOptions {
  std::vector<std::string> inputs;
  std::string output_path;
  std::string output_dir;
  std::string files_from;
  std::string manifest;
  unsigned jobs = 0;
  std::string width, height;  // lengths with units, as rsvg-convert takes them
  bool keep_aspect_ratio = false;
  std::optional<double> zoom, x_zoom, y_zoom;
  std::optional<double> dpi, dpi_x, dpi_y;
  std::string background;
  std::string stylesheet;                // -s: a CSS file applied after the document's own sheets
  std::string export_id;                 // -i: render only the element with this id
  std::optional<std::string> languages;  // -l: "es-MX,de,en", for <switch> systemLanguage
  bool allow_files = false;
  std::string format = "png";
  std::string left, top, page_width, page_height;
  bool unlimited = false;
  bool keep_image_data = false;  // PDF/PS only in rsvg-convert: accepted, no effect on a PNG
  double tolerance = kDefaultFlattenTolerance;
  std::string antialias = "default";
  bool verbose = false;
  bool quiet = false;
  svg::DocumentLimits limits;
  RenderLimitOptions render_limits;
  std::int64_t max_input_mib = kDefaultMaxInputMiB;
};

std::string lower_case(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

/// The extension of `path`'s last component, lower case, without the dot; empty when it has none.
std::string extension_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t dot = name.find_last_of('.');
  if (dot == std::string::npos || dot == 0) return {};
  return lower_case(name.substr(dot + 1));
}

/// -b none: no background, as rsvg-convert reads it (the default, written out; scripts pass it).
bool is_no_background(const std::string& text) {
  return lower_case(text) == "none";
}

/// The languages a user's environment asks for, when -l is not given: as rsvg-convert (through GLib's
/// g_get_language_names), the first set of LANGUAGE (a colon-separated list), LC_ALL, LC_MESSAGES and
/// LANG. A locale name "de_CH.UTF-8@euro" gives the tags "de-CH" and then "de"; the C and POSIX locales
/// name no language, so with none of these set, no systemLanguage test passes (SVG 1.1 5.8.5).
std::vector<std::string> environment_languages() {
  std::string names;
  for (const char* variable : {"LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"}) {
    const char* value = std::getenv(variable);
    if (value != nullptr && *value != '\0') {
      names = value;
      break;
    }
  }
  std::vector<std::string> tags;
  const auto add = [&tags](std::string tag) {
    if (!tag.empty() && std::find(tags.begin(), tags.end(), tag) == tags.end())
      tags.push_back(std::move(tag));
  };
  std::size_t start = 0;
  while (start <= names.size()) {
    const std::size_t colon = std::min(names.find(':', start), names.size());
    std::string name = names.substr(start, colon - start);
    start = colon + 1;
    name = name.substr(0, name.find_first_of(".@"));  // the codeset and the modifier
    if (name.empty() || name == "C" || name == "POSIX") continue;
    std::replace(name.begin(), name.end(), '_', '-');
    const bool tag =
        std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '-'; });
    if (!tag) continue;
    add(name);
    add(name.substr(0, name.find('-')));
  }
  return tags;
}

/// The render options the flags describe, or a usage error's message.
Result<RenderSettings> settings_from(const RenderCommandOptions& o) {
  RenderSettings settings;
  svg::RenderOptions& render = settings.render;
  render.dpi = o.dpi_x.value_or(o.dpi.value_or(96.0));
  const double dpi_y = o.dpi_y.value_or(o.dpi.value_or(96.0));
  render.dpi_y = dpi_y;
  const auto length = [&](const std::string& flag, const std::string& text, double dpi,
                          std::optional<double>& into, bool positive) -> Status {
    if (text.empty()) return Status::ok();
    const Result<double> pixels = command_line_length(flag, text, dpi);
    if (!pixels) return pixels.error();
    if (positive && !(*pixels > 0.0)) {
      return Error{ErrorKind::kInvalidArgument, flag + ": invalid value '" + text + "': must be positive"};
    }
    into = *pixels;
    return Status::ok();
  };
  CURVESCAN_PROPAGATE(length("--width", o.width, render.dpi, render.width, true));
  CURVESCAN_PROPAGATE(length("--height", o.height, dpi_y, render.height, true));
  CURVESCAN_PROPAGATE(length("--page-width", o.page_width, render.dpi, render.page_width, true));
  CURVESCAN_PROPAGATE(length("--page-height", o.page_height, dpi_y, render.page_height, true));
  if (render.page_width.has_value() != render.page_height.has_value()) {
    return Error{ErrorKind::kInvalidArgument, "give --page-width and --page-height together"};
  }
  std::optional<double> left, top;
  CURVESCAN_PROPAGATE(length("--left", o.left, render.dpi, left, false));
  CURVESCAN_PROPAGATE(length("--top", o.top, dpi_y, top, false));
  render.left = left.value_or(0.0);
  render.top = top.value_or(0.0);
  render.zoom = o.zoom.value_or(1.0);
  render.x_zoom = o.x_zoom.value_or(1.0);
  render.y_zoom = o.y_zoom.value_or(1.0);
  render.keep_aspect_ratio = o.keep_aspect_ratio;
  if (o.languages) {
    const Result<std::vector<std::string>> languages = parse_accept_language(*o.languages);
    if (!languages) return languages.error();
    render.languages = *languages;
  } else {
    render.languages = environment_languages();
  }
  if (!o.export_id.empty()) {
    if (o.export_id == "#") return Error{ErrorKind::kInvalidArgument, "--export-id: '#' names no element"};
    render.export_id = o.export_id;
  }
  settings.allow_files = o.allow_files;
  render.tolerance = o.tolerance;
  render.antialias = o.antialias == "none" ? Antialias::kNone : Antialias::kExact;
  render.limits = o.limits;
  render.limits.render = o.render_limits.render_limits();
  if (!o.background.empty() && !is_no_background(o.background)) {
    const Result<Color> background = svg::parse_color(o.background);
    if (!background) {
      return Error{ErrorKind::kInvalidArgument, "--background-color: " + background.error().message};
    }
    render.background = *background;
  }
  if (lower_case(o.format) != "png") {
    return Error{ErrorKind::kInvalidArgument,
                 "--format: '" + o.format + "' is not supported; PNG is the one format curvescan writes"};
  }
  settings.max_input_bytes =
      input_size_bytes(o.unlimited ? std::max(o.max_input_mib, kUnlimitedInputMiB) : o.max_input_mib);
  return settings;
}

void report_messages(const std::string& input, const RenderedFile& rendered, bool verbose, bool quiet) {
  if (quiet) return;
  const std::string name = input == "-" ? "standard input" : input;
  for (const std::string& warning : rendered.warnings) report_warning(kCommand, name + ": " + warning);
  if (verbose) {
    for (const std::string& note : rendered.notes) report_warning(kCommand, name + ": " + note);
  }
}

int run_single(const RenderCommandOptions& o, const RenderSettings& settings) {
  const std::string input = o.inputs.empty() ? "-" : o.inputs.front();
  const std::string output = o.output_path.empty() ? "-" : o.output_path;
  if (output == "-" && isatty(STDOUT_FILENO)) {
    return report_usage_error(kCommand,
                              "standard output is a terminal; name a PNG file with -o, or redirect");
  }
  // One file: its large fills use the cores (-j, default all); a batch uses them for files instead.
  RenderSettings single = settings;
  single.render.threads =
      static_cast<int>(o.jobs != 0 ? o.jobs : std::max(1u, std::thread::hardware_concurrency()));
  const RenderedFile rendered = render_svg_file(input, single);
  if (!rendered.image) return report_error(kCommand, rendered.image.error());
  report_messages(input, rendered, o.verbose, o.quiet);
  const Status written = write_png_output(output, *rendered.image);
  if (!written) return report_error(kCommand, written.error());
  return kExitOk;
}

int run_render(RenderCommandOptions o) {
  if (o.zoom && (o.x_zoom || o.y_zoom)) {
    return report_usage_error(kCommand, "--zoom cannot be combined with --x-zoom or --y-zoom");
  }
  Result<RenderSettings> settings = settings_from(o);
  if (!settings) return report_usage_error(kCommand, settings.error().message);
  if (!o.stylesheet.empty()) {
    // A user style sheet (docs/svg.md, "CSS"), read under the same size bound as the documents.
    Result<std::string> sheet = read_input(o.stylesheet, settings->max_input_bytes);
    if (!sheet) return report_error(kCommand, "--stylesheet: " + sheet.error().message);
    settings->render.style_sheet = std::move(sheet).value();
    // Its messages name the file, with the line and column of the rule (standard input: "-").
    settings->render.style_sheet_name = o.stylesheet == "-" ? "style sheet on standard input" : o.stylesheet;
  }
  if (!o.output_path.empty() && o.output_path != "-") {
    const std::string extension = extension_of(o.output_path);
    if (!extension.empty() && extension != "png") {
      return report_usage_error(kCommand, "the output '" + o.output_path + "' is named ." + extension +
                                              ", but PNG is the one format curvescan writes (name it .png)");
    }
  }
  std::vector<std::string> read_files = o.inputs;
  for (const std::string* also : {&o.stylesheet, &o.files_from}) read_files.push_back(*also);
  for (const std::string* output : {&o.output_path, &o.manifest}) {
    if (const auto input = input_named_by_output(*output, read_files))
      return report_usage_error(kCommand, output_is_input_message(*output, *input));
  }
  const bool batch = !o.output_dir.empty() || !o.files_from.empty() || o.inputs.size() > 1;
  if (!batch) return run_single(o, *settings);
  if (o.output_dir.empty()) {
    return report_usage_error(kCommand,
                              "several inputs need --output-dir DIR (each output is named after its input)");
  }
  if (!o.output_path.empty())
    return report_usage_error(kCommand, "-o names one output; with --output-dir leave it out");
  BatchOptions batch_options;
  batch_options.inputs = o.inputs;
  batch_options.files_from = o.files_from;
  batch_options.output_dir = o.output_dir;
  batch_options.manifest = o.manifest;
  batch_options.jobs = o.jobs;
  batch_options.verbose = o.verbose;
  batch_options.quiet = o.quiet;
  return run_render_batch(batch_options, *settings);
}

/// -o "", -i "", -s "", -l "": refused as rsvg-convert refuses them. An empty -o from an unset shell
/// variable must not quietly mean standard output.
const CLI::Validator kNotEmpty(
    [](std::string& text) {
      return text.empty() ? std::string("an empty value names nothing") : std::string();
    },
    "");

/// -b: a CSS colour, or none.
const CLI::Validator kBackgroundColour(
    [](std::string& text) {
      if (is_no_background(text)) return std::string();
      const std::string error = css_colour_error(text);
      return error.empty() ? error : error + " (nor none)";
    },
    "");

}  // namespace

void add_render_command(CLI::App& root, CommandResult& result) {
  auto o = std::make_shared<RenderCommandOptions>();
  CLI::App* command = root.add_subcommand(
      "render",
      "Render SVG documents (docs/svg.md) to PNG images, with rsvg-convert's options. Lengths are a number "
      "with a unit: px, in, cm, mm, pt or pc (a plain number is px).\n"
      "Examples:\n"
      "  curvescan render icon.svg -o icon.png\n"
      "  curvescan render -w 512 -a drawing.svgz > drawing.png\n"
      "  curvescan render -d 300 -p 300 -b white poster.svg -o poster.png\n"
      "  curvescan render icons/*.svg --output-dir png/ -j 2 --manifest png/manifest.jsonl");
  command->set_help_flag();  // -h is --height here, as in rsvg-convert
  command->set_help_flag("-?,--help", "print this help and exit");
  command->footer(std::string(kLimitsHelp) + "\n" + kExitCodesHelp);
  command->set_version_flag("-v,--version", kVersionText, "print the version and exit");
  // Each option names its value in words and states its unit, range and default (help_formatter.h).
  command->add_option("FILE", o->inputs,
                      "SVG or gzip-compressed SVG files; none or - reads standard input; several need "
                      "--output-dir");
  command->add_option("-o,--output", o->output_path, "output PNG file; - or none: standard output")
      ->type_name("FILE")
      ->check(kNotEmpty);
  command
      ->add_option("-w,--width", o->width,
                   "output width, a length; alone, the height follows the aspect ratio; with -h, the drawing "
                   "is stretched unless -a (default: the document's width)")
      ->type_name("LENGTH");
  command
      ->add_option("-h,--height", o->height, "output height, a length (see --width; default: the document's)")
      ->type_name("LENGTH");
  command->add_flag("-a,--keep-aspect-ratio", o->keep_aspect_ratio,
                    "with -w and -h, scale uniformly to fit inside them; with a zoom, shrink it uniformly");
  command
      ->add_option("-z,--zoom", o->zoom,
                   "scale factor for both axes, 1e-9 to 1e9 (default 1; not with -x, -y)")
      ->type_name("FACTOR")
      ->check(kFiniteNumber)
      ->check(number_in_range(1e-9, 1e9));
  command->add_option("-x,--x-zoom", o->x_zoom, "horizontal scale factor, 1e-9 to 1e9 (default 1)")
      ->type_name("FACTOR")
      ->check(kFiniteNumber)
      ->check(number_in_range(1e-9, 1e9));
  command->add_option("-y,--y-zoom", o->y_zoom, "vertical scale factor, 1e-9 to 1e9 (default 1)")
      ->type_name("FACTOR")
      ->check(kFiniteNumber)
      ->check(number_in_range(1e-9, 1e9));
  command
      ->add_option(
          "-d,--dpi-x", o->dpi_x,
          "horizontal resolution for physical units (in, cm, mm, pt, pc) in pixels per inch, 0.001 to "
          "1e6 (default 96)")
      ->type_name("DPI")
      ->check(kFiniteNumber)
      ->check(number_in_range(1e-3, 1e6));
  command
      ->add_option(
          "-p,--dpi-y", o->dpi_y,
          "vertical resolution in pixels per inch, 0.001 to 1e6 (default 96, also when only -d is given)")
      ->type_name("DPI")
      ->check(kFiniteNumber)
      ->check(number_in_range(1e-3, 1e6));
  command
      ->add_option(
          "--dpi", o->dpi,
          "resolution of both axes in pixels per inch, 0.001 to 1e6; -d and -p override it (default 96)")
      ->type_name("DPI")
      ->check(kFiniteNumber)
      ->check(number_in_range(1e-3, 1e6));
  command
      ->add_option(
          "-b,--background-color,--background", o->background,
          "CSS colour painted under the drawing: a name, #rgb, #rrggbb, rgb(), hsl(), or none for no "
          "background (default: transparent)")
      ->type_name("COLOUR")
      ->check(kBackgroundColour);
  command
      ->add_option("-i,--export-id", o->export_id,
                   "render only the element with this id (\"#id\" or \"id\"), at the size of what it draws "
                   "(default: the whole document)")
      ->type_name("ID")
      ->check(kNotEmpty);
  command
      ->add_option("-s,--stylesheet", o->stylesheet,
                   "CSS file applied after the document's own style sheets; - reads standard input "
                   "(default: none)")
      ->type_name("FILE")
      ->check(kNotEmpty);
  command
      ->add_option(
          "-l,--accept-language", o->languages,
          "languages for <switch> systemLanguage, most preferred first, e.g. \"es-MX,de;q=0.8,en\" "
          "(default: the environment's, from LANGUAGE, LC_ALL, LC_MESSAGES or LANG; none under the C "
          "locale)")
      ->type_name("LANGUAGES")
      ->check(kNotEmpty);
  command->add_flag("--allow-files", o->allow_files,
                    "let <image> read files in the document's directory and below (never the network)");
  command->add_option("-f,--format", o->format, "output format; png is the only one")
      ->type_name("FORMAT")
      ->capture_default_str();
  command
      ->add_option("--left", o->left,
                   "distance from the page's left edge to the drawing, a length (default 0)")
      ->type_name("LENGTH");
  command
      ->add_option("--top", o->top, "distance from the page's top edge to the drawing, a length (default 0)")
      ->type_name("LENGTH");
  command
      ->add_option("--page-width", o->page_width,
                   "image width when it should differ from the drawing's, a length (with --page-height)")
      ->type_name("LENGTH");
  command->add_option("--page-height", o->page_height, "image height, a length (with --page-width)")
      ->type_name("LENGTH");
  command->add_flag("-u,--unlimited", o->unlimited,
                    "allow huge SVG files: the input size limit becomes at least " +
                        std::to_string(kUnlimitedInputMiB) + " MiB");
  command->add_flag("--keep-image-data,!--no-keep-image-data", o->keep_image_data,
                    "accepted for rsvg-convert compatibility; no effect on PNG output");
  command
      ->add_option("--output-dir", o->output_dir,
                   "render each FILE to DIR/NAME.png (NAME: the file's name without .svg/.svgz)")
      ->type_name("DIR");
  command
      ->add_option("--files-from", o->files_from,
                   "also render the files named in this file, one a line; - reads standard input")
      ->type_name("LIST");
  command
      ->add_option("-j,--jobs", o->jobs,
                   "threads: files rendered at once in a batch, or for one file those drawing it (the pixels "
                   "do not depend on it), 1 to 1024 (default: all cores)")
      ->type_name("N")
      ->check(number_in_range(1u, 1024u));
  command
      ->add_option("--manifest", o->manifest,
                   "with --output-dir: write one JSON line per input (input, output, status, milliseconds, "
                   "warnings) to this file")
      ->type_name("FILE.jsonl");
  command
      ->add_option("--tolerance", o->tolerance,
                   "flattening tolerance: the largest distance between a curve and its line segments, in "
                   "device pixels, 1e-6 to 100")
      ->type_name("PIXELS")
      ->check(kFiniteNumber)
      ->check(number_in_range(1e-6, 100.0))
      ->capture_default_str();
  command
      ->add_option("--antialias", o->antialias,
                   "default: exact-area coverage of every pixel (the default); none: aliased edges")
      ->type_name("MODE")
      ->check(one_of({"none", "default"}));
  CLI::Option* verbose = command->add_flag(
      "--verbose", o->verbose, "also report elements outside SVG that were skipped (notes); not with -q");
  command->add_flag("-q,--quiet", o->quiet, "no warnings, no progress line; errors only; not with --verbose")
      ->excludes(verbose);
  command
      ->add_option("--max-pixels", o->limits.max_pixels,
                   "largest output image in pixels, 1 to " + std::to_string(kMaxImagePixels))
      ->type_name("PIXELS")
      ->check(number_in_range(std::int64_t{1}, kMaxImagePixels))
      ->capture_default_str();
  command
      ->add_option("--max-elements", o->limits.max_elements,
                   "most elements rendered, <use> expansions included, 1 to 100000000")
      ->type_name("N")
      ->check(number_in_range(std::size_t{1}, std::size_t{100'000'000}))
      ->capture_default_str();
  command
      ->add_option("--max-depth", o->limits.max_depth,
                   "deepest element nesting, 1 to " + std::to_string(kLargestMaxDepth))
      ->type_name("N")
      ->check(number_in_range(1, kLargestMaxDepth))
      ->capture_default_str();
  command->add_option("--max-use-depth", o->limits.max_use_depth, "deepest <use> nesting, 1 to 10000")
      ->type_name("N")
      ->check(number_in_range(1, 10'000))
      ->capture_default_str();
  add_render_limit_options(*command, o->render_limits, /*with_dashes=*/true);
  add_input_size_option(*command, o->max_input_mib);
  command->callback([o, &result] { result.exit_code = run_render(*o); });
}

}  // namespace curvescan::cli
