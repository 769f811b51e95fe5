#include "primitive_numbers.h"

#include <cmath>
#include <string_view>

#include "curvescan/svg/number.h"

namespace curvescan::svg::detail::filter {

namespace {

std::optional<std::vector<double>> numbers_of(const pugi::xml_node& element, const char* name) {
  const pugi::xml_attribute attribute = element.attribute(name);
  if (!attribute) return std::nullopt;
  const std::string_view text = trim_whitespace(attribute.value());
  if (text.empty()) return std::nullopt;
  NumberList list = parse_number_list(text);
  if (!list.complete || list.values.empty()) return std::nullopt;
  return std::move(list.values);
}

}  // namespace

std::optional<double> primitive_number(const pugi::xml_node& element, const char* name) {
  const pugi::xml_attribute attribute = element.attribute(name);
  if (!attribute) return std::nullopt;
  return parse_number(attribute.value());
}

std::optional<NumberPair> primitive_number_pair(const pugi::xml_node& element, const char* name) {
  const auto values = numbers_of(element, name);
  if (!values || values->size() > 2) return std::nullopt;
  return NumberPair{values->front(), values->back()};
}

std::optional<std::vector<double>> primitive_number_list(const pugi::xml_node& element, const char* name) {
  return numbers_of(element, name);
}

bool is_integer_value(double v) noexcept {
  return std::isfinite(v) && std::trunc(v) == v;
}

}  // namespace curvescan::svg::detail::filter
