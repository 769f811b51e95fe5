// One SVG file to one image (render_file.h).
#include "render_file.h"

#include <filesystem>
#include <system_error>

#include "curvescan/svg/gzip.h"
#include "input_file.h"
#include "large_stack.h"
#include "limit_options.h"

namespace curvescan::cli {
namespace {

// 64 KiB of stack per nesting level covers the renderer's recursion (about 3 KiB per level measured in a
// release build) with room for sanitizers; 64 levels more for the calls around it.
constexpr std::size_t kStackBytesPerLevel = std::size_t{64} << 10;

std::string display_name(const std::string& input) { return input == "-" ? "standard input" : input; }

}  // namespace

RenderedFile render_svg_file(const std::string& input, const RenderSettings& settings) {
  RenderedFile result;
  Result<std::string> text = read_input(input, settings.max_input_bytes);
  if (!text) {
    result.image = text.error();
    return result;
  }
  if (svg::is_gzip(*text)) {
    // The same size limit as an uncompressed input: a small compressed file cannot expand without bound.
    text = svg::gunzip(*text, settings.max_input_bytes);
    if (!text) {
      const Error& error = text.error();
      result.image = error.kind == ErrorKind::kLimitExceeded
                         ? input_too_large(display_name(input) + " (uncompressed)", settings.max_input_bytes)
                         : Error{error.kind, "'" + display_name(input) + "': " + error.message};
      return result;
    }
  }
  svg::RenderOptions options = settings.render;
  if (settings.allow_files && input != "-") {
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(input, error);
    if (!error) options.resource_directory = absolute.parent_path();
  }
  const std::size_t stack_bytes =
      (static_cast<std::size_t>(settings.render.limits.max_depth) + 64) * kStackBytesPerLevel;
  Result<svg::RenderedDocument> rendered =
      run_on_large_stack(stack_bytes, [&] { return svg::render_svg_document(*text, options); });
  if (!rendered) {
    Error error = rendered.error();
    error.message = display_name(input) + ": " + error.message;
    result.image = std::move(error);
    return result;
  }
  result.warnings = std::move(rendered->warnings);
  result.notes = std::move(rendered->notes);
  result.image = std::move(rendered->image);
  return result;
}

}  // namespace curvescan::cli
