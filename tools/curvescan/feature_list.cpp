// Parsing of --features (feature_list.h).
#include "feature_list.h"

#include <algorithm>
#include <charconv>

namespace curvescan::cli {
namespace {

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

}  // namespace

Result<std::vector<FontFeature>> parse_feature_list(std::string_view list) {
  std::vector<FontFeature> features;
  if (trimmed(list).empty()) return features;
  while (true) {
    const std::size_t comma = std::min(list.find(','), list.size());
    std::string_view item = trimmed(list.substr(0, comma));
    const std::string quoted = "'" + std::string(item) + "'";
    std::uint32_t value = 1;
    if (item.starts_with('-')) {
      value = 0;
      item.remove_prefix(1);
    } else if (const std::size_t equals = item.find('='); equals != std::string_view::npos) {
      const std::string_view number = trimmed(item.substr(equals + 1));
      const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
      if (number.empty() || error != std::errc() || end != number.data() + number.size() || value > 65535) {
        return Error{ErrorKind::kInvalidArgument,
                     "feature " + quoted + ": the value after '=' must be a whole number from 0 to 65535"};
      }
      item = trimmed(item.substr(0, equals));
    }
    // OpenType feature tags are four printable ASCII characters (OpenType spec, "Tag" data type).
    if (item.size() != 4 || !std::all_of(item.begin(), item.end(), [](char c) { return c >= 0x21 && c <= 0x7e; })) {
      return Error{ErrorKind::kInvalidArgument,
                   "feature " + quoted + ": a feature is a four-letter OpenType tag such as smcp, -liga or salt=2"};
    }
    features.push_back({font_feature_tag(item), value});
    if (comma == list.size()) break;
    list.remove_prefix(comma + 1);
  }
  return features;
}

}  // namespace curvescan::cli
