// SpecReader: typed, validated access to the fields of one JSON object, with error messages that name
// the field ("'weights'[2] must be a finite number > 0"). Shared by every JSON input of the CLI.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "curvescan/curves/point.h"
#include "curvescan/status.h"

namespace curvescan::cli {

class SpecReader {
 public:
  explicit SpecReader(const nlohmann::json& object) : object_(object) {}

  [[nodiscard]] bool has(const char* field) const { return object_.contains(field); }
  /// Fails on the first field error and keeps it; later calls return defaults until error() is read.
  std::vector<Point> points(const char* field, std::size_t max_count);
  std::vector<double> numbers(const char* field, std::size_t max_count);
  double number(const char* field, std::optional<double> fallback = std::nullopt);
  int integer(const char* field, std::optional<int> fallback = std::nullopt);
  bool boolean(const char* field, bool fallback);
  std::string string(const char* field, std::optional<std::string> fallback = std::nullopt);
  Point point(const char* field);
  /// Rejects fields not in `known` (a typo such as "weigths" must not be silently ignored).
  void only(std::initializer_list<const char*> known);

  [[nodiscard]] bool failed() const { return error_.has_value(); }
  [[nodiscard]] Error error() const { return *error_; }

 private:
  void fail(std::string message);
  /// As fail(), for a limit exceeded (kLimitExceeded; the message names the flag that raises it).
  void fail_limit(std::string message);
  const nlohmann::json* field_or_fail(const char* field);
  const nlohmann::json& object_;
  std::optional<Error> error_;
};

}  // namespace curvescan::cli
