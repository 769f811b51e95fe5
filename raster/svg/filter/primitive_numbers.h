// The number-valued attributes of filter primitives (Filter Effects 1, section 15 and its attribute
// grammars): <number>, <number-optional-number>, <list-of-numbers> and <integer>, read from plain XML
// attributes. A value that does not parse is treated as if the attribute were absent, so the caller applies
// the attribute's lacuna value (Filter Effects 1, section 2 "lacuna value"); the spec's error cases
// (negative frequencies, wrong matrix sizes...) are decided by each primitive's reader.
#pragma once

#include <optional>
#include <pugixml.hpp>
#include <vector>

namespace curvescan::svg::detail::filter {

/// The two numbers of a <number-optional-number>; `y` repeats `x` when one number was given.
struct NumberPair {
  double x = 0.0;
  double y = 0.0;
};

/// One finite number, or nullopt when the attribute is absent or not exactly one number.
[[nodiscard]] std::optional<double> primitive_number(const pugi::xml_node& element, const char* name);
/// One or two finite numbers, or nullopt when absent or malformed (three numbers, junk, "1,").
[[nodiscard]] std::optional<NumberPair> primitive_number_pair(const pugi::xml_node& element,
                                                              const char* name);
/// A whole list of finite numbers, or nullopt when absent or malformed.
[[nodiscard]] std::optional<std::vector<double>> primitive_number_list(const pugi::xml_node& element,
                                                                       const char* name);
/// True when `v` is an integer (the <integer> of the grammars; "3.0" written as a number counts).
[[nodiscard]] bool is_integer_value(double v) noexcept;

}  // namespace curvescan::svg::detail::filter
