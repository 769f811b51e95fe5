// The cascade of one element (cascade.h).
#include "cascade.h"

#include <algorithm>
#include <vector>

#include "css/style_sheet.h"
#include "css/syntax.h"

namespace curvescan::svg::detail {
namespace {

struct Winner {
  std::string_view name;
  std::string_view value;
};

// The winning declarations of one element, in the order they were last set: a later set of the same
// property replaces the earlier one and moves to the end, so that applying the list in order honours
// precedence also between a shorthand (font) and its longhands (font-size).
class Winners {
 public:
  void set(std::string_view name, std::string_view value) {
    const auto found =
        std::find_if(list_.begin(), list_.end(), [&](const Winner& w) { return w.name == name; });
    if (found != list_.end()) list_.erase(found);
    list_.push_back({name, value});
  }
  const std::vector<Winner>& list() const { return list_; }

 private:
  std::vector<Winner> list_;
};

// Whether the renderer reads property `name` from the cascade: the property table of computed_style.h,
// plus transform and transform-origin (read by the renderer itself) and stop-opacity (read for <stop>).
// Declarations of
// other names are dropped before the winners are chosen, which also keeps the list short
// whatever the input declares.
bool is_cascaded(std::string_view name) {
  // `marker` is a CSS shorthand only (painting_properties.h): declared, never a presentation attribute.
  return is_style_property(name) || name == "marker" || name == "transform" || name == "transform-origin" ||
         name == "stop-opacity";
}

// The precedence levels of cascade.h. `style_declarations` keeps the parsed style attribute alive.
Winners cascade(const pugi::xml_node& node, const css::StyleSheets* sheets,
                std::vector<css::Declaration>& style_declarations) {
  Winners winners;
  for (const pugi::xml_attribute& attribute : node.attributes()) {
    const std::string_view name = attribute.name();
    if (is_style_property(name)) winners.set(name, attribute.value());
  }
  std::vector<css::MatchedBlock> matched;
  if (sheets && !sheets->empty()) sheets->match(node, matched);
  const pugi::xml_attribute style = node.attribute("style");
  if (style) style_declarations = css::parse_declaration_list(style.value());
  for (const bool important : {false, true}) {
    for (const css::MatchedBlock& block : matched) {
      for (const css::Declaration& declaration : *block.declarations) {
        if (declaration.important == important && is_cascaded(declaration.name))
          winners.set(declaration.name, declaration.value);
      }
    }
    for (const css::Declaration& declaration : style_declarations) {
      if (declaration.important == important && is_cascaded(declaration.name))
        winners.set(declaration.name, declaration.value);
    }
  }
  return winners;
}

}  // namespace

ComputedStyle cascade_style(const pugi::xml_node& node, const ComputedStyle& parent,
                            const ResolveContext& context, Diagnostics& diagnostics) {
  ComputedStyle style = inherit_style(parent);
  std::vector<css::Declaration> style_declarations;
  const Winners winners = cascade(node, context.style_sheets, style_declarations);
  const auto is_font_size = [](std::string_view name) { return name == "font-size" || name == "font"; };
  for (const Winner& winner : winners.list()) {
    if (is_font_size(winner.name))
      apply_property(style, parent, winner.name, winner.value, context, diagnostics);
  }
  for (const Winner& winner : winners.list()) {
    if (!is_font_size(winner.name))
      apply_property(style, parent, winner.name, winner.value, context, diagnostics);
  }
  return style;
}

std::optional<std::string> declared_value(const pugi::xml_node& node, std::string_view name,
                                          const css::StyleSheets* sheets) {
  if ((!sheets || sheets->empty()) && !node.attribute("style")) return std::nullopt;  // the common case
  std::vector<css::Declaration> style_declarations;
  const Winners winners = cascade(node, sheets, style_declarations);
  for (const Winner& winner : winners.list()) {
    if (winner.name == name) return std::string(winner.value);
  }
  return std::nullopt;
}

std::optional<std::string> cascaded_value(const pugi::xml_node& node, std::string_view name,
                                          const css::StyleSheets* sheets) {
  if (std::optional<std::string> declared = declared_value(node, name, sheets)) return declared;
  // A presentation attribute ranks lowest (also one outside the property table, such as stop-opacity).
  if (const pugi::xml_attribute attribute = node.attribute(std::string(name).c_str()))
    return attribute.value();
  return std::nullopt;
}

}  // namespace curvescan::svg::detail
