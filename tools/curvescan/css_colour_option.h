// Checks options that take a CSS colour (text --color/--background, and render -b, which also takes
// "none"): a value that is not a colour is a wrong command line, so a usage error (exit 64) naming the
// option, before anything is read or rendered. The validator's description is empty: the help names the
// value in words.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "curvescan/svg/color.h"

namespace curvescan::cli {

/// Why `text` is not a CSS colour, or empty when it is one.
inline std::string css_colour_error(const std::string& text) {
  const Result<Color> colour = svg::parse_color(text);
  return colour ? std::string() : colour.error().message;
}

inline const CLI::Validator kCssColour([](std::string& text) { return css_colour_error(text); }, "");

}  // namespace curvescan::cli
