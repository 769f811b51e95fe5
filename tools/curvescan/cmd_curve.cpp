// `curvescan curve SPEC.json [--tolerance T] [-o OUT.json]`: one curve from a JSON spec, flattened.
//
// Prints JSON: the exact Bézier pieces of the curve (every family converts exactly; see curve_spec.h) and
// the polyline the flattener makes of them, within the tolerance as a Hausdorff distance.
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <span>
#include <string>

#include "commands.h"
#include "curve_families.h"
#include "curve_spec.h"
#include "curvescan/curves/flatten.h"
#include "exit_codes.h"
#include "finite_number.h"
#include "input_file.h"
#include "limit_options.h"
#include "option_range.h"
#include "output.h"
#include "output_is_input.h"

namespace curvescan::cli {
namespace {

struct CurveOptions {
  std::string spec_path;
  std::string output_path = "-";
  double tolerance = kDefaultFlattenTolerance;
  CurveSpecLimits limits;
  std::int64_t max_segments = kDefaultMaxRenderSegments;  // polyline segments (limits.h)
  std::int64_t max_input_mib = kDefaultMaxInputMiB;
  std::int64_t max_memory_mib = kDefaultMaxMemoryMiB;
};

// What the command holds, counted against --max-memory before it is allocated:
// - the parsed spec: nlohmann::json is 16 bytes a value, held in a std::vector that may be twice as long
//   as its elements (32), plus the array or object itself and an object member's map node (about 64)
//   and key; a first SAX pass counts these without building anything;
// - the exact pieces (a 16-byte Point each, a vector per piece) and the polyline (a Point each), and the
//   JSON text of both, about 56 bytes a point (two 17-digit numbers and the layout).
// Measured: a 200 000-point cubic B-spline (4.1 million polyline points) is counted as 361 MiB and
// peaks at 354 MiB (RSS).
constexpr std::int64_t kSpecBytesPerValue = 48;
constexpr std::int64_t kSpecBytesPerMember = 64;
constexpr std::int64_t kOutputBytesPerPoint = 16 + 56;
constexpr std::int64_t kOutputBytesPerPiece = 64;

// Counts what parsing `text` into a DOM would allocate (see above); stops counting at a syntax error, which
// the real parse then reports.
struct SpecMemoryCounter : nlohmann::json_sax<nlohmann::json> {
  std::int64_t bytes = 0;
  bool value() {
    bytes += kSpecBytesPerValue;
    return true;
  }
  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t& text) override {
    bytes += static_cast<std::int64_t>(text.size());
    return value();
  }
  bool binary(binary_t& data) override {
    bytes += static_cast<std::int64_t>(data.size());
    return value();
  }
  bool start_object(std::size_t) override { return value(); }
  bool key(string_t& text) override {
    bytes += kSpecBytesPerMember + static_cast<std::int64_t>(text.size());
    return true;
  }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return value(); }
  bool end_array() override { return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& error) override {
    // nlohmann's message reads "[json.exception.parse_error.101] parse error at line L, column C: why";
    // the user needs the part from "line".
    syntax_error = error.what();
    if (const std::size_t at = syntax_error.find("line "); at != std::string::npos) syntax_error.erase(0, at);
    // Others (a number too large, "[json.exception.out_of_range.406] number overflow parsing '1e400'") have
    // no position: only the tag goes.
    if (syntax_error.starts_with("[json.exception.")) {
      if (const std::size_t end = syntax_error.find("] "); end != std::string::npos)
        syntax_error.erase(0, end + 2);
    }
    // It quotes the text last read: bytes of a binary file must not reach the terminal, nor a long run.
    constexpr std::size_t kMaxLength = 200;
    if (syntax_error.size() > kMaxLength) syntax_error = syntax_error.substr(0, kMaxLength) + "...";
    for (char& c : syntax_error)
      if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    return false;
  }
  std::string syntax_error;  ///< where and why the text is not JSON; empty when it is
};

std::string memory_message(const std::string& what, std::int64_t bytes, std::int64_t max_memory_mib,
                           const std::string& flags = "--max-memory") {
  return what + " needs " + std::to_string((bytes + (1 << 20) - 1) >> 20) + " MiB, beyond the memory limit of " +
         std::to_string(max_memory_mib) + " MiB (raise " + flags + ")";
}

// A JSON number with the shortest round-trip representation, appended to `text`: nlohmann::json's own
// formatting of a finite double (its serializer calls detail::to_chars, Grisu2, for exactly this), without
// building a json value and a serializer per number, which made up most of the time of a 10^5-point curve
// (a polyline of millions of points). Non-finite values, which the pieces and the polyline never hold,
// still go through dump() (as null).
void append_number(std::string& text, double value) {
  if (!std::isfinite(value)) {
    text += nlohmann::json(value).dump();
    return;
  }
  char buffer[64];
  const char* end = nlohmann::detail::to_chars(buffer, buffer + sizeof buffer, value);
  text.append(buffer, static_cast<std::size_t>(end - buffer));
}

void append_point_list(std::string& text, std::span<const Point> points, const char* indent) {
  text += '[';
  for (std::size_t i = 0; i < points.size(); ++i) {
    text += i == 0 ? "\n" : ",\n";
    text += indent;
    text += '[';
    append_number(text, points[i].x);
    text += ", ";
    append_number(text, points[i].y);
    text += ']';
  }
  text += ']';
}

// One curve as JSON, laid out for people: a point per line, fields in a fixed order.
std::string curve_json(const std::string& type, double tolerance, const std::vector<CurveSegment>& segments,
                       std::span<const Point> polyline) {
  std::string text = "{\n \"type\": " + nlohmann::json(type).dump() + ",\n \"tolerance\": ";
  // About 40 characters a point (two 17-digit numbers and the layout): one allocation instead of doubling
  // through a string of 100 MB and more.
  std::size_t point_count = polyline.size();
  for (const CurveSegment& segment : segments) point_count += segment.points.size() + segment.weights.size();
  text.reserve(48 * point_count + 256);
  append_number(text, tolerance);
  text += ",\n \"segments\": [";
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const CurveSegment& segment = segments[i];
    text += i == 0 ? "\n" : ",\n";
    text += "  {\"degree\": " + std::to_string(segment.points.size() - 1) + ", \"points\": ";
    append_point_list(text, segment.points, "    ");
    if (!segment.weights.empty()) text += ",\n   \"weights\": " + nlohmann::json(segment.weights).dump();
    text += '}';
  }
  text += "],\n \"polyline\": ";
  append_point_list(text, polyline, "  ");
  text += "\n}\n";
  return text;
}

void append_polylines(std::string& text, const std::vector<std::vector<Point>>& polylines) {
  text += '[';
  for (std::size_t i = 0; i < polylines.size(); ++i) {
    text += i == 0 ? "\n  " : ",\n  ";
    append_point_list(text, polylines[i], "   ");
  }
  text += ']';
}

// The JSON of an explicit or implicit curve or of patches (curve_families.h): the exact pieces where there
// are any, the polylines (one `polyline` when an explicit graph is not split), and the notes.
std::string family_json(const std::string& type, double tolerance, const FamilyCurve& curve) {
  std::string text = "{\n \"type\": " + nlohmann::json(type).dump() + ",\n \"tolerance\": ";
  append_number(text, tolerance);
  if (type == "bezier-patch") {
    text += ",\n \"segments\": [";
    for (std::size_t i = 0; i < curve.segments.size(); ++i) {
      const CurveSegment& segment = curve.segments[i];
      text += i == 0 ? "\n" : ",\n";
      text += "  {\"degree\": " + std::to_string(segment.points.size() - 1) + ", \"points\": ";
      append_point_list(text, segment.points, "    ");
      if (!segment.weights.empty()) text += ",\n   \"weights\": " + nlohmann::json(segment.weights).dump();
      text += '}';
    }
    text += ']';
  }
  if (type == "explicit" && curve.polylines.size() == 1) {
    text += ",\n \"polyline\": ";
    append_point_list(text, curve.polylines[0], "  ");
  } else {
    text += ",\n \"polylines\": ";
    append_polylines(text, curve.polylines);
  }
  if (!curve.notes.empty()) text += ",\n \"notes\": " + nlohmann::json(curve.notes).dump();
  text += "\n}\n";
  return text;
}

/// "'spec.json'" or "standard input": what every error about the spec's content begins with, so that a
/// message read in a script's log says which file to fix.
std::string spec_source(const CurveOptions& options) {
  return options.spec_path == "-" ? "standard input" : "'" + options.spec_path + "'";
}

int report_spec_error(const CurveOptions& options, const std::string& message) {
  return report_error("curve", spec_source(options) + ": " + message);
}

int run_family(const CurveOptions& options, const nlohmann::json& spec, std::int64_t spec_bytes) {
  constexpr const char* kCommand = "curve";
  const Result<FamilyCurve> curve =
      build_family_curve(spec, options.tolerance, static_cast<std::size_t>(options.max_segments), options.limits);
  if (!curve) return report_spec_error(options, curve.error().message);
  std::int64_t used = spec_bytes;
  for (const auto& polyline : curve->polylines) used += static_cast<std::int64_t>(polyline.size()) * kOutputBytesPerPoint;
  for (const CurveSegment& segment : curve->segments) {
    used += kOutputBytesPerPiece + static_cast<std::int64_t>(segment.points.size()) * kOutputBytesPerPoint;
  }
  if (used > (options.max_memory_mib << 20)) {
    return report_spec_error(options,
                             memory_message("the curve with its JSON text", used, options.max_memory_mib));
  }
  for (const std::string& note : curve->notes) report_warning(kCommand, note);
  const Status written = write_output(options.output_path, family_json(spec.at("type").get<std::string>(),
                                                                       options.tolerance, *curve));
  if (!written) return report_error(kCommand, written.error());
  return kExitOk;
}

int run_curve(const CurveOptions& options) {
  constexpr const char* kCommand = "curve";
  if (!std::isfinite(options.tolerance)) return report_error(kCommand, "--tolerance must be a finite number");
  if (const auto input = input_named_by_output(options.output_path, {options.spec_path}))
    return report_usage_error(kCommand, output_is_input_message(options.output_path, *input));
  const Result<std::string> text = read_input(options.spec_path, input_size_bytes(options.max_input_mib));
  if (!text) return report_error(kCommand, text.error());
  const std::int64_t budget = options.max_memory_mib << 20;
  SpecMemoryCounter counter;
  (void)nlohmann::json::sax_parse(*text, &counter, nlohmann::json::input_format_t::json, /*strict=*/true);
  if (counter.bytes > budget)
    return report_spec_error(options,
                             memory_message("parsing the spec", counter.bytes, options.max_memory_mib));
  // JSON text has no NUL byte (RFC 8259 section 7 escapes it in strings); the parser would stop at one and
  // accept the spec before it, whatever follows.
  if (const std::size_t nul = text->find('\0'); nul != std::string::npos) {
    return report_error(kCommand, spec_source(options) + " is not valid JSON: a NUL byte at offset " +
                                      std::to_string(nul) + " (is the file binary?)");
  }
  const nlohmann::json spec = nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
  if (spec.is_discarded()) {
    return report_error(kCommand, spec_source(options) + " is not valid JSON" +
                                      (counter.syntax_error.empty() ? "" : ": " + counter.syntax_error));
  }
  if (spec.is_object() && spec.contains("type") && spec["type"].is_string() &&
      is_family_type(spec["type"].get<std::string>())) {
    return run_family(options, spec, counter.bytes);
  }
  const Result<std::vector<CurveSegment>> segments = build_curve_segments(spec, options.limits);
  if (!segments) return report_spec_error(options, segments.error().message);
  std::int64_t used = counter.bytes;
  for (const CurveSegment& segment : *segments) {
    used += kOutputBytesPerPiece +
            static_cast<std::int64_t>(segment.points.size() + segment.weights.size()) * kOutputBytesPerPoint;
  }
  if (used > budget)
    return report_spec_error(options,
                             memory_message("the spec with its exact pieces", used, options.max_memory_mib));
  // The polyline and its text may use what is left: as many points as fit, if fewer than --max-segments
  // allows; a polyline that needs more is reported against --max-memory.
  const std::int64_t points_in_memory = (budget - used) / kOutputBytesPerPoint;
  const bool memory_bound = points_in_memory - 1 < options.max_segments;
  const std::int64_t max_segments = memory_bound ? std::max<std::int64_t>(1, points_in_memory - 1) : options.max_segments;
  const Result<std::vector<Point>> polyline =
      flatten_curve_segments(*segments, options.tolerance, static_cast<std::size_t>(max_segments));
  if (!polyline && memory_bound && polyline.error().kind == ErrorKind::kLimitExceeded &&
      polyline.error().message.find("--max-segments") != std::string::npos) {
    return report_spec_error(options,
                             "the polyline needs more than " + std::to_string(max_segments) +
                                 " segments at this tolerance, more than the memory limit of " +
                                 std::to_string(options.max_memory_mib) +
                                 " MiB holds with its JSON text (raise --max-memory or --tolerance)");
  }
  if (!polyline) return report_spec_error(options, polyline.error().message);
  const std::string json = curve_json(spec.at("type").get<std::string>(), options.tolerance, *segments, *polyline);
  const Status written = write_output(options.output_path, json);
  if (!written) return report_error(kCommand, written.error());
  return kExitOk;
}

}  // namespace

void add_curve_command(CLI::App& root, CommandResult& result) {
  auto options = std::make_shared<CurveOptions>();
  CLI::App* command = root.add_subcommand(
      "curve",
      "Read one curve from a JSON spec (docs/curve-spec.md), print its exact Bezier pieces and its "
      "flattened polyline as JSON.\n"
      "Examples:\n"
      "  curvescan curve spline.json -o spline-out.json\n"
      "  echo '{\"type\": \"bezier\", \"points\": [[0,0],[10,30],[40,-20],[50,10]]}' | curvescan curve -\n"
      "  curvescan curve nurbs.json --tolerance 0.01 --max-segments 100000");
  command->set_help_flag("-h,--help", "print this help and exit");
  command->footer(std::string(kLimitsHelp) + "\n" + kExitCodesHelp);
  // Each option names its value in words and states its unit, range and default (help_formatter.h).
  command->add_option("SPEC", options->spec_path, "curve spec, a JSON file; - reads standard input")->required();
  command->add_option("-o,--output", options->output_path, "output JSON file; - writes standard output (default: standard output)")
      ->type_name("FILE");
  command
      ->add_option("--tolerance", options->tolerance,
                   "flattening tolerance: the largest distance between polyline and curve, in curve units, "
                   "1e-9 to 1e9")
      ->type_name("DISTANCE")
      ->check(kFiniteNumber)
      ->check(number_in_range(1e-9, 1e9))
      ->capture_default_str();
  command->add_option("--max-degree", options->limits.max_degree, "largest degree a spec may ask for, 1 to 1024")
      ->type_name("N")
      ->check(number_in_range(1, 1024))
      ->capture_default_str();
  command
      ->add_option("--max-points", options->limits.max_points,
                   "most control points (and knots) a B-spline, NURBS or interpolation spec may list, 1 to " +
                       std::to_string(std::size_t{1} << 26))
      ->type_name("N")
      ->check(number_in_range(std::size_t{1}, std::size_t{1} << 26))
      ->capture_default_str();
  command
      ->add_option("--max-segments", options->max_segments,
                   "most segments the flattened polyline may have, 1 to " + std::to_string(kLargestSegmentBudget))
      ->type_name("N")
      ->check(number_in_range(std::int64_t{1}, kLargestSegmentBudget))
      ->capture_default_str();
  add_input_size_option(*command, options->max_input_mib);
  command
      ->add_option("--max-memory", options->max_memory_mib,
                   "memory in MiB for the parsed spec, the polyline and its JSON text, 1 to " +
                       std::to_string(kLargestMemoryMiB))
      ->type_name("MiB")
      ->check(number_in_range(std::int64_t{1}, kLargestMemoryMiB))
      ->capture_default_str();
  command->callback([options, &result] { result.exit_code = run_curve(*options); });
}

}  // namespace curvescan::cli
