// CSS transform functions (css_transform.h).
#include "css_transform.h"

#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "css/syntax.h"
#include "css/tokenizer.h"

namespace curvescan::svg::detail {
namespace {

enum class ArgumentKind { kNumber, kLength, kAngle };

// A length in px (CSS Values 4, 6.2 absolute lengths); nullopt for another unit.
std::optional<double> length_px(const css::Token& token) {
  if (token.type == css::TokenType::kNumber) {
    if (token.number == 0.0) return 0.0;
    return std::nullopt;
  }
  if (token.type != css::TokenType::kDimension) return std::nullopt;
  static constexpr std::array<std::pair<std::string_view, double>, 7> kUnits{{{"px", 1.0},
                                                                              {"in", 96.0},
                                                                              {"cm", 96.0 / 2.54},
                                                                              {"mm", 96.0 / 25.4},
                                                                              {"q", 96.0 / 101.6},
                                                                              {"pt", 96.0 / 72.0},
                                                                              {"pc", 16.0}}};
  const std::string unit = css::ascii_lower(token.value);
  for (const auto& [name, factor] : kUnits) {
    if (name == unit) return token.number * factor;
  }
  return std::nullopt;
}

// An angle in radians (CSS Values 4, 7.1); 0 may omit the unit.
std::optional<double> angle_radians(const css::Token& token) {
  if (token.type == css::TokenType::kNumber) {
    if (token.number == 0.0) return 0.0;
    return std::nullopt;
  }
  if (token.type != css::TokenType::kDimension) return std::nullopt;
  const std::string unit = css::ascii_lower(token.value);
  if (unit == "deg") return token.number * std::numbers::pi / 180.0;
  if (unit == "grad") return token.number * std::numbers::pi / 200.0;
  if (unit == "rad") return token.number;
  if (unit == "turn") return token.number * 2.0 * std::numbers::pi;
  return std::nullopt;
}

std::optional<double> number(const css::Token& token) {
  if (token.type == css::TokenType::kNumber) return token.number;
  if (token.type == css::TokenType::kPercentage) return token.number / 100.0;  // scale(50%) (Transforms 2)
  return std::nullopt;
}

Error error(std::string_view text, const std::string& why) {
  return Error{ErrorKind::kCorruptInput, "transform '" + std::string(text) + "': " + why};
}

}  // namespace

Result<Affine> parse_css_transform(std::string_view text) {
  const css::TokenList list = css::tokenize(text);
  const std::vector<css::Token>& tokens = list.tokens;
  std::size_t at = 0;
  const auto skip_whitespace = [&] {
    while (at < tokens.size() && tokens[at].type == css::TokenType::kWhitespace) ++at;
  };
  skip_whitespace();
  if (at + 1 == tokens.size() && tokens[at].type == css::TokenType::kIdent &&
      css::ascii_lower(tokens[at].value) == "none")
    return Affine::identity();
  Affine result = Affine::identity();
  bool any = false;
  while (at < tokens.size()) {
    if (tokens[at].type != css::TokenType::kFunction) return error(text, "expected a transform function");
    const std::string name = css::ascii_lower(tokens[at].value);
    ++at;
    // The arguments: single tokens separated by commas, up to the ')'.
    std::vector<const css::Token*> arguments;
    bool expect_argument = true;
    for (;;) {
      skip_whitespace();
      if (at >= tokens.size()) return error(text, "missing ')' after " + name + "()");
      const css::Token& token = tokens[at++];
      if (token.type == css::TokenType::kCloseParen) break;
      if (token.type == css::TokenType::kComma && !expect_argument) {
        expect_argument = true;
        continue;
      }
      if (!expect_argument) return error(text, "expected ',' between the arguments of " + name + "()");
      arguments.push_back(&token);
      expect_argument = false;
    }
    if (expect_argument && !arguments.empty()) return error(text, "a trailing ',' in " + name + "()");
    const std::size_t count = arguments.size();
    const auto argument = [&](std::size_t i, ArgumentKind kind) -> std::optional<double> {
      switch (kind) {
        case ArgumentKind::kNumber:
          return number(*arguments[i]);
        case ArgumentKind::kLength:
          return length_px(*arguments[i]);
        case ArgumentKind::kAngle:
          return angle_radians(*arguments[i]);
      }
      return std::nullopt;
    };
    // Reads `count` arguments of `kind` into `values`, or fails naming the function.
    std::array<double, 6> values{};
    const auto read = [&](ArgumentKind kind) {
      for (std::size_t i = 0; i < count; ++i) {
        const std::optional<double> value = argument(i, kind);
        if (!value || !std::isfinite(*value)) return false;
        values[i] = *value;
      }
      return true;
    };
    const auto arity = [&](std::size_t low, std::size_t high) { return count >= low && count <= high; };
    Affine step;
    if (name == "matrix" && count == 6 && read(ArgumentKind::kNumber)) {
      step = Affine{values[0], values[1], values[2], values[3], values[4], values[5]};
    } else if (name == "translate" && arity(1, 2) && read(ArgumentKind::kLength)) {
      step = Affine::translate(values[0], count == 2 ? values[1] : 0.0);
    } else if ((name == "translatex" || name == "translatey") && count == 1 && read(ArgumentKind::kLength)) {
      step = name == "translatex" ? Affine::translate(values[0], 0.0) : Affine::translate(0.0, values[0]);
    } else if (name == "scale" && arity(1, 2) && read(ArgumentKind::kNumber)) {
      step = Affine::scale(values[0], count == 2 ? values[1] : values[0]);
    } else if ((name == "scalex" || name == "scaley") && count == 1 && read(ArgumentKind::kNumber)) {
      step = name == "scalex" ? Affine::scale(values[0], 1.0) : Affine::scale(1.0, values[0]);
    } else if ((name == "rotate" || name == "rotatez") && count == 1 && read(ArgumentKind::kAngle)) {
      step = Affine::rotate(values[0]);
    } else if (name == "skew" && arity(1, 2) && read(ArgumentKind::kAngle)) {
      // skew(ax, ay) = [1 tan(ax); tan(ay) 1] (Transforms 1, 13.1).
      step = Affine{1.0, std::tan(count == 2 ? values[1] : 0.0), std::tan(values[0]), 1.0, 0.0, 0.0};
    } else if ((name == "skewx" || name == "skewy") && count == 1 && read(ArgumentKind::kAngle)) {
      step = name == "skewx" ? Affine::skew_x(values[0]) : Affine::skew_y(values[0]);
    } else {
      return error(text, name + "() with these arguments is not supported");
    }
    result = result * step;  // left to right: the rightmost applies first
    any = true;
    skip_whitespace();
  }
  if (!any) return error(text, "no transform function");
  return result;
}

}  // namespace curvescan::svg::detail
