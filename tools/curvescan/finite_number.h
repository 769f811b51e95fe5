// A CLI11 validator for floating-point options: CLI::Range compares with < and >, which NaN passes, so
// "-z nan" reached the library; with this check every NaN or infinite option value is a usage error (64),
// and a value that is not a number at all is named as such (CLI11's own "Could not convert" says less).
// Its description is empty: the help names the value in words (help_formatter.h).
#pragma once

#include <cmath>
#include <string>

#include <CLI/CLI.hpp>

namespace curvescan::cli {

inline const CLI::Validator kFiniteNumber(
    [](std::string& text) -> std::string {
      try {
        std::size_t used = 0;
        const double value = std::stod(text, &used);
        if (used != text.size()) return "'" + text + "' is not a number";
        if (std::isfinite(value)) return {};
      } catch (const std::out_of_range&) {  // beyond double, e.g. 1e400
      } catch (const std::exception&) {
        return "'" + text + "' is not a number";
      }
      return "the value '" + text + "' is not a finite number";
    },
    "");

}  // namespace curvescan::cli
