// CSS transform functions (css_transform.h).
#include "css_transform.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "css/syntax.h"
#include "css/tokenizer.h"

namespace curvescan::svg::detail {
namespace {

enum class ArgumentKind { kNumber, kLengthX, kLengthY, kLengthZ, kAngle };

// A length in px (CSS Values 4, 6.2 absolute lengths; em and ex of the font size); a percentage of
// `percent_of` (nullopt: none allowed, as for z); nullopt for another unit.
std::optional<double> length_px(const css::Token& token, const CssTransformContext& context,
                                std::optional<double> percent_of) {
  if (token.type == css::TokenType::kNumber) {
    if (token.number == 0.0) return 0.0;
    return std::nullopt;
  }
  if (token.type == css::TokenType::kPercentage) {
    if (!percent_of) return std::nullopt;
    return token.number / 100.0 * *percent_of;
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
  if (unit == "em") return token.number * context.font_size;
  if (unit == "ex") return token.number * context.font_size * 0.5;
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

// A 4 x 4 matrix in CSS's notation: m[i][j] is m(i+1)(j+1) of CSS Transforms 2, 12, column i, row j, so
// that a point (x, y, z, 1) maps to sum over i of column i times its coordinate.
struct Matrix4 {
  std::array<std::array<double, 4>, 4> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};

  /// this x other: `other` applies first.
  Matrix4 operator*(const Matrix4& other) const {
    Matrix4 product;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        double sum = 0.0;
        for (int k = 0; k < 4; ++k) sum += m[k][j] * other.m[i][k];
        product.m[i][j] = sum;
      }
    return product;
  }

  static Matrix4 from_affine(const Affine& a) {
    Matrix4 r;
    r.m[0][0] = a.a;
    r.m[0][1] = a.b;
    r.m[1][0] = a.c;
    r.m[1][1] = a.d;
    r.m[3][0] = a.e;
    r.m[3][1] = a.f;
    return r;
  }

  static Matrix4 translate(double x, double y, double z) {
    Matrix4 r;
    r.m[3] = {x, y, z, 1.0};
    return r;
  }

  static Matrix4 scale(double x, double y, double z) {
    Matrix4 r;
    r.m[0][0] = x;
    r.m[1][1] = y;
    r.m[2][2] = z;
    return r;
  }

  // rotate3d(x, y, z, a) (CSS Transforms 2, 12.1); nullopt for the zero vector (the function is invalid).
  static std::optional<Matrix4> rotate(double x, double y, double z, double angle) {
    const double length = std::sqrt(x * x + y * y + z * z);
    if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
    x /= length;
    y /= length;
    z /= length;
    const double sc = std::sin(angle / 2.0) * std::cos(angle / 2.0);
    const double sq = std::sin(angle / 2.0) * std::sin(angle / 2.0);
    Matrix4 r;
    r.m[0] = {1.0 - 2.0 * (y * y + z * z) * sq, 2.0 * (x * y * sq + z * sc), 2.0 * (x * z * sq - y * sc),
              0.0};
    r.m[1] = {2.0 * (x * y * sq - z * sc), 1.0 - 2.0 * (x * x + z * z) * sq, 2.0 * (y * z * sq + x * sc),
              0.0};
    r.m[2] = {2.0 * (x * z * sq + y * sc), 2.0 * (y * z * sq - x * sc), 1.0 - 2.0 * (x * x + y * y) * sq,
              0.0};
    return r;
  }

  // perspective(d) (CSS Transforms 2, 12.1): m34 = -1/d, with d clamped to at least 1 px as that section
  // says for the function.
  static Matrix4 perspective(double distance) {
    Matrix4 r;
    r.m[2][3] = -1.0 / std::max(distance, 1.0);
    return r;
  }
};

}  // namespace

Result<Affine> parse_css_transform(std::string_view text, const CssTransformContext& context) {
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
  Matrix4 result;
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
        case ArgumentKind::kLengthX:
          return length_px(*arguments[i], context, context.reference_width);
        case ArgumentKind::kLengthY:
          return length_px(*arguments[i], context, context.reference_height);
        case ArgumentKind::kLengthZ:
          return length_px(*arguments[i], context, std::nullopt);
        case ArgumentKind::kAngle:
          return angle_radians(*arguments[i]);
      }
      return std::nullopt;
    };
    // Reads the arguments, the i-th of kinds[i] (the last kind repeats), into `values`, or fails.
    std::array<double, 16> values{};
    const auto read = [&](std::initializer_list<ArgumentKind> kinds) {
      for (std::size_t i = 0; i < count; ++i) {
        const ArgumentKind kind = *(kinds.begin() + std::min(i, kinds.size() - 1));
        const std::optional<double> value = argument(i, kind);
        if (!value || !std::isfinite(*value)) return false;
        values[i] = *value;
      }
      return true;
    };
    using K = ArgumentKind;
    const auto arity = [&](std::size_t low, std::size_t high) { return count >= low && count <= high; };
    std::optional<Matrix4> step;
    if (name == "matrix" && count == 6 && read({K::kNumber})) {
      step = Matrix4::from_affine(Affine{values[0], values[1], values[2], values[3], values[4], values[5]});
    } else if (name == "matrix3d" && count == 16 && read({K::kNumber})) {
      step = Matrix4{};
      for (int i = 0; i < 16; ++i) step->m[i / 4][i % 4] = values[i];  // column by column (12.1)
    } else if (name == "translate" && arity(1, 2) && read({K::kLengthX, K::kLengthY})) {
      step = Matrix4::translate(values[0], count == 2 ? values[1] : 0.0, 0.0);
    } else if (name == "translate3d" && count == 3 && read({K::kLengthX, K::kLengthY, K::kLengthZ})) {
      step = Matrix4::translate(values[0], values[1], values[2]);
    } else if (name == "translatex" && count == 1 && read({K::kLengthX})) {
      step = Matrix4::translate(values[0], 0.0, 0.0);
    } else if (name == "translatey" && count == 1 && read({K::kLengthY})) {
      step = Matrix4::translate(0.0, values[0], 0.0);
    } else if (name == "translatez" && count == 1 && read({K::kLengthZ})) {
      step = Matrix4::translate(0.0, 0.0, values[0]);
    } else if (name == "scale" && arity(1, 2) && read({K::kNumber})) {
      step = Matrix4::scale(values[0], count == 2 ? values[1] : values[0], 1.0);
    } else if (name == "scale3d" && count == 3 && read({K::kNumber})) {
      step = Matrix4::scale(values[0], values[1], values[2]);
    } else if ((name == "scalex" || name == "scaley" || name == "scalez") && count == 1 &&
               read({K::kNumber})) {
      step = Matrix4::scale(name == "scalex" ? values[0] : 1.0, name == "scaley" ? values[0] : 1.0,
                            name == "scalez" ? values[0] : 1.0);
    } else if ((name == "rotate" || name == "rotatez") && count == 1 && read({K::kAngle})) {
      step = Matrix4::from_affine(Affine::rotate(values[0]));
    } else if ((name == "rotatex" || name == "rotatey") && count == 1 && read({K::kAngle})) {
      step = Matrix4::rotate(name == "rotatex" ? 1.0 : 0.0, name == "rotatey" ? 1.0 : 0.0, 0.0, values[0]);
    } else if (name == "rotate3d" && count == 4 && read({K::kNumber, K::kNumber, K::kNumber, K::kAngle})) {
      step = Matrix4::rotate(values[0], values[1], values[2], values[3]);
      if (!step) return error(text, "rotate3d() about the zero vector");
    } else if (name == "perspective" && count == 1 && read({K::kLengthZ})) {
      step = Matrix4::perspective(values[0]);
    } else if (name == "skew" && arity(1, 2) && read({K::kAngle})) {
      // skew(ax, ay) = [1 tan(ax); tan(ay) 1] (Transforms 1, 13.1).
      step = Matrix4::from_affine(
          Affine{1.0, std::tan(count == 2 ? values[1] : 0.0), std::tan(values[0]), 1.0, 0.0, 0.0});
    } else if ((name == "skewx" || name == "skewy") && count == 1 && read({K::kAngle})) {
      step = Matrix4::from_affine(name == "skewx" ? Affine::skew_x(values[0]) : Affine::skew_y(values[0]));
    } else {
      return error(text, name + "() with these arguments is not supported");
    }
    result = result * *step;  // left to right: the rightmost applies first
    any = true;
    skip_whitespace();
  }
  if (!any) return error(text, "no transform function");
  // Flattened onto z = 0: a point (x, y, 0, 1) maps to columns 0, 1 and 3; its w must not depend on x or
  // y for the map to be affine.
  const auto& m = result.m;
  const double w = m[3][3];
  // 1e-12 of w: cos(90deg) and the like leave rounding noise where the exact matrix has a zero.
  const double noise = 1e-12 * std::abs(w);
  if (!(std::abs(w) > 0.0) || !std::isfinite(w) || std::abs(m[0][3]) > noise || std::abs(m[1][3]) > noise)
    return error(text,
                 "a perspective projection of the plane is not supported (only 2D-equivalent 3D transforms)");
  const Affine affine{m[0][0] / w, m[0][1] / w, m[1][0] / w, m[1][1] / w, m[3][0] / w, m[3][1] / w};
  if (!std::isfinite(affine.a) || !std::isfinite(affine.b) || !std::isfinite(affine.c) ||
      !std::isfinite(affine.d) || !std::isfinite(affine.e) || !std::isfinite(affine.f))
    return error(text, "the transform is not finite");
  return affine;
}

}  // namespace curvescan::svg::detail
