// A CLI11 validator for options that take a CSS colour (render -b, text --color/--background): a value
// that is not a colour is a wrong command line, so a usage error (exit 64) naming the option, before
// anything is read or rendered. Its description is empty: the help names the value in words.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "curvescan/svg/color.h"

namespace curvescan::cli {

inline const CLI::Validator kCssColour(
    [](std::string& text) -> std::string {
      const Result<Color> colour = svg::parse_color(text);
      return colour ? std::string() : colour.error().message;
    },
    "");

}  // namespace curvescan::cli
