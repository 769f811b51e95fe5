// Geometry properties from the cascade (geometry_properties.h).
#include "geometry_properties.h"

#include <array>
#include <cmath>

#include "cascade.h"
#include "css/syntax.h"
#include "curvescan/svg/number.h"

namespace curvescan::svg::detail {
namespace {

constexpr std::array<std::string_view, 10> kGeometryProperties{"x",  "y", "width", "height", "cx",
                                                               "cy", "r", "rx",    "ry",     "d"};

enum class Keyword { kNone, kInherit, kInitial };

// The CSS-wide keywords (CSS Cascade 4, 7.3), ASCII case-insensitive; revert acts as unset in an author
// style sheet when the user agent's sheet does not set the property, as for these.
Keyword css_wide_keyword(std::string_view value) {
  const std::string lowered = css::ascii_lower(trim_whitespace(value));
  if (lowered == "inherit") return Keyword::kInherit;
  if (lowered == "initial" || lowered == "unset" || lowered == "revert" || lowered == "revert-layer")
    return Keyword::kInitial;
  return Keyword::kNone;
}

bool allows_auto(std::string_view name) {
  return name == "width" || name == "height" || name == "rx" || name == "ry";
}

bool allows_negative(std::string_view name) {
  return name == "x" || name == "y" || name == "cx" || name == "cy";
}

// The value of a length property, once validated: nullopt for auto. `error` says why a value is
// invalid (and stays empty when it is valid).
std::optional<Length> length_value(std::string_view name, std::string_view value, std::string& error) {
  value = trim_whitespace(value);
  error.clear();
  if (allows_auto(name) && css::ascii_lower(value) == "auto") return std::nullopt;
  const Result<Length> length = parse_length(value);
  if (!length) {
    error = length.error().message;
  } else if (!std::isfinite(length->value)) {
    error = "not a finite number";
  } else if (!allows_negative(name) && length->value < 0.0) {
    error = "negative";
  } else {
    return *length;
  }
  return std::nullopt;
}

void warn_invalid(Diagnostics& diagnostics, const pugi::xml_node& node, std::string_view name,
                  std::string_view value, std::string_view why) {
  diagnostics.warnings.push_back(diagnostics.element_prefix(node) + std::string(kInvalidValueWarning) + " '" +
                                 std::string(value) + "' of property '" + std::string(name) +
                                 "': " + std::string(why));
}

}  // namespace

bool is_geometry_property(std::string_view name) noexcept {
  for (const std::string_view known : kGeometryProperties) {
    if (known == name) return true;
  }
  return false;
}

std::optional<Length> geometry_length(const pugi::xml_node& start, std::string_view name,
                                      const css::StyleSheets* sheets, Diagnostics& diagnostics) {
  // `inherit` walks up: each step is one ancestor, so the loop ends at the root.
  for (pugi::xml_node node = start; node && node.type() == pugi::node_element; node = node.parent()) {
    // A value's own grammar; the CSS-wide keywords only in declarations (an attribute is no declaration:
    // x="inherit" is invalid, as SVG 1.1 has it for these attributes and resvg reads it).
    const auto valid_length = [&](std::string_view value) {
      std::string error;
      (void)length_value(name, value, error);
      if (!error.empty()) warn_invalid(diagnostics, node, name, value, error);
      return error.empty();
    };
    const ValueCheck valid = [&](std::string_view value) {
      return css_wide_keyword(value) != Keyword::kNone || valid_length(value);
    };
    std::optional<std::string> value = declared_value(node, name, sheets, valid);
    if (!value) {
      const pugi::xml_attribute attribute = node.attribute(std::string(name).c_str());
      if (!attribute || !valid_length(attribute.value())) return std::nullopt;
      value = attribute.value();
    }
    const Keyword keyword = css_wide_keyword(*value);
    if (keyword == Keyword::kInitial) return std::nullopt;
    if (keyword == Keyword::kInherit) continue;
    std::string error;
    return length_value(name, *value, error);
  }
  return std::nullopt;
}

std::optional<std::string> css_path_function(std::string_view value) {
  value = trim_whitespace(value);
  if (value.size() < 5 || css::ascii_lower(value.substr(0, 5)) != "path(" || value.back() != ')')
    return std::nullopt;
  std::string_view inside = trim_whitespace(value.substr(5, value.size() - 6));
  // An optional fill rule first (CSS Shapes 1 path(): "[<fill-rule>,]? <string>"): the d property
  // ignores it, the fill-rule property decides.
  for (const std::string_view rule : {"nonzero", "evenodd"}) {
    if (inside.size() > rule.size() && css::ascii_lower(inside.substr(0, rule.size())) == rule) {
      std::string_view rest = trim_whitespace(inside.substr(rule.size()));
      if (!rest.empty() && rest.front() == ',') inside = trim_whitespace(rest.substr(1));
    }
  }
  if (inside.size() < 2 || (inside.front() != '"' && inside.front() != '\'') ||
      inside.back() != inside.front())
    return std::nullopt;
  const char quote = inside.front();
  const std::string_view body = inside.substr(1, inside.size() - 2);
  std::string text;
  for (std::size_t i = 0; i < body.size(); ++i) {
    if (body[i] == quote) return std::nullopt;  // the string ended before the ')'
    if (body[i] == '\\' && i + 1 < body.size()) {
      ++i;  // an escaped character stands for itself (path data has no use for hex escapes)
      if (body[i] == '\n') continue;  // an escaped newline is no character (4.3.5)
    }
    text += body[i];
  }
  return text;
}

std::string geometry_path_data(const pugi::xml_node& start, const css::StyleSheets* sheets,
                               Diagnostics& diagnostics) {
  for (pugi::xml_node node = start; node && node.type() == pugi::node_element; node = node.parent()) {
    // The declarations hold CSS values: none, path("...") or a CSS-wide keyword.
    const ValueCheck valid = [&](std::string_view value) {
      const std::string lowered = css::ascii_lower(trim_whitespace(value));
      const bool ok = lowered == "none" || css_wide_keyword(value) != Keyword::kNone ||
                      css_path_function(value).has_value();
      if (!ok) warn_invalid(diagnostics, node, "d", value, "expected none or path(\"...\")");
      return ok;
    };
    if (const std::optional<std::string> declared = declared_value(node, "d", sheets, valid)) {
      const Keyword keyword = css_wide_keyword(*declared);
      if (keyword == Keyword::kInitial) return {};
      if (keyword == Keyword::kInherit) continue;
      return css_path_function(*declared).value_or(std::string());  // none: no path
    }
    // The attribute holds path data (errors are reported where it is read: rendered up to the error).
    return node.attribute("d").value();
  }
  return {};
}

}  // namespace curvescan::svg::detail
