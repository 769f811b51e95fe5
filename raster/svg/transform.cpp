// SVG transform-list parsing (transform.h), SVG 1.1 section 7.6 and its grammar.
#include "curvescan/svg/transform.h"

#include <numbers>
#include <string>
#include <vector>

#include "curvescan/svg/number.h"

namespace curvescan::svg {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

Error bad_transform(std::string_view text, const std::string& why) {
  return Error{ErrorKind::kInvalidArgument, "transform '" + std::string(text) + "': " + why};
}

bool is_name_char(char c) noexcept {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

// The item for function `name` with `args`, or an explanation of why the count is wrong.
Result<Affine> transform_item(std::string_view name, const std::vector<double>& args, std::string_view text) {
  const std::size_t n = args.size();
  auto wrong_count = [&] {
    return bad_transform(text, std::string(name) + "() does not take " + std::to_string(n) + " arguments");
  };
  if (name == "matrix") {
    if (n != 6) return wrong_count();
    return Affine{args[0], args[1], args[2], args[3], args[4], args[5]};
  }
  if (name == "translate") {
    if (n != 1 && n != 2) return wrong_count();
    return Affine::translate(args[0], n == 2 ? args[1] : 0.0);  // ty defaults to 0
  }
  if (name == "scale") {
    if (n != 1 && n != 2) return wrong_count();
    return Affine::scale(args[0], n == 2 ? args[1] : args[0]);  // sy defaults to sx
  }
  if (name == "rotate") {
    if (n != 1 && n != 3) return wrong_count();
    const Affine rotation = Affine::rotate(args[0] * kRadiansPerDegree);
    if (n == 1) return rotation;
    // rotate(a cx cy) = translate(cx cy) rotate(a) translate(-cx -cy)
    return Affine::translate(args[1], args[2]) * rotation * Affine::translate(-args[1], -args[2]);
  }
  if (name == "skewX") {
    if (n != 1) return wrong_count();
    return Affine::skew_x(args[0] * kRadiansPerDegree);
  }
  if (name == "skewY") {
    if (n != 1) return wrong_count();
    return Affine::skew_y(args[0] * kRadiansPerDegree);
  }
  return bad_transform(text, "unknown function '" + std::string(name) + "'");
}

}  // namespace

Result<Affine> parse_transform(std::string_view text) {
  Affine total = Affine::identity();
  std::string_view rest = text;
  skip_whitespace(rest);
  while (!rest.empty()) {
    std::size_t name_length = 0;
    while (name_length < rest.size() && is_name_char(rest[name_length])) ++name_length;
    if (name_length == 0) return bad_transform(text, "expected a transform function");
    const std::string_view name = rest.substr(0, name_length);
    rest.remove_prefix(name_length);
    skip_whitespace(rest);
    if (rest.empty() || rest.front() != '(')
      return bad_transform(text, "expected '(' after " + std::string(name));
    rest.remove_prefix(1);
    skip_whitespace(rest);
    std::vector<double> args;
    while (!rest.empty() && rest.front() != ')') {
      const std::optional<double> value = consume_number(rest);
      if (!value) return bad_transform(text, "expected a number in " + std::string(name) + "()");
      args.push_back(*value);
      skip_comma_whitespace(rest);
    }
    if (rest.empty()) return bad_transform(text, "missing ')' after " + std::string(name));
    rest.remove_prefix(1);
    Result<Affine> item = transform_item(name, args, text);
    if (!item) return item.error();
    total = total * *item;
    skip_comma_whitespace(rest);
  }
  return total;
}

}  // namespace curvescan::svg
