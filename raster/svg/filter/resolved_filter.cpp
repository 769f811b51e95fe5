// A <filter> read once (resolved_filter.h).
#include "resolved_filter.h"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "filter_graph.h"
#include "filter_region.h"
#include "href_chain.h"
#include "xml_names.h"

namespace curvescan::svg::detail::filter {
namespace {

bool is_standard_input(std::string_view reference) {
  return reference == "SourceGraphic" || reference == "SourceAlpha";
}

// The standard inputs of Filter Effects 1 (9.2) that this renderer does not provide, as browsers do not:
// BackgroundImage and BackgroundAlpha (the backdrop under the filter region, which needs
// enable-background or an isolated group's backdrop), and FillPaint and StrokePaint (the element's fill
// or stroke paint over the filter region; Chrome never implemented them and resvg dropped them). Like
// browsers, this renderer reads each as a name no primitive gave -- the previous result, SourceGraphic
// for the first primitive -- with a warning.
bool is_unsupported_input(std::string_view reference) {
  return reference == "BackgroundImage" || reference == "BackgroundAlpha" || reference == "FillPaint" ||
         reference == "StrokePaint";
}

// The primitives of `primitives` (a <filter>) with their inputs planned: each input resolved to the
// primitive that makes it (or a standard input), and the last primitive that reads each result, so that an
// image nobody reads any more is given back for reuse (filter_graph.cpp). Stops at the first primitive
// without an implementation. The attributes are read after (read_primitives).
void plan_primitives(const pugi::xml_node& primitives, ResolvedFilter& filter, Diagnostics& diagnostics) {
  std::vector<ResolvedPrimitive>& plan = filter.primitives;
  std::unordered_map<std::string, int> names;
  std::vector<std::string> unsupported_inputs;
  for (pugi::xml_node node = primitives.first_child(); node; node = node.next_sibling()) {
    if (node.type() != pugi::node_element) continue;
    const std::string_view name = local_name(node);
    if (!is_filter_primitive(name)) continue;  // <desc>, <title>, foreign markup: not primitives
    const PrimitiveEntry* entry = find_primitive(name);
    if (entry == nullptr) {
      filter.unsupported = std::string(name);
      diagnostics.unsupported("<" + filter.unsupported + ">");
      break;
    }
    ResolvedPrimitive step;
    step.node = node;
    step.entry = entry;
    const int index = static_cast<int>(plan.size());
    const auto add_input = [&](std::string_view reference) {
      if (is_unsupported_input(reference) && std::find(unsupported_inputs.begin(), unsupported_inputs.end(),
                                                       reference) == unsupported_inputs.end())
        unsupported_inputs.emplace_back(reference);
      if (is_standard_input(reference)) {
        step.inputs.push_back({std::string(reference), -1});
      } else if (const auto found = names.find(std::string(reference));
                 !reference.empty() && found != names.end()) {
        step.inputs.push_back({{}, found->second});
      } else if (index > 0) {
        // A missing `in`, or a reference to no earlier result (Filter Effects 1, 9.2: "treated as if no
        // result was specified"): the previous result, or SourceGraphic for the first primitive.
        step.inputs.push_back({{}, index - 1});
      } else {
        step.inputs.push_back({"SourceGraphic", -1});
      }
    };
    if (entry->inputs == PrimitiveInputs::kIn || entry->inputs == PrimitiveInputs::kInAndIn2) {
      add_input(node.attribute("in").value());
    }
    if (entry->inputs == PrimitiveInputs::kInAndIn2) add_input(node.attribute("in2").value());
    if (entry->inputs == PrimitiveInputs::kMergeNodes) {
      for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
        if (local_name(child) == "feMergeNode") add_input(child.attribute("in").value());
      }
    }
    for (const PrimitiveInput& input : step.inputs) {
      if (input.producer >= 0) plan[static_cast<std::size_t>(input.producer)].last_use = index;
      if (input.producer < 0) filter.standard_last_use[input.standard] = index;
    }
    if (const std::string_view result_name = node.attribute("result").value(); !result_name.empty()) {
      names[std::string(result_name)] = index;
    }
    // An feMerge composites each of its nodes over the image: one pass each.
    filter.passes +=
        entry->inputs == PrimitiveInputs::kMergeNodes ? 1 + static_cast<std::int64_t>(step.inputs.size()) : 1;
    plan.push_back(std::move(step));
  }
  if (!filter.unsupported.empty()) {
    diagnostics.warnings.push_back("a filter with <" + filter.unsupported + "> gives a transparent result");
    return;
  }
  for (const std::string& input : unsupported_inputs)
    diagnostics.unsupported("filter input " + input + " (the previous result is read instead)");
}

// Each planned primitive's subregion attributes, colour space and parameters.
void read_primitives(ResolvedFilter& filter, const IdIndex& ids, const ResolveContext& context,
                     const css::StyleSheets* style_sheets,
                     const std::function<ComputedStyle(const pugi::xml_node&)>& style_of,
                     Diagnostics& diagnostics) {
  const bool box = filter.bounding_box_primitives;
  for (ResolvedPrimitive& primitive : filter.primitives) {
    const std::string element(local_name(primitive.node));
    const auto coordinate = [&](const char* name, LengthAxis axis) {
      const pugi::xml_attribute attribute = primitive.node.attribute(name);
      if (!attribute) return std::nan("");
      return region_attribute(attribute, std::nan(""), box, axis, element, diagnostics);
    };
    primitive.subregion = {coordinate("x", context.horizontal()), coordinate("y", context.vertical()),
                           coordinate("width", context.horizontal()),
                           coordinate("height", context.vertical())};
    primitive.color_space = color_interpolation_filters(primitive.node, style_sheets);
    primitive.params = primitive.entry->read(PrimitiveReading{
        primitive.node, primitive.color_space, style_sheets, diagnostics, primitive.error, ids, style_of});
    if (!primitive.error.empty()) {
      primitive.params = NoParams{};
      diagnostics.warnings.push_back(primitive.error + "; the filter gives a transparent result");
    }
  }
}

}  // namespace

ResolvedFilter resolve_filter(const pugi::xml_node& filter, const IdIndex& ids, const ResolveContext& context,
                              const css::StyleSheets* style_sheets,
                              const std::function<ComputedStyle(const pugi::xml_node&)>& style_of,
                              Diagnostics& diagnostics) {
  constexpr int kMaxChain = 16;
  const std::vector<pugi::xml_node> chain =
      href_chain(filter, ids, {"filter"}, kMaxChain, "filter", diagnostics);
  ResolvedFilter resolved;
  resolved.element = filter;
  pugi::xml_node primitives = filter;
  for (const pugi::xml_node& link : chain) {
    if (link.find_child([](const pugi::xml_node& child) { return child.type() == pugi::node_element; })) {
      primitives = link;
      break;
    }
  }
  resolved.region_in_box =
      std::string_view(chain_attribute(chain, "filterUnits").value()) != "userSpaceOnUse";
  resolved.bounding_box_primitives =
      std::string_view(chain_attribute(chain, "primitiveUnits").value()) == "objectBoundingBox";
  const auto value = [&](const char* name, double fraction, LengthAxis axis) {
    return region_attribute(chain_attribute(chain, name),
                            resolved.region_in_box ? fraction : fraction * axis.percent_reference,
                            resolved.region_in_box, axis, "filter", diagnostics);
  };
  resolved.x = value("x", -0.1, context.horizontal());
  resolved.y = value("y", -0.1, context.vertical());
  resolved.width = value("width", 1.2, context.horizontal());
  resolved.height = value("height", 1.2, context.vertical());
  plan_primitives(primitives, resolved, diagnostics);
  if (resolved.unsupported.empty())
    read_primitives(resolved, ids, context, style_sheets, style_of, diagnostics);
  resolved.peak_images = peak_filter_images(resolved);
  return resolved;
}

}  // namespace curvescan::svg::detail::filter
