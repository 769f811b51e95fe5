// The parsers of command-line values that are text a user (or a program driving curvescan) supplies, kept
// out of the command files so that the fuzz target cli_options (fuzz/targets/cli_options.cpp) drives the
// very functions the commands call: an HTTP Accept-Language list (render -l), a length with a unit
// (render -w/-h/--left/...), a region x,y,w,h (diff --ignore) and a list of file names (render
// --files-from). Each returns a value or an error message naming the option; none throws.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "curvescan/diff/image_diff.h"
#include "curvescan/status.h"

namespace curvescan::cli {

/// An HTTP Accept-Language list ("es-MX,de;q=0.8,en;q=0.5", RFC 9110 12.5.4) as language tags, most
/// preferred first (a stable sort on the q weights; weight 0 drops a tag).
[[nodiscard]] Result<std::vector<std::string>> parse_accept_language(const std::string& text);

/// A command-line length ("300", "10cm", "2.5in") in pixels at `dpi`: the units rsvg-convert accepts
/// (px, in, cm, mm, pt, pc); the error names `flag`.
[[nodiscard]] Result<double> command_line_length(const std::string& flag, const std::string& text,
                                                 double dpi);

/// "x,y,w,h" (integers, w and h >= 0), the rectangle of diff --ignore.
[[nodiscard]] Result<PixelBox> parse_ignore_region(const std::string& text);

/// A list of input names, one a line; blank lines are skipped, a trailing '\r' is dropped.
[[nodiscard]] std::vector<std::string> parse_name_list(std::string_view text);

}  // namespace curvescan::cli
