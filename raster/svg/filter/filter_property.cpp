// The `filter` property (filter_property.h).
#include "filter_property.h"

#include <array>
#include <cctype>
#include <cmath>
#include <numbers>

#include "computed_style.h"
#include "css/syntax.h"
#include "curvescan/svg/length.h"
#include "curvescan/svg/number.h"

namespace curvescan::svg::detail::filter {
namespace {

using Kind = FilterFunction::Kind;

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Splits the arguments of a function at top-level whitespace (a colour such as rgb(1, 2, 3) stays one
// argument). No filter function takes a comma-separated list (Filter Effects 1, 13): a top-level comma
// makes the value invalid, as browsers parse it.
std::optional<std::vector<std::string_view>> split_arguments(std::string_view text) {
  std::vector<std::string_view> parts;
  int depth = 0;
  std::size_t start = std::string_view::npos;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    const char c = i < text.size() ? text[i] : ' ';
    if (depth == 0 && c == ',') return std::nullopt;
    const bool separator = depth == 0 && is_svg_whitespace(c);
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (separator) {
      if (start != std::string_view::npos) parts.push_back(text.substr(start, i - start));
      start = std::string_view::npos;
    } else if (start == std::string_view::npos) {
      start = i;
    }
  }
  return parts;
}

// A non-negative number or percentage.
std::optional<double> amount(std::string_view text) {
  const bool percent = !text.empty() && text.back() == '%';
  const std::optional<double> value = parse_number(percent ? text.substr(0, text.size() - 1) : text);
  if (!value || !(*value >= 0.0) || !std::isfinite(*value)) return std::nullopt;
  return percent ? *value / 100.0 : *value;
}

// A length (no percentages: the filter functions do not take them) as user units plus font sizes. A plain
// number is px (the header says why).
struct SplitLength {
  double px = 0.0, em = 0.0;
};
std::optional<SplitLength> css_length(std::string_view text) {
  const Result<Length> length = parse_length(text);
  if (!length || length->unit == LengthUnit::kPercent) return std::nullopt;
  // length_to_pixels is linear in the font size: its value at 0 is the px part, the growth per unit the em.
  const double at_zero = length_to_pixels(*length, LengthContext{96.0, 0.0, 0.0});
  const double per_em = length_to_pixels(*length, LengthContext{96.0, 1.0, 0.0}) - at_zero;
  if (!std::isfinite(at_zero) || !std::isfinite(per_em)) return std::nullopt;
  return SplitLength{at_zero, per_em};
}

// A CSS angle in degrees; 0 may omit the unit.
std::optional<double> angle(std::string_view text) {
  static constexpr std::array<std::pair<std::string_view, double>, 4> kUnits{
      {{"deg", 1.0}, {"grad", 0.9}, {"rad", 180.0 / std::numbers::pi}, {"turn", 360.0}}};
  const std::string folded = lower(text);
  for (const auto& [unit, factor] : kUnits) {
    if (folded.size() > unit.size() && folded.ends_with(unit)) {
      const std::optional<double> value =
          parse_number(std::string_view(folded).substr(0, folded.size() - unit.size()));
      if (!value || !std::isfinite(*value)) return std::nullopt;
      return *value * factor;
    }
  }
  const std::optional<double> value = parse_number(text);
  if (value && *value == 0.0) return 0.0;
  return std::nullopt;
}

std::optional<FilterFunction> parse_function(std::string_view name, std::string_view body) {
  const std::optional<std::vector<std::string_view>> split = split_arguments(body);
  if (!split) return std::nullopt;
  const std::vector<std::string_view>& args = *split;
  FilterFunction f;
  const std::string folded = lower(name);
  const auto one_amount = [&](Kind kind, double fallback,
                              bool clamp_to_one) -> std::optional<FilterFunction> {
    if (args.size() > 1) return std::nullopt;
    f.kind = kind;
    f.amount = fallback;
    if (args.size() == 1) {
      const std::optional<double> value = amount(args[0]);
      if (!value) return std::nullopt;
      f.amount = clamp_to_one ? std::min(*value, 1.0) : *value;
    }
    return f;
  };
  if (folded == "blur") {
    if (args.size() > 1) return std::nullopt;
    f.kind = Kind::kBlur;
    if (args.size() == 1) {
      const std::optional<SplitLength> sigma = css_length(args[0]);
      if (!sigma || sigma->px < 0.0 || sigma->em < 0.0) return std::nullopt;
      f.amount = sigma->px;
      f.amount_em = sigma->em;
    }
    return f;
  }
  if (folded == "drop-shadow") {
    f.kind = Kind::kDropShadow;
    // <color>? && <length>{2,3}: the colour before or after the lengths, never between them.
    std::vector<SplitLength> lengths;
    bool colour_seen = false, colour_after_length = false;
    for (const std::string_view arg : args) {
      if (const std::optional<SplitLength> length = css_length(arg)) {
        if (colour_after_length) return std::nullopt;  // colour between lengths
        lengths.push_back(*length);
        continue;
      }
      if (colour_seen) return std::nullopt;
      colour_seen = true;
      colour_after_length = !lengths.empty();
      const Result<Color> color = parse_color(arg);
      if (!color) {
        if (lower(arg) != "currentcolor") return std::nullopt;
        continue;
      }
      f.color = *color;
    }
    if (lengths.size() < 2 || lengths.size() > 3) return std::nullopt;
    f.dx = lengths[0].px;
    f.dx_em = lengths[0].em;
    f.dy = lengths[1].px;
    f.dy_em = lengths[1].em;
    if (lengths.size() == 3) {
      if (lengths[2].px < 0.0 || lengths[2].em < 0.0) return std::nullopt;
      f.amount = lengths[2].px;
      f.amount_em = lengths[2].em;
    }
    return f;
  }
  if (folded == "hue-rotate") {
    if (args.size() > 1) return std::nullopt;
    f.kind = Kind::kHueRotate;
    if (args.size() == 1) {
      const std::optional<double> degrees = angle(args[0]);
      if (!degrees) return std::nullopt;
      f.amount = *degrees;
    }
    return f;
  }
  if (folded == "brightness") return one_amount(Kind::kBrightness, 1.0, false);
  if (folded == "contrast") return one_amount(Kind::kContrast, 1.0, false);
  if (folded == "grayscale") return one_amount(Kind::kGrayscale, 1.0, true);
  if (folded == "invert") return one_amount(Kind::kInvert, 1.0, true);
  if (folded == "opacity") return one_amount(Kind::kOpacity, 1.0, true);
  if (folded == "saturate") return one_amount(Kind::kSaturate, 1.0, false);
  if (folded == "sepia") return one_amount(Kind::kSepia, 1.0, true);
  return std::nullopt;
}

}  // namespace

std::optional<std::vector<FilterFunction>> parse_filter_property(std::string_view text) {
  text = trim_whitespace(text);
  std::vector<FilterFunction> list;
  if (css::ascii_equal_ignoring_case(text, "none")) return list;
  while (!text.empty()) {
    const std::size_t open = text.find('(');
    if (open == std::string_view::npos || open == 0) return std::nullopt;
    // The matching parenthesis (a colour argument may nest one level).
    int depth = 0;
    std::size_t close = std::string_view::npos;
    for (std::size_t i = open; i < text.size(); ++i) {
      if (text[i] == '(') ++depth;
      if (text[i] == ')' && --depth == 0) {
        close = i;
        break;
      }
    }
    if (close == std::string_view::npos) return std::nullopt;
    const std::string_view name = trim_whitespace(text.substr(0, open));
    if (lower(name) == "url") {
      const std::optional<std::string> id = parse_url_reference(text.substr(0, close + 1));
      if (!id) return std::nullopt;
      FilterFunction f;
      f.url_id = *id;
      list.push_back(std::move(f));
    } else {
      std::optional<FilterFunction> f = parse_function(name, text.substr(open + 1, close - open - 1));
      if (!f) return std::nullopt;
      list.push_back(std::move(*f));
    }
    text = trim_whitespace(text.substr(close + 1));
  }
  if (list.empty()) return std::nullopt;
  return list;
}

}  // namespace curvescan::svg::detail::filter
