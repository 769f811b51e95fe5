// The parsers of command-line text (command_line_text.h).
#include "command_line_text.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string_view>
#include <utility>

#include "curvescan/svg/length.h"

namespace curvescan::cli {

Result<double> command_line_length(const std::string& flag, const std::string& text, double dpi) {
  const Result<svg::Length> length = svg::parse_length(text);
  const auto refuse = [&](const std::string& why) {
    return Error{ErrorKind::kInvalidArgument, flag + ": invalid value '" + text + "': " + why};
  };
  if (!length) return refuse("not a number with a unit");
  switch (length->unit) {
    case svg::LengthUnit::kPercent:
    case svg::LengthUnit::kEm:
    case svg::LengthUnit::kEx:
      return refuse("supported units are px, in, cm, mm, pt, pc");
    default:
      break;
  }
  const double pixels = svg::length_to_pixels(*length, svg::LengthContext{dpi, 16.0, 0.0});
  if (!std::isfinite(pixels)) return refuse("not a finite length");
  return pixels;
}

Result<std::vector<std::string>> parse_accept_language(const std::string& text) {
  std::vector<std::pair<double, std::string>> weighted;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    std::string item = text.substr(start, comma - start);
    start = comma + 1;
    double weight = 1.0;
    if (const std::size_t semicolon = item.find(';'); semicolon != std::string::npos) {
      std::string parameter = item.substr(semicolon + 1);
      item.erase(semicolon);
      parameter.erase(0, parameter.find_first_not_of(" \t"));
      char* end = nullptr;
      if (parameter.rfind("q=", 0) == 0) weight = std::strtod(parameter.c_str() + 2, &end);
      if (end == nullptr || *end != '\0' || !(weight >= 0.0 && weight <= 1.0)) {
        return Error{ErrorKind::kInvalidArgument, "--accept-language: '" + text + "' has a bad weight"};
      }
    }
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    const bool tag = !item.empty() && std::all_of(item.begin(), item.end(), [](unsigned char c) {
      return std::isalnum(c) || c == '-' || c == '*';
    });
    if (!tag)
      return Error{ErrorKind::kInvalidArgument,
                   "--accept-language: '" + text + "' is not a list of language tags"};
    if (weight > 0.0) weighted.emplace_back(weight, item);
  }
  std::stable_sort(weighted.begin(), weighted.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::string> tags;
  for (auto& [weight, tag] : weighted) tags.push_back(std::move(tag));
  return tags;
}

namespace {

// One integer of "x,y,w,h": blanks around it and a leading '+' allowed (as scanf's %d reads them), but
// nothing else, and a value that does not fit in an int is refused instead of overflowing.
std::optional<int> parse_region_field(std::string_view field) {
  field.remove_prefix(std::min(field.find_first_not_of(" \t"), field.size()));
  field.remove_suffix(field.size() - std::min(field.find_last_not_of(" \t") + 1, field.size()));
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  int value = 0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || error != std::errc{} || end != field.data() + field.size()) return std::nullopt;
  return value;
}

}  // namespace

Result<PixelBox> parse_ignore_region(const std::string& text) {
  std::array<int, 4> values{};
  std::size_t start = 0;
  bool ok = true;
  for (std::size_t i = 0; i < values.size() && ok; ++i) {
    const std::size_t comma = i + 1 < values.size() ? text.find(',', start) : text.size();
    if (comma == std::string::npos) {
      ok = false;
      break;
    }
    const std::optional<int> value = parse_region_field(std::string_view(text).substr(start, comma - start));
    ok = value.has_value();
    if (ok) values[i] = *value;
    start = comma + 1;
  }
  const PixelBox box{values[0], values[1], values[2], values[3]};
  if (!ok || box.width < 0 || box.height < 0) {
    return Error{ErrorKind::kInvalidArgument,
                 "'" + text + "' must be x,y,w,h: four integers, the width and height >= 0"};
  }
  return box;
}

std::vector<std::string> parse_name_list(std::string_view text) {
  std::vector<std::string> names;
  std::istringstream lines{std::string(text)};
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!line.empty()) names.push_back(line);
  }
  return names;
}

}  // namespace curvescan::cli
