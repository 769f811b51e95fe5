// CLI11 validators that say what a value must be. CLI::Range reports "Value abc not in range 0.000000 to
// 1000000000.000000" (a word that is no number, and 1e-9 printed as 0) and lends the help a parser type
// name ("FLOAT in [1e-09 - 1e+09]"); these report
//
//   --zoom: '0' is out of range: give a number from 1e-9 to 1e9
//   --jobs: 'x' is not a whole number: give one from 1 to 1024
//
// and have an empty description, as the help says the range in words (help_formatter.h).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <initializer_list>
#include <string>
#include <type_traits>
#include <vector>

namespace curvescan::cli {

/// `value` as a user would write it: 100, 0.001, 1e-9, 1e9 (printf's %g without its exponent padding).
inline std::string number_words(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  std::string text = buffer;
  if (const std::size_t e = text.find('e'); e != std::string::npos) {
    std::string exponent = text.substr(e + 1);
    const bool negative = exponent[0] == '-';
    exponent.erase(0, exponent.find_first_not_of("+-0"));
    text = text.substr(0, e + 1) + (negative ? "-" : "") + exponent;
  }
  return text;
}

/// The closed range [low, high] of an integer or floating-point option.
template <typename T>
CLI::Validator number_in_range(T low, T high) {
  const std::string kind = std::is_integral_v<T> ? "a whole number" : "a number";
  const std::string bounds = std::is_integral_v<T> ? std::to_string(low) + " to " + std::to_string(high)
                                                   : number_words(low) + " to " + number_words(high);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        T value{};
        if (!CLI::detail::lexical_cast(text, value)) {
          return "'" + text + "' is not " + kind + ": give one from " + bounds;
        }
        if (!(value >= low && value <= high))
          return "'" + text + "' is out of range: give " + kind + " from " + bounds;
        return {};
      },
      "");
}

/// One of `words`, spelt exactly.
inline CLI::Validator one_of(std::initializer_list<const char*> words) {
  std::vector<std::string> choices(words.begin(), words.end());
  std::string listed;
  for (const std::string& word : choices) listed += (listed.empty() ? "" : ", ") + word;
  return CLI::Validator(
      [choices, listed](std::string& text) -> std::string {
        for (const std::string& word : choices) {
          if (text == word) return {};
        }
        return "'" + text + "' is not one of " + listed;
      },
      "");
}

}  // namespace curvescan::cli
