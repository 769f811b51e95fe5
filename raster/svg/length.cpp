// SVG lengths (length.h): unit table and conversion, SVG 1.1 section 7.10.
#include "curvescan/svg/length.h"

#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "curvescan/svg/number.h"

namespace curvescan::svg {
namespace {

constexpr std::array<std::pair<std::string_view, LengthUnit>, 9> kUnits{{
    {"px", LengthUnit::kPx},
    {"pt", LengthUnit::kPt},
    {"pc", LengthUnit::kPc},
    {"mm", LengthUnit::kMm},
    {"cm", LengthUnit::kCm},
    {"in", LengthUnit::kIn},
    {"em", LengthUnit::kEm},
    {"ex", LengthUnit::kEx},
    {"%", LengthUnit::kPercent},
}};

}  // namespace

Result<Length> parse_length(std::string_view text) {
  std::string_view rest = trim_whitespace(text);
  const std::optional<double> value = consume_number(rest);
  if (!value) return Error{ErrorKind::kInvalidArgument, "'" + std::string(text) + "' is not a length"};
  if (rest.empty()) return Length{*value, LengthUnit::kNone};
  for (const auto& [name, unit] : kUnits) {
    if (rest == name) return Length{*value, unit};
  }
  return Error{ErrorKind::kInvalidArgument,
               "unknown unit '" + std::string(rest) + "' in length '" + std::string(text) + "'"};
}

double Resolution::diagonal() const noexcept {
  return std::sqrt((x * x + y * y) / 2.0);
}

double length_to_pixels(Length length, const LengthContext& context) noexcept {
  switch (length.unit) {
    case LengthUnit::kNone:
    case LengthUnit::kPx:
      return length.value;
    case LengthUnit::kPt:
      return length.value * context.dpi / 72.0;
    case LengthUnit::kPc:
      return length.value * context.dpi / 6.0;
    case LengthUnit::kMm:
      return length.value * context.dpi / 25.4;
    case LengthUnit::kCm:
      return length.value * context.dpi / 2.54;
    case LengthUnit::kIn:
      return length.value * context.dpi;
    case LengthUnit::kEm:
      return length.value * context.font_size;
    case LengthUnit::kEx:
      return length.value * context.font_size * 0.5;
    case LengthUnit::kPercent:
      return length.value * context.percent_reference / 100.0;
  }
  return length.value;
}

}  // namespace curvescan::svg
