// CSS colour parsing (color.h). The named-colour table is CSS Color Module Level 3 section 4.3
// ("Extended color keywords", the SVG 1.1 colour names) plus Level 4's "rebeccapurple".
#include "curvescan/svg/color.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "curvescan/svg/number.h"

namespace curvescan::svg {
namespace {

struct NamedColor {
  std::string_view name;
  std::uint32_t rgb;  // 0xRRGGBB
};

// Sorted by name for binary search.
constexpr auto kNamedColors = std::to_array<NamedColor>({
    {"aliceblue", 0xF0F8FF},
    {"antiquewhite", 0xFAEBD7},
    {"aqua", 0x00FFFF},
    {"aquamarine", 0x7FFFD4},
    {"azure", 0xF0FFFF},
    {"beige", 0xF5F5DC},
    {"bisque", 0xFFE4C4},
    {"black", 0x000000},
    {"blanchedalmond", 0xFFEBCD},
    {"blue", 0x0000FF},
    {"blueviolet", 0x8A2BE2},
    {"brown", 0xA52A2A},
    {"burlywood", 0xDEB887},
    {"cadetblue", 0x5F9EA0},
    {"chartreuse", 0x7FFF00},
    {"chocolate", 0xD2691E},
    {"coral", 0xFF7F50},
    {"cornflowerblue", 0x6495ED},
    {"cornsilk", 0xFFF8DC},
    {"crimson", 0xDC143C},
    {"cyan", 0x00FFFF},
    {"darkblue", 0x00008B},
    {"darkcyan", 0x008B8B},
    {"darkgoldenrod", 0xB8860B},
    {"darkgray", 0xA9A9A9},
    {"darkgreen", 0x006400},
    {"darkgrey", 0xA9A9A9},
    {"darkkhaki", 0xBDB76B},
    {"darkmagenta", 0x8B008B},
    {"darkolivegreen", 0x556B2F},
    {"darkorange", 0xFF8C00},
    {"darkorchid", 0x9932CC},
    {"darkred", 0x8B0000},
    {"darksalmon", 0xE9967A},
    {"darkseagreen", 0x8FBC8F},
    {"darkslateblue", 0x483D8B},
    {"darkslategray", 0x2F4F4F},
    {"darkslategrey", 0x2F4F4F},
    {"darkturquoise", 0x00CED1},
    {"darkviolet", 0x9400D3},
    {"deeppink", 0xFF1493},
    {"deepskyblue", 0x00BFFF},
    {"dimgray", 0x696969},
    {"dimgrey", 0x696969},
    {"dodgerblue", 0x1E90FF},
    {"firebrick", 0xB22222},
    {"floralwhite", 0xFFFAF0},
    {"forestgreen", 0x228B22},
    {"fuchsia", 0xFF00FF},
    {"gainsboro", 0xDCDCDC},
    {"ghostwhite", 0xF8F8FF},
    {"gold", 0xFFD700},
    {"goldenrod", 0xDAA520},
    {"gray", 0x808080},
    {"green", 0x008000},
    {"greenyellow", 0xADFF2F},
    {"grey", 0x808080},
    {"honeydew", 0xF0FFF0},
    {"hotpink", 0xFF69B4},
    {"indianred", 0xCD5C5C},
    {"indigo", 0x4B0082},
    {"ivory", 0xFFFFF0},
    {"khaki", 0xF0E68C},
    {"lavender", 0xE6E6FA},
    {"lavenderblush", 0xFFF0F5},
    {"lawngreen", 0x7CFC00},
    {"lemonchiffon", 0xFFFACD},
    {"lightblue", 0xADD8E6},
    {"lightcoral", 0xF08080},
    {"lightcyan", 0xE0FFFF},
    {"lightgoldenrodyellow", 0xFAFAD2},
    {"lightgray", 0xD3D3D3},
    {"lightgreen", 0x90EE90},
    {"lightgrey", 0xD3D3D3},
    {"lightpink", 0xFFB6C1},
    {"lightsalmon", 0xFFA07A},
    {"lightseagreen", 0x20B2AA},
    {"lightskyblue", 0x87CEFA},
    {"lightslategray", 0x778899},
    {"lightslategrey", 0x778899},
    {"lightsteelblue", 0xB0C4DE},
    {"lightyellow", 0xFFFFE0},
    {"lime", 0x00FF00},
    {"limegreen", 0x32CD32},
    {"linen", 0xFAF0E6},
    {"magenta", 0xFF00FF},
    {"maroon", 0x800000},
    {"mediumaquamarine", 0x66CDAA},
    {"mediumblue", 0x0000CD},
    {"mediumorchid", 0xBA55D3},
    {"mediumpurple", 0x9370DB},
    {"mediumseagreen", 0x3CB371},
    {"mediumslateblue", 0x7B68EE},
    {"mediumspringgreen", 0x00FA9A},
    {"mediumturquoise", 0x48D1CC},
    {"mediumvioletred", 0xC71585},
    {"midnightblue", 0x191970},
    {"mintcream", 0xF5FFFA},
    {"mistyrose", 0xFFE4E1},
    {"moccasin", 0xFFE4B5},
    {"navajowhite", 0xFFDEAD},
    {"navy", 0x000080},
    {"oldlace", 0xFDF5E6},
    {"olive", 0x808000},
    {"olivedrab", 0x6B8E23},
    {"orange", 0xFFA500},
    {"orangered", 0xFF4500},
    {"orchid", 0xDA70D6},
    {"palegoldenrod", 0xEEE8AA},
    {"palegreen", 0x98FB98},
    {"paleturquoise", 0xAFEEEE},
    {"palevioletred", 0xDB7093},
    {"papayawhip", 0xFFEFD5},
    {"peachpuff", 0xFFDAB9},
    {"peru", 0xCD853F},
    {"pink", 0xFFC0CB},
    {"plum", 0xDDA0DD},
    {"powderblue", 0xB0E0E6},
    {"purple", 0x800080},
    {"rebeccapurple", 0x663399},
    {"red", 0xFF0000},
    {"rosybrown", 0xBC8F8F},
    {"royalblue", 0x4169E1},
    {"saddlebrown", 0x8B4513},
    {"salmon", 0xFA8072},
    {"sandybrown", 0xF4A460},
    {"seagreen", 0x2E8B57},
    {"seashell", 0xFFF5EE},
    {"sienna", 0xA0522D},
    {"silver", 0xC0C0C0},
    {"skyblue", 0x87CEEB},
    {"slateblue", 0x6A5ACD},
    {"slategray", 0x708090},
    {"slategrey", 0x708090},
    {"snow", 0xFFFAFA},
    {"springgreen", 0x00FF7F},
    {"steelblue", 0x4682B4},
    {"tan", 0xD2B48C},
    {"teal", 0x008080},
    {"thistle", 0xD8BFD8},
    {"tomato", 0xFF6347},
    {"turquoise", 0x40E0D0},
    {"violet", 0xEE82EE},
    {"wheat", 0xF5DEB3},
    {"white", 0xFFFFFF},
    {"whitesmoke", 0xF5F5F5},
    {"yellow", 0xFFFF00},
    {"yellowgreen", 0x9ACD32},
});
static_assert(kNamedColors.size() == 148, "CSS Color 3's 147 names plus rebeccapurple");
static_assert(std::is_sorted(kNamedColors.begin(), kNamedColors.end(),
                             [](const NamedColor& x, const NamedColor& y) { return x.name < y.name; }),
              "binary search needs the table sorted by name");

Error bad_color(std::string_view text) {
  return Error{ErrorKind::kInvalidArgument, "'" + std::string(text) + "' is not a CSS colour"};
}

std::string ascii_lower(std::string_view text) {
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; });
  return lower;
}

std::optional<int> hex_digit(char c) noexcept {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return std::nullopt;
}

std::optional<Color> parse_hex(std::string_view digits_text) {
  std::vector<int> digits;
  for (char c : digits_text) {
    const std::optional<int> digit = hex_digit(c);
    if (!digit) return std::nullopt;
    digits.push_back(*digit);
  }
  std::array<int, 4> channels{0, 0, 0, 255};
  if (digits.size() == 3 || digits.size() == 4) {  // #rgb(a): each digit doubled, 0xF -> 0xFF
    for (std::size_t i = 0; i < digits.size(); ++i) channels[i] = digits[i] * 17;
  } else if (digits.size() == 6 || digits.size() == 8) {
    for (std::size_t i = 0; i < digits.size() / 2; ++i) channels[i] = digits[2 * i] * 16 + digits[2 * i + 1];
  } else {
    return std::nullopt;
  }
  return Color{channels[0] / 255.0, channels[1] / 255.0, channels[2] / 255.0, channels[3] / 255.0};
}

struct FunctionArgument {
  double value = 0.0;
  bool percent = false;
};

// The comma- or space-separated arguments between the parentheses of "name(...)".
std::optional<std::vector<FunctionArgument>> function_arguments(std::string_view inside) {
  std::vector<FunctionArgument> arguments;
  skip_whitespace(inside);
  while (!inside.empty()) {
    const std::optional<double> value = consume_number(inside);
    if (!value) return std::nullopt;
    FunctionArgument argument{*value, false};
    if (!inside.empty() && inside.front() == '%') {
      argument.percent = true;
      inside.remove_prefix(1);
    } else if (inside.substr(0, 3) == "deg") {  // hsl() hue may carry "deg" (CSS Color 4)
      inside.remove_prefix(3);
    }
    arguments.push_back(argument);
    skip_whitespace(inside);
    if (!inside.empty() && (inside.front() == ',' || inside.front() == '/')) {
      inside.remove_prefix(1);
      skip_whitespace(inside);
      if (inside.empty()) return std::nullopt;
    }
  }
  return arguments;
}

double clamp01(double value) noexcept {
  return std::clamp(value, 0.0, 1.0);
}

// An rgb() channel: an integer 0..255 or a percentage.
double rgb_channel(const FunctionArgument& argument) noexcept {
  return clamp01(argument.percent ? argument.value / 100.0 : argument.value / 255.0);
}

// An alpha: a number 0..1 or a percentage.
double alpha_channel(const FunctionArgument& argument) noexcept {
  return clamp01(argument.percent ? argument.value / 100.0 : argument.value);
}

// CSS Color 3 section 4.2.4, the HSL-to-RGB algorithm given there.
double hue_to_rgb(double m1, double m2, double h) noexcept {
  if (h < 0.0) h += 1.0;
  if (h > 1.0) h -= 1.0;
  if (h * 6.0 < 1.0) return m1 + (m2 - m1) * h * 6.0;
  if (h * 2.0 < 1.0) return m2;
  if (h * 3.0 < 2.0) return m1 + (m2 - m1) * (2.0 / 3.0 - h) * 6.0;
  return m1;
}

Color hsl_to_rgb(double hue_degrees, double saturation, double lightness, double alpha) noexcept {
  const double h = (hue_degrees - 360.0 * std::floor(hue_degrees / 360.0)) / 360.0;
  const double m2 =
      lightness <= 0.5 ? lightness * (saturation + 1.0) : lightness + saturation - lightness * saturation;
  const double m1 = lightness * 2.0 - m2;
  return {hue_to_rgb(m1, m2, h + 1.0 / 3.0), hue_to_rgb(m1, m2, h), hue_to_rgb(m1, m2, h - 1.0 / 3.0), alpha};
}

std::optional<Color> parse_function(std::string_view name, std::string_view inside) {
  const std::optional<std::vector<FunctionArgument>> arguments = function_arguments(inside);
  if (!arguments || (arguments->size() != 3 && arguments->size() != 4)) return std::nullopt;
  const std::vector<FunctionArgument>& args = *arguments;
  const double alpha = args.size() == 4 ? alpha_channel(args[3]) : 1.0;
  if (name == "rgb" || name == "rgba") {
    // CSS: the three channels are all integers or all percentages.
    if (args[0].percent != args[1].percent || args[1].percent != args[2].percent) return std::nullopt;
    return Color{rgb_channel(args[0]), rgb_channel(args[1]), rgb_channel(args[2]), alpha};
  }
  if (name == "hsl" || name == "hsla") {
    if (args[0].percent || !args[1].percent || !args[2].percent) return std::nullopt;
    return hsl_to_rgb(args[0].value, clamp01(args[1].value / 100.0), clamp01(args[2].value / 100.0), alpha);
  }
  return std::nullopt;
}

}  // namespace

Result<Color> parse_color(std::string_view text) {
  const std::string_view trimmed = trim_whitespace(text);
  if (trimmed.empty()) return bad_color(text);
  if (trimmed.front() == '#') {
    const std::optional<Color> color = parse_hex(trimmed.substr(1));
    if (!color) return bad_color(text);
    return *color;
  }
  const std::string lower = ascii_lower(trimmed);
  if (lower == "transparent") return Color{0.0, 0.0, 0.0, 0.0};
  if (const std::size_t open = lower.find('('); open != std::string::npos) {
    if (lower.back() != ')') return bad_color(text);
    const std::string_view view(lower);
    const std::optional<Color> color =
        parse_function(trim_whitespace(view.substr(0, open)), view.substr(open + 1, view.size() - open - 2));
    if (!color) return bad_color(text);
    return *color;
  }
  const auto found =
      std::lower_bound(kNamedColors.begin(), kNamedColors.end(), lower,
                       [](const NamedColor& entry, const std::string& key) { return entry.name < key; });
  if (found == kNamedColors.end() || found->name != lower) return bad_color(text);
  return Color{((found->rgb >> 16) & 0xFF) / 255.0, ((found->rgb >> 8) & 0xFF) / 255.0,
               (found->rgb & 0xFF) / 255.0, 1.0};
}

}  // namespace curvescan::svg
