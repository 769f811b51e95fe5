// The cascade of one element (cascade.h).
#include "cascade.h"

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "css/custom_properties.h"
#include "css/style_sheet.h"
#include "css/syntax.h"
#include "css/var_substitution.h"
#include "curvescan/svg/number.h"
#include "geometry_properties.h"
#include "painting_properties.h"
#include "text_font_variants.h"
#include "text_properties.h"
#include "xml_names.h"

namespace curvescan::svg::detail {
namespace {

// One declared value of a property: a presentation attribute, or a declaration of a sheet or of the
// style attribute.
struct Candidate {
  std::string_view name;
  std::string_view value;
  bool presentation_attribute = false;
};

// Custom property declarations are cascaded too (CSS Variables 1, section 2), from sheets and style
// attributes only: there are no presentation attributes of custom properties.
bool is_custom(const Candidate& candidate) {
  return !candidate.presentation_attribute && css::is_custom_property_name(candidate.name);
}

// Whether the renderer reads property `name` from the cascade: the property table of computed_style.h,
// plus transform and transform-origin (read by the renderer itself), stop-opacity (read for <stop>), the
// properties the filter primitives read (flood-color, flood-opacity, lighting-color,
// color-interpolation-filters) and the geometry properties (SVG 2 geometry_properties.h, read by the
// shapes). Declarations of other names are dropped before the cascade is sorted, which also keeps the
// list short whatever the input declares.
// SVG 2 6.6 gives properties newer than SVG 1.1 no presentation attribute (browsers ignore them as
// attributes): mix-blend-mode and isolation (painting_properties.h), the font ones of CSS Fonts 3 and 4
// (text_font_variants.h) and text-transform (text_properties.h); and `marker` is a CSS shorthand only (SVG
// 1.1 11.6.2).
bool has_no_presentation_attribute(std::string_view name) {
  return is_css_only_property(name) || is_css_only_font_property(name) ||
         text::is_css_only_text_property(name);
}

bool is_cascaded(std::string_view name) {
  // `marker`, mix-blend-mode and isolation are CSS only (painting_properties.h): declared, never
  // presentation attributes; so is background-color, read on the root only (canvas_background.h).
  return is_style_property(name) || is_css_only_property(name) || css::is_custom_property_name(name) ||
         name == "transform" || name == "transform-origin" || name == "stop-opacity" ||
         name == "flood-color" || name == "flood-opacity" || name == "lighting-color" ||
         name == "color-interpolation-filters" || name == "background-color" || is_geometry_property(name);
}

// Properties that change what a document draws and that this renderer does not implement, each with its
// initial value (declaring that changes nothing, so it is not named). Their declarations are dropped as
// those of unknown properties are, but named once in a warning (no silent loss, docs/svg.md):
//  - inline-size, shape-inside, shape-subtract, shape-padding, shape-margin (SVG 2 11.4-11.5,
//    auto-wrapped text and text in a shape);
//  - font-size-adjust (CSS Fonts 4), which browsers apply to SVG text;
//  - animation, animation-name (CSS Animations 1): a browser shows the animation's state at load time.
struct UnimplementedProperty {
  std::string_view name;
  std::string_view initial;
};
constexpr UnimplementedProperty kUnimplemented[] = {{"inline-size", "auto"},    {"shape-inside", "none"},
                                                    {"shape-subtract", "none"}, {"shape-padding", "0"},
                                                    {"shape-margin", "0"},      {"font-size-adjust", "none"},
                                                    {"animation", "none"},      {"animation-name", "none"}};

// The name of the unimplemented property `name` is when `value` is not its initial value (nor a
// CSS-wide keyword, which changes nothing either where the property inherits from nothing drawn).
std::optional<std::string_view> unimplemented_property(std::string_view name, std::string_view value) {
  for (const UnimplementedProperty& property : kUnimplemented) {
    if (property.name != name) continue;
    const std::string lower = css::ascii_lower(trim_whitespace(value));
    if (lower.empty() || lower == property.initial || lower == "initial" || lower == "unset" ||
        lower == "inherit" || lower == "revert")
      return std::nullopt;
    return property.name;
  }
  return std::nullopt;
}

// Every declared value of `node`, lowest precedence first (the levels of cascade.h): applied in this
// order, each valid one replacing the value before it, the last valid one wins. An invalid value then
// leaves the one below it in place, as if the parser had dropped it (CSS Syntax 3 5.4.6, CSS Cascade 4
// 4.1: invalid declarations are not part of the cascade). `style_declarations` keeps the parsed style
// attribute alive.
// `unimplemented`, when given, receives the names of unimplemented properties (kUnimplemented) declared
// with another value than their initial one, by an attribute, a sheet or the style attribute.
std::vector<Candidate> cascade(const pugi::xml_node& node, const css::StyleSheets* sheets,
                               std::vector<css::Declaration>& style_declarations,
                               std::vector<std::string_view>* unimplemented = nullptr) {
  const auto note = [unimplemented](std::string_view name, std::string_view value) {
    if (unimplemented == nullptr) return;
    if (const std::optional<std::string_view> property = unimplemented_property(name, value))
      unimplemented->push_back(*property);
  };
  std::vector<Candidate> candidates;
  for (const pugi::xml_attribute& attribute : node.attributes()) {
    const std::string_view name = attribute.name();
    if (is_style_property(name) && !has_no_presentation_attribute(name))
      candidates.push_back({name, attribute.value(), true});
    // font-size-adjust has a presentation attribute (SVG 2 6.6); an attribute named after one of the others
    // is no presentation attribute, but what it asks for is dropped all the same.
    note(name, attribute.value());
  }
  std::vector<css::MatchedBlock> matched;
  if (sheets && !sheets->empty()) sheets->match(node, matched);
  const pugi::xml_attribute style = node.attribute("style");
  if (style) style_declarations = css::parse_declaration_list(style.value());
  for (const bool important : {false, true}) {
    for (const css::MatchedBlock& block : matched) {
      for (const css::Declaration& declaration : *block.declarations) {
        if (declaration.important == important && is_cascaded(declaration.name))
          candidates.push_back({declaration.name, declaration.value, false});
        if (important) note(declaration.name, declaration.value);  // once: on the second pass
      }
    }
    for (const css::Declaration& declaration : style_declarations) {
      if (declaration.important == important && is_cascaded(declaration.name))
        candidates.push_back({declaration.name, declaration.value, false});
      if (important) note(declaration.name, declaration.value);
    }
  }
  return candidates;
}

// At most the first 80 bytes of a substituted value, for a warning (it may be up to 1 MiB long).
std::string quoted_start(std::string_view value) {
  constexpr std::size_t kQuoted = 80;
  if (value.size() <= kQuoted) return std::string(value);
  std::size_t cut = kQuoted;
  while (cut > 0 && (static_cast<unsigned char>(value[cut]) & 0xC0) == 0x80) --cut;  // a whole UTF-8 character
  return std::string(value.substr(0, cut)) + "...";
}

// The custom properties `candidates` declare, in cascade order.
std::vector<css::CustomDeclaration> custom_declarations(const std::vector<Candidate>& candidates) {
  std::vector<css::CustomDeclaration> declarations;
  for (const Candidate& candidate : candidates) {
    if (is_custom(candidate)) declarations.push_back({candidate.name, candidate.value});
  }
  return declarations;
}

// The custom properties of `node` along the document tree (each ancestor's declarations over its parent's),
// for the properties read outside cascade_style (declared_value). Made only for a value that holds var().
// A budget of its own: these reads are few (a gradient's stops, a transform), each bounded by it.
std::shared_ptr<const css::CustomProperties> document_custom_properties(const pugi::xml_node& node,
                                                                        const css::StyleSheets* sheets) {
  std::vector<pugi::xml_node> chain;
  for (pugi::xml_node element = node; element && element.type() == pugi::node_element;
       element = element.parent())
    chain.push_back(element);
  std::shared_ptr<const css::CustomProperties> properties;
  css::SubstitutionBudget budget{4 * css::kMaxSubstitutedValueBytes};
  std::vector<std::string> ignored;  // cascade_style reports them for the elements drawn
  for (auto element = chain.rbegin(); element != chain.rend(); ++element) {
    std::vector<css::Declaration> style_declarations;
    const std::vector<css::CustomDeclaration> declared =
        custom_declarations(cascade(*element, sheets, style_declarations));
    if (!declared.empty()) properties = css::compute_custom_properties(properties, declared, budget, ignored);
  }
  return properties;
}

// `value` with its var() functions substituted from `properties`, or "unset" when that fails: a value
// invalid at computed-value time makes the property unset (CSS Variables 1, 3.1).
std::string substituted_or_unset(std::string_view value, const css::CustomProperties* properties,
                                 css::SubstitutionBudget& budget) {
  css::Substitution substituted = css::substitute_var(
      value, [properties](std::string_view name) { return properties ? properties->find(name) : nullptr; },
      budget);
  return substituted.value ? std::move(*substituted.value) : std::string("unset");
}

}  // namespace

ComputedStyle cascade_style(const pugi::xml_node& node, const ComputedStyle& parent,
                            const ResolveContext& context, Diagnostics& diagnostics) {
  ComputedStyle style = inherit_style(parent);
  // The user agent's sheet sits below every author declaration; of the properties read here it sets
  // only overflow. The root is the element without an element parent (a sub-document's root too).
  style.painting.overflow = user_agent_overflow(local_name(node), node.parent().type() != pugi::node_element);
  std::vector<css::Declaration> style_declarations;
  std::vector<std::string_view> unimplemented;
  const std::vector<Candidate> candidates =
      cascade(node, context.style_sheets, style_declarations, &unimplemented);
  // Custom properties first: the other values may reference them (CSS Variables 1). Their problems are
  // named once each, without the element: a rule for every element would repeat them for each.
  if (const std::vector<css::CustomDeclaration> custom = custom_declarations(candidates); !custom.empty()) {
    std::vector<std::string> problems;
    style.custom_properties = css::compute_custom_properties(parent.custom_properties, custom,
                                                             diagnostics.substitution_budget, problems);
    for (std::string& problem : problems) diagnostics.warn_once(std::move(problem));
  }
  // The values with var(), substituted (CSS Variables 1, section 3: at computed-value time, then the
  // property's grammar parses the result); `substituted[i]` for candidates[i], nullopt when it failed.
  // Both stay empty (no allocation) for the common element without var().
  std::vector<std::optional<std::string>> substituted;
  std::vector<std::string> failures;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const Candidate& candidate = candidates[i];
    if (is_custom(candidate) || !css::contains_var(candidate.value)) continue;
    if (substituted.empty()) {
      substituted.resize(candidates.size());
      failures.resize(candidates.size());
    }
    const css::CustomProperties* properties = style.custom_properties.get();
    css::Substitution result = css::substitute_var(
        candidate.value,
        [properties](std::string_view name) { return properties ? properties->find(name) : nullptr; },
        diagnostics.substitution_budget);
    if (result.value) {
      substituted[i] = std::move(result.value);
    } else {
      failures[i] = css::describe(result);
    }
  }
  for (const std::string_view name : unimplemented)
    diagnostics.unsupported("the " + std::string(name) + " property");
  for (const pugi::xml_attribute& attribute : node.attributes()) {
    const std::string_view name = attribute.name();
    if (has_no_presentation_attribute(name))
      diagnostics.unsupported("the " + std::string(name) + " attribute (a CSS property only: use style=\"" +
                              std::string(name) + ": ...\")");
    // SVG 1.1 14.3.5's clip (a rectangle on a viewport element; deprecated by CSS Masking 1 for clip-path)
    // is not drawn: named unless it is the initial `auto`, which changes nothing.
    if (name == "clip" && trim_whitespace(attribute.value()) != "auto")
      diagnostics.unsupported("the clip property (use clip-path)");
  }
  for (const css::Declaration& declaration : style_declarations) {
    if (declaration.name == "clip" && trim_whitespace(declaration.value) != "auto")
      diagnostics.unsupported("the clip property (use clip-path)");
  }
  // The font size first, because em lengths of the other properties depend on it; then every
  // declaration in order, the font ones again (idempotent: they depend only on the parent) so that a
  // later font-family beats an earlier `font` and the other way round. The first pass keeps its
  // warnings to itself: the second repeats them.
  // A declaration with an empty value ("fill:") is invalid for every property (CSS Syntax 3 5.4.6 leaves
  // it empty, and no property's grammar matches nothing): warned about here, as the property parsers warn
  // about the others, and dropped. Presentation attributes are left to the property parsers.
  const auto is_font_size = [](std::string_view name) { return name == "font-size" || name == "font"; };
  const auto is_empty_declaration = [](const Candidate& candidate) {
    return !candidate.presentation_attribute && candidate.value.empty();
  };
  // candidates[i] applied. A value with var() was valid when it was parsed (CSS Variables 1, section 3),
  // so it is part of the cascade whatever it becomes: when the substitution fails or its result is not a
  // valid value, the property is unset (section 3.1: inherited or initial), NOT the declaration below.
  const auto apply = [&](std::size_t i, Diagnostics& out) {
    const Candidate& candidate = candidates[i];
    if (is_custom(candidate)) return;  // computed above
    if (is_empty_declaration(candidate)) {
      out.warnings.push_back(std::string(kInvalidValueWarning) + " '' of property '" +
                             std::string(candidate.name) + "'");
      return;
    }
    if (!substituted.empty() && (substituted[i] || !failures[i].empty())) {
      const std::size_t before = out.warnings.size();
      if (substituted[i]) {
        if (apply_property(style, parent, candidate.name, *substituted[i], context, out)) return;
        out.warnings.resize(before);  // the parser's own line, replaced by the one below
        failures[i] = "'" + quoted_start(*substituted[i]) + "' after var() substitution is not a valid value";
      }
      apply_property(style, parent, candidate.name, "unset", context, out);
      out.warnings.push_back(std::string(kInvalidValueWarning) + " '" + std::string(candidate.value) +
                             "' of property '" + std::string(candidate.name) + "' (" + failures[i] +
                             "): the property is unset");
      return;
    }
    apply_property(style, parent, candidate.name, candidate.value, context, out);
  };
  Diagnostics first_pass;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (is_font_size(candidates[i].name)) apply(i, first_pass);
  }
  const std::size_t earlier_warnings = diagnostics.warnings.size();
  for (std::size_t i = 0; i < candidates.size(); ++i) apply(i, diagnostics);
  // An invalid value says which element holds it and where, as style sheet warnings name their rule.
  for (std::size_t i = earlier_warnings; i < diagnostics.warnings.size(); ++i) {
    std::string& warning = diagnostics.warnings[i];
    if (warning.rfind(kInvalidValueWarning, 0) == 0) warning = diagnostics.element_prefix(node) + warning;
  }
  return style;
}

std::optional<std::string> declared_value(const pugi::xml_node& node, std::string_view name,
                                          const css::StyleSheets* sheets, const ValueCheck& valid) {
  if ((!sheets || sheets->empty()) && !node.attribute("style")) return std::nullopt;  // the common case
  std::vector<css::Declaration> style_declarations;
  const std::vector<Candidate> candidates = cascade(node, sheets, style_declarations);
  // Highest precedence first; presentation attributes are not declarations of a sheet.
  for (auto it = candidates.rbegin(); it != candidates.rend(); ++it) {
    if (it->name != name || it->presentation_attribute || it->value.empty()) continue;
    if (css::contains_var(it->value)) {
      // Valid at parse time whatever it holds: its substitution, or unset when that is invalid (3.1).
      // Only where `valid` refuses unset (a reader without the CSS-wide keywords) does the next one apply.
      css::SubstitutionBudget budget{4 * css::kMaxSubstitutedValueBytes};
      std::string value =
          substituted_or_unset(it->value, document_custom_properties(node, sheets).get(), budget);
      if (valid && !valid(value)) value = "unset";
      if (!valid || valid(value)) return value;
      continue;
    }
    if (!valid || valid(it->value)) return std::string(it->value);
  }
  return std::nullopt;
}

std::optional<std::string> cascaded_value(const pugi::xml_node& node, std::string_view name,
                                          const css::StyleSheets* sheets, const ValueCheck& valid) {
  if (std::optional<std::string> declared = declared_value(node, name, sheets, valid)) return declared;
  // A presentation attribute ranks lowest (also one outside the property table, such as stop-opacity).
  if (const pugi::xml_attribute attribute = node.attribute(std::string(name).c_str())) {
    std::string value = attribute.value();
    if (css::contains_var(value)) {  // as in a declaration (cascade.h)
      css::SubstitutionBudget budget{4 * css::kMaxSubstitutedValueBytes};
      value = substituted_or_unset(value, document_custom_properties(node, sheets).get(), budget);
      if (valid && !valid(value)) value = "unset";
    }
    if (!valid || valid(value)) return value;
  }
  return std::nullopt;
}

}  // namespace curvescan::svg::detail
