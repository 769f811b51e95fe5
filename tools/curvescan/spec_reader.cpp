#include "spec_reader.h"

#include <cmath>
#include <limits>

namespace curvescan::cli {
namespace {

std::optional<double> finite_number(const nlohmann::json& value) {
  if (!value.is_number()) return std::nullopt;
  const double number = value.get<double>();
  if (!std::isfinite(number)) return std::nullopt;
  return number;
}

std::optional<Point> finite_point(const nlohmann::json& value) {
  if (!value.is_array() || value.size() != 2) return std::nullopt;
  const auto x = finite_number(value[0]);
  const auto y = finite_number(value[1]);
  if (!x || !y) return std::nullopt;
  return Point{*x, *y};
}

}  // namespace

void SpecReader::fail(std::string message) {
  if (!error_) error_ = Error{ErrorKind::kInvalidArgument, std::move(message)};
}

void SpecReader::fail_limit(std::string message) {
  if (!error_) error_ = Error{ErrorKind::kLimitExceeded, std::move(message)};
}

const nlohmann::json* SpecReader::field_or_fail(const char* field) {
  if (failed()) return nullptr;
  const auto it = object_.find(field);
  if (it == object_.end()) {
    fail(std::string("missing field '") + field + "'");
    return nullptr;
  }
  return &*it;
}

std::vector<Point> SpecReader::points(const char* field, std::size_t max_count) {
  const nlohmann::json* value = field_or_fail(field);
  if (!value) return {};
  if (!value->is_array()) {
    fail(std::string("'") + field + "' must be an array of [x, y] pairs");
    return {};
  }
  if (value->size() > max_count) {
    fail_limit(std::string("'") + field + "' has " + std::to_string(value->size()) + " points, above the limit of " +
               std::to_string(max_count) + " (raise --max-points, or --max-degree for one Bezier piece)");
    return {};
  }
  std::vector<Point> result;
  result.reserve(value->size());
  for (std::size_t i = 0; i < value->size(); ++i) {
    const auto point = finite_point((*value)[i]);
    if (!point) {
      fail(std::string("'") + field + "'[" + std::to_string(i) + "] must be a pair [x, y] of finite numbers");
      return {};
    }
    result.push_back(*point);
  }
  return result;
}

std::vector<double> SpecReader::numbers(const char* field, std::size_t max_count) {
  const nlohmann::json* value = field_or_fail(field);
  if (!value) return {};
  if (!value->is_array()) {
    fail(std::string("'") + field + "' must be an array of numbers");
    return {};
  }
  if (value->size() > max_count) {
    fail_limit(std::string("'") + field + "' has " + std::to_string(value->size()) + " entries, above the limit of " +
               std::to_string(max_count) + " (raise --max-points, or --max-degree for one Bezier piece)");
    return {};
  }
  std::vector<double> result;
  result.reserve(value->size());
  for (std::size_t i = 0; i < value->size(); ++i) {
    const auto number = finite_number((*value)[i]);
    if (!number) {
      fail(std::string("'") + field + "'[" + std::to_string(i) + "] must be a finite number");
      return {};
    }
    result.push_back(*number);
  }
  return result;
}

double SpecReader::number(const char* field, std::optional<double> fallback) {
  if (failed()) return 0.0;
  if (!has(field) && fallback) return *fallback;
  const nlohmann::json* value = field_or_fail(field);
  if (!value) return 0.0;
  const auto number = finite_number(*value);
  if (!number) {
    fail(std::string("'") + field + "' must be a finite number");
    return 0.0;
  }
  return *number;
}

int SpecReader::integer(const char* field, std::optional<int> fallback) {
  if (failed()) return 0;
  if (!has(field) && fallback) return *fallback;
  const nlohmann::json* value = field_or_fail(field);
  if (!value) return 0;
  if (!value->is_number_integer()) {
    fail(std::string("'") + field + "' must be an integer");
    return 0;
  }
  const auto wide = value->get<long long>();
  if (wide < std::numeric_limits<int>::min() || wide > std::numeric_limits<int>::max()) {
    fail(std::string("'") + field + "' is out of range");
    return 0;
  }
  return static_cast<int>(wide);
}

bool SpecReader::boolean(const char* field, bool fallback) {
  if (failed()) return fallback;
  if (!has(field)) return fallback;
  const nlohmann::json& value = object_.at(field);
  if (!value.is_boolean()) {
    fail(std::string("'") + field + "' must be true or false");
    return fallback;
  }
  return value.get<bool>();
}

std::string SpecReader::string(const char* field, std::optional<std::string> fallback) {
  if (failed()) return {};
  if (!has(field) && fallback) return *fallback;
  const nlohmann::json* value = field_or_fail(field);
  if (!value) return {};
  if (!value->is_string()) {
    fail(std::string("'") + field + "' must be a string");
    return {};
  }
  return value->get<std::string>();
}

Point SpecReader::point(const char* field) {
  const nlohmann::json* value = field_or_fail(field);
  if (!value) return {};
  const auto point = finite_point(*value);
  if (!point) {
    fail(std::string("'") + field + "' must be a pair [x, y] of finite numbers");
    return {};
  }
  return *point;
}

void SpecReader::only(std::initializer_list<const char*> known) {
  if (failed()) return;
  for (const auto& [key, value] : object_.items()) {
    bool found = false;
    for (const char* name : known) found = found || key == name;
    if (!found) {
      std::string list;
      for (const char* name : known) list += (list.empty() ? "" : ", ") + std::string(name);
      fail("unknown field '" + key + "' (this curve type takes: " + list + ")");
      return;
    }
  }
}

}  // namespace curvescan::cli
