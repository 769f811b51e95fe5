// The primitive table (primitive_table.h): each adapter reads its primitive's attributes (Filter Effects 1,
// section 9, one subsection per primitive) and calls the pixel function of its own file.
#include "primitive_table.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

#include "blend.h"
#include "cascade.h"
#include "color_matrix.h"
#include "component_transfer.h"
#include "composite.h"
#include "convolve_matrix.h"
#include "css/syntax.h"
#include "curvescan/svg/color.h"
#include "curvescan/svg/number.h"
#include "displacement_map.h"
#include "drop_shadow.h"
#include "flood.h"
#include "gaussian_blur.h"
#include "lighting.h"
#include "morphology.h"
#include "offset.h"
#include "painting_properties.h"
#include "tile.h"
#include "turbulence.h"
#include "xml_names.h"

namespace curvescan::svg::detail::filter {
namespace {

std::string_view attribute(const pugi::xml_node& node, const char* name) {
  return node.attribute(name).value();
}

// A number attribute, `fallback` when absent; nullopt when present but not a number.
std::optional<double> number_attribute(const pugi::xml_node& node, const char* name, double fallback) {
  const pugi::xml_attribute value = node.attribute(name);
  if (!value) return fallback;
  const std::optional<double> parsed = parse_number(value.value());
  if (!parsed || !std::isfinite(*parsed)) return std::nullopt;
  return parsed;
}

// "<number> <number>?" (stdDeviation, radius, kernelUnitLength): the second defaults to the first.
std::optional<std::pair<double, double>> number_pair(const pugi::xml_node& node, const char* name,
                                                     double fallback) {
  const pugi::xml_attribute value = node.attribute(name);
  if (!value) return std::pair{fallback, fallback};
  const NumberList list = parse_number_list(value.value());
  if (!list.complete || list.values.empty() || list.values.size() > 2) return std::nullopt;
  for (const double v : list.values) {
    if (!std::isfinite(v)) return std::nullopt;
  }
  return std::pair{list.values[0], list.values.size() == 2 ? list.values[1] : list.values[0]};
}

std::string name_of(const PrimitiveCall& call) {
  return "<" + std::string(local_name(call.node)) + ">";
}

// The input's ink inside the subregion: where a primitive that keeps transparent pixels transparent can
// have a result (FilterImage::extent).
PixelRect ink_of(const FilterImage& image, PixelRect subregion) noexcept {
  return image.extent.intersect(image.bounds()).intersect(subregion);
}

// feFlood (9.12).
std::string run_flood(const PrimitiveCall& call) {
  const FilterColor color = primitive_color(call.node, "flood-color", "flood-opacity", call.color_space,
                                            call.environment, call.diagnostics);
  call.out.extent = color.a > 0.0f ? call.subregion.intersect(call.needed) : PixelRect{};
  flood(color, call.out.extent, call.out);
  return {};
}

// A number attribute that is absent or not a number counts as `fallback` (SVG 2, 6.7: an invalid value is
// as if the attribute were not specified); `warn` is told about a value that is present but unusable.
double number_or_initial(const pugi::xml_node& node, const char* name, double fallback,
                         const std::function<void(const std::string&)>& warn = {}) {
  const std::optional<double> value = number_attribute(node, name, fallback);
  if (!value && warn) {
    warn("<" + std::string(local_name(node)) + "> " + name + " '" + node.attribute(name).value() +
         "' is not a number; " + std::to_string(static_cast<int>(fallback)) + " is used");
  }
  return value.value_or(fallback);
}

// feOffset's dx, dy (9.17) in whole filter pixels (a value that is not a number counts as 0).
std::pair<long long, long long> offset_pixels(const pugi::xml_node& node, const FilterSpace& space,
                                              const std::function<void(const std::string&)>& warn = {}) {
  const double dx = number_or_initial(node, "dx", 0.0, warn), dy = number_or_initial(node, "dy", 0.0, warn);
  return std::pair{whole_pixel_offset(space.x_to_pixels(space.user_width(dx))),
                   whole_pixel_offset(space.y_to_pixels(space.user_height(dy)))};
}

// The warning channel of a primitive call.
std::function<void(const std::string&)> warner(const PrimitiveCall& call) {
  return [&call](const std::string& message) { call.diagnostics.warnings.push_back(message); };
}

// feOffset (9.17): dx, dy in primitiveUnits, rounded to whole filter pixels (offset.h).
std::string run_offset(const PrimitiveCall& call) {
  const auto [shift_x, shift_y] = offset_pixels(call.node, call.space, warner(call));
  call.out.extent = ink_of(*call.in, call.in->bounds())
                        .moved(shift_x, shift_y)
                        .intersect(call.subregion)
                        .intersect(call.needed);
  offset(*call.in, call.out.extent, shift_x, shift_y, call.out);
  return {};
}

// stdDeviation (σx, σy) in primitive units: `fallback` when absent. Filter Effects 1, 9.13: "A negative
// value or a value of zero disables the effect of the given filter primitive (i.e., the result is the filter
// input image)"; a malformed value (not one or two numbers) is as if not specified, which for
// feGaussianBlur is 0 too. Both give {0, 0}, with a warning.
std::pair<double, double> deviation_numbers(const pugi::xml_node& node, double fallback,
                                            const std::function<void(const std::string&)>& warn = {}) {
  const std::optional<std::pair<double, double>> sigma = number_pair(node, "stdDeviation", fallback);
  if (sigma && sigma->first >= 0.0 && sigma->second >= 0.0) return *sigma;
  if (warn) {
    warn("<" + std::string(local_name(node)) + "> stdDeviation '" + node.attribute("stdDeviation").value() +
         "' is not one or two non-negative numbers; the blur is disabled");
  }
  return {0.0, 0.0};
}

// stdDeviation in pixels along x and y.
std::pair<double, double> deviation_pixels(const PrimitiveCall& call, double fallback) {
  const std::pair<double, double> sigma = deviation_numbers(call.node, fallback, warner(call));
  return std::pair{call.space.x_to_pixels(call.space.user_width(sigma.first)),
                   call.space.y_to_pixels(call.space.user_height(sigma.second))};
}

// feGaussianBlur (9.13).
std::string run_gaussian_blur(const PrimitiveCall& call) {
  const auto [sigma_x, sigma_y] = deviation_pixels(call, 0.0);
  EdgeMode mode = EdgeMode::kNone;
  if (const pugi::xml_attribute edge = call.node.attribute("edgeMode")) {
    const std::optional<EdgeMode> parsed = parse_edge_mode(edge.value());
    if (!parsed) {
      call.diagnostics.warnings.push_back(name_of(call) + " edgeMode '" + edge.value() +
                                          "' is not valid; none used");
    } else {
      mode = *parsed;
    }
  }
  // The blur reads its input image as the input made it, beyond this primitive's subregion too (the
  // subregion clips the result, Filter Effects 1, 9.7; edgeMode extends the *input* image, whose edge is
  // the input's own subregion), and writes only the needed pixels of its subregion.
  const PixelRect keep = call.subregion.intersect(call.needed);
  PixelRect read = call.in_subregion.intersect(call.in->bounds());
  if (mode == EdgeMode::kNone) {
    // Beyond the input's ink everything is transparent, and a written pixel reads at most the blur's reach
    // away: the blur of that rectangle (transparent outside it) is the blur of the whole input there.
    const long long reach_x = blur_reach(sigma_x), reach_y = blur_reach(sigma_y);
    read =
        ink_of(*call.in, call.in->bounds()).intersect(keep.grown(reach_x, reach_y)).grown(reach_x, reach_y);
    read = read.intersect(keep.grown(reach_x, reach_y));
  }
  gaussian_blur(*call.in, read, sigma_x, sigma_y, mode, call.out, call.in_alpha_only, keep);
  call.out.extent = read.intersect(keep);
  return {};
}

// feDropShadow (Filter Effects 1, 9.11).
std::string run_drop_shadow(const PrimitiveCall& call) {
  const std::pair<double, double> sigma = deviation_pixels(call, 2.0);
  const double dx = number_or_initial(call.node, "dx", 2.0, warner(call)),
               dy = number_or_initial(call.node, "dy", 2.0, warner(call));
  DropShadowParams params;
  params.sigma_x = sigma.first;
  params.sigma_y = sigma.second;
  params.dx = call.space.x_to_pixels(call.space.user_width(dx));
  params.dy = call.space.y_to_pixels(call.space.user_height(dy));
  params.color = primitive_color(call.node, "flood-color", "flood-opacity", call.color_space,
                                 call.environment, call.diagnostics);
  drop_shadow(*call.in, params, call.subregion, call.out, call.needed);
  return {};
}

// feComposite (9.9).
std::string run_composite(const PrimitiveCall& call) {
  static constexpr std::array<std::pair<std::string_view, CompositeOperator>, 7> kOperators{{
      {"over", CompositeOperator::kOver},
      {"in", CompositeOperator::kIn},
      {"out", CompositeOperator::kOut},
      {"atop", CompositeOperator::kAtop},
      {"xor", CompositeOperator::kXor},
      {"lighter", CompositeOperator::kLighter},
      {"arithmetic", CompositeOperator::kArithmetic},
  }};
  CompositeParams params;
  if (const pugi::xml_attribute op = call.node.attribute("operator")) {
    const auto found = std::find_if(kOperators.begin(), kOperators.end(),
                                    [&](const auto& entry) { return entry.first == op.value(); });
    if (found == kOperators.end()) {
      call.diagnostics.warnings.push_back(name_of(call) + " operator '" + op.value() +
                                          "' is not valid; over used");
    } else {
      params.op = found->second;
    }
  }
  double* k[4] = {&params.k1, &params.k2, &params.k3, &params.k4};
  const char* names[4] = {"k1", "k2", "k3", "k4"};
  for (int i = 0; i < 4; ++i) {
    const std::optional<double> value = number_attribute(call.node, names[i], 0.0);
    if (!value) return name_of(call) + " " + names[i] + " is not a number";
    *k[i] = *value;
  }
  // Where the result can be other than transparent: both inputs transparent give transparent, except for
  // arithmetic with k4 > 0 (Porter-Duff: in keeps where both are, out where `in` is, atop where `in2` is).
  // A constant input (an feFlood not drawn) covers the whole subregion.
  const PixelRect a = call.in != nullptr ? ink_of(*call.in, call.subregion) : call.subregion,
                  b = call.in2 != nullptr ? ink_of(*call.in2, call.subregion) : call.subregion;
  PixelRect area = a.unite(b);
  switch (params.op) {
    case CompositeOperator::kIn:
      area = a.intersect(b);
      break;
    case CompositeOperator::kOut:
      area = a;
      break;
    case CompositeOperator::kAtop:
      area = b;
      break;
    case CompositeOperator::kArithmetic:
      area = PixelRect{};
      if (params.k1 != 0.0) area = a.intersect(b);
      if (params.k2 != 0.0) area = area.unite(a);
      if (params.k3 != 0.0) area = area.unite(b);
      if (!(params.k4 <= 0.0)) area = call.subregion;
      break;
    default:
      break;
  }
  call.out.extent = area.intersect(call.needed);
  composite(CompositeInput{call.in, call.in_constant}, CompositeInput{call.in2, call.in2_constant}, params,
            call.out.extent, call.out);
  return {};
}

// feMerge (9.16).
std::string run_merge(const PrimitiveCall& call) {
  PixelRect area;
  for (const FilterImage* input : call.merge_inputs) area = area.unite(ink_of(*input, call.subregion));
  call.out.extent = area.intersect(call.needed);
  if (call.merge_other_space.empty()) {
    merge(call.merge_inputs, area, call.out);
  } else {
    merge(call.merge_inputs, call.merge_other_space, call.color_space, area, call.out);
  }
  return {};
}

// feBlend (9.6): mode, default normal.
std::string run_blend(const PrimitiveCall& call) {
  BlendMode mode = BlendMode::kNormal;
  if (const pugi::xml_attribute value = call.node.attribute("mode")) {
    const std::optional<BlendMode> parsed = parse_blend_mode(value.value());
    if (!parsed) {
      call.diagnostics.warnings.push_back(name_of(call) + " mode '" + value.value() +
                                          "' is not valid; normal used");
    } else {
      mode = *parsed;
    }
  }
  // Every mode blends two transparent pixels into a transparent one.
  call.out.extent =
      ink_of(*call.in, call.subregion).unite(ink_of(*call.in2, call.subregion)).intersect(call.needed);
  blend(*call.in, *call.in2, mode, call.out.extent, call.out);
  return {};
}

// feColorMatrix (9.8): type matrix (default) with 20 values, saturate (default 1), hueRotate (default 0),
// luminanceToAlpha. A values list of the wrong length is the identity, with a warning, as in Chrome and
// resvg. A type that is none of these is as if not specified (SVG 2, 6.7): matrix, its lacuna value.
std::string run_color_matrix(const PrimitiveCall& call) {
  std::string_view type = call.node.attribute("type") ? attribute(call.node, "type") : "matrix";
  if (type != "matrix" && type != "saturate" && type != "hueRotate" && type != "luminanceToAlpha") {
    call.diagnostics.warnings.push_back(name_of(call) + " type '" + std::string(type) +
                                        "' is not valid; matrix is used");
    type = "matrix";
  }
  const pugi::xml_attribute values = call.node.attribute("values");
  const NumberList list = parse_number_list(values.value());
  const bool usable = values && list.complete;
  ColorMatrix matrix = identity_color_matrix();
  const auto warn = [&](const std::string& what) {
    call.diagnostics.warnings.push_back(name_of(call) + " " + what + "; the identity is used");
  };
  if (type == "matrix") {
    if (usable && list.values.size() == 20) {
      std::copy(list.values.begin(), list.values.end(), matrix.begin());
    } else if (values) {
      warn("values needs 20 numbers");
    }
  } else if (type == "saturate") {
    if (usable && list.values.size() == 1) {
      matrix = saturate_matrix(list.values[0]);
    } else if (values) {
      warn("values needs one number for saturate");
    }
  } else if (type == "hueRotate") {
    if (usable && list.values.size() == 1) {
      matrix = hue_rotate_matrix(list.values[0]);
    } else if (values) {
      warn("values needs one number for hueRotate");
    }
  } else {
    matrix = luminance_to_alpha_matrix();
  }
  // A transparent pixel stays transparent unless the alpha row adds a constant.
  call.out.extent =
      (matrix[19] <= 0.0 ? ink_of(*call.in, call.subregion) : call.subregion).intersect(call.needed);
  color_matrix(*call.in, matrix, call.out.extent, call.out);
  return {};
}

// feComponentTransfer (9.10): the last feFuncR/G/B/A child of each kind counts.
std::string run_component_transfer(const PrimitiveCall& call) {
  TransferFunctions functions;
  static constexpr std::array<std::string_view, 4> kChildren{"feFuncR", "feFuncG", "feFuncB", "feFuncA"};
  for (pugi::xml_node child = call.node.first_child(); child; child = child.next_sibling()) {
    const auto slot = std::find(kChildren.begin(), kChildren.end(), local_name(child));
    if (slot == kChildren.end()) continue;
    TransferFunction f;
    const std::string_view type = attribute(child, "type");
    const auto number = [&](const char* name, double fallback) {
      return number_attribute(child, name, fallback).value_or(fallback);
    };
    if (type == "table" || type == "discrete") {
      f.type = type == "table" ? TransferFunction::Type::kTable : TransferFunction::Type::kDiscrete;
      // A list that is not all numbers is as if not specified: empty, which is the identity (9.10).
      const NumberList table = parse_number_list(attribute(child, "tableValues"));
      if (table.complete) {
        f.table_values = table.values;
      } else {
        call.diagnostics.warnings.push_back("<" + std::string(local_name(child)) + "> tableValues '" +
                                            std::string(attribute(child, "tableValues")) +
                                            "' is not a list of numbers; identity used");
      }
    } else if (type == "linear") {
      f.type = TransferFunction::Type::kLinear;
      f.slope = number("slope", 1.0);
      f.intercept = number("intercept", 0.0);
    } else if (type == "gamma") {
      f.type = TransferFunction::Type::kGamma;
      f.amplitude = number("amplitude", 1.0);
      f.exponent = number("exponent", 1.0);
      f.offset = number("offset", 0.0);
    } else if (type != "identity") {
      // An invalid type is an error in the attribute; the function then acts as the identity (as in
      // Chrome and resvg).
      call.diagnostics.warnings.push_back("<" + std::string(local_name(child)) + "> type '" +
                                          std::string(type) + "' is not valid; identity used");
    }
    functions[static_cast<std::size_t>(slot - kChildren.begin())] = std::move(f);
  }
  // A transparent pixel stays transparent unless the alpha function maps 0 above 0.
  call.out.extent = (functions[3].apply(0.0) > 0.0 ? call.subregion : ink_of(*call.in, call.subregion))
                        .intersect(call.needed);
  component_transfer(*call.in, functions, call.out.extent, call.out);
  return {};
}

// feTile (9.20).
std::string run_tile(const PrimitiveCall& call) {
  tile(*call.in, call.in_subregion, call.subregion, call.out);
  return {};
}

// feImage (9.14): drawn by the document (FilterEnvironment::draw_fe_image).
std::string run_image(const PrimitiveCall& call) {
  if (call.environment.draw_fe_image) {
    call.environment.draw_fe_image(call.node, call.space, call.user_subregion, call.subregion, call.out);
    convert_color_space(call.out, ColorSpace::kSrgb, call.color_space);
  }
  return {};
}

// feTurbulence (9.26), no input: the noise is a function of user-space position (turbulence.h).
std::string run_turbulence(const PrimitiveCall& call) {
  std::string error;
  const std::optional<TurbulenceParams> params = read_turbulence(call.node, error);
  if (!params) return error;
  // Noise is a function of position alone: only the needed pixels are computed (the stitching tile stays
  // the subregion).
  call.out.extent = call.subregion.intersect(call.needed);
  render_turbulence(*params, call.space, call.subregion, call.out, call.needed);
  return {};
}

// feMorphology (9.21).
std::string run_morphology(const PrimitiveCall& call) {
  std::string error;
  const std::optional<MorphologyParams> params = read_morphology(call.node, error);
  if (!params) return error;
  // The window reads the input where it exists, beyond this primitive's subregion too (morphology.h);
  // only the needed pixels are computed.
  call.out.extent = render_morphology(*params, call.space, call.subregion, *call.in, call.out,
                                      call.in_subregion, call.needed);
  return {};
}

// kernelUnitLength is read and checked by the kernels, then approximated at device resolution: say so.
void warn_kernel_unit_length(const std::optional<NumberPair>& kernel_unit_length, Diagnostics& diagnostics) {
  if (kernel_unit_length) diagnostics.unsupported("kernelUnitLength (approximated at device resolution)");
}

// feConvolveMatrix (9.10).
std::string run_convolve_matrix(const PrimitiveCall& call) {
  std::string error;
  const std::optional<ConvolveMatrixParams> params = read_convolve_matrix(call.node, error);
  if (!params) return error;
  warn_kernel_unit_length(params->kernel_unit_length, call.diagnostics);
  // Only the needed pixels (input_needed grew the input's needed pixels by the kernel's reach).
  // edgeMode extends the input at its own subregion's edge, beyond this primitive's (convolve_matrix.h).
  render_convolve_matrix(*params, call.space, call.subregion, *call.in, call.out, call.needed,
                         call.in_subregion);
  return {};
}

// feDisplacementMap (9.12): in displaced by the channels of in2.
std::string run_displacement_map(const PrimitiveCall& call) {
  std::string error;
  const std::optional<DisplacementMapParams> params = read_displacement_map(call.node, error);
  if (!params) return error;
  render_displacement_map(*params, call.space, call.subregion, *call.in, *call.in2, call.out);
  return {};
}

// lighting-color (initial: white) in the primitive's colour space, for the two lighting primitives.
std::array<float, 3> lighting_color(const PrimitiveCall& call) {
  const FilterColor color = primitive_color(call.node, "lighting-color", "", call.color_space,
                                            call.environment, call.diagnostics, Color{1.0, 1.0, 1.0, 1.0});
  return {color.r, color.g, color.b};
}

// feDiffuseLighting (9.11) and feSpecularLighting (9.22): the alpha of in as a height map, lit.
std::string run_diffuse_lighting(const PrimitiveCall& call) {
  std::string error;
  const std::optional<DiffuseLightingParams> params = read_diffuse_lighting(call.node, error);
  if (!params) return error;
  warn_kernel_unit_length(params->kernel_unit_length, call.diagnostics);
  render_diffuse_lighting(*params, call.space, call.subregion, *call.in, lighting_color(call), call.out,
                          call.needed, call.in_subregion);
  return {};
}

std::string run_specular_lighting(const PrimitiveCall& call) {
  std::string error;
  const std::optional<SpecularLightingParams> params = read_specular_lighting(call.node, error);
  if (!params) return error;
  warn_kernel_unit_length(params->kernel_unit_length, call.diagnostics);
  render_specular_lighting(*params, call.space, call.subregion, *call.in, lighting_color(call), call.out,
                           call.needed, call.in_subregion);
  return {};
}

// The table: every primitive of Filter Effects 1 and feDropShadow.
// writes_whole_extent and in_place (primitive_table.h) are set where the kernel's loops make them true.
constexpr std::array<PrimitiveEntry, 17> kPrimitives{{
    {"feFlood", PrimitiveInputs::kNone, run_flood, true, false},
    {"feOffset", PrimitiveInputs::kIn, run_offset, true, true},
    {"feGaussianBlur", PrimitiveInputs::kIn, run_gaussian_blur, true, false},
    {"feDropShadow", PrimitiveInputs::kIn, run_drop_shadow, false, false},
    {"feComposite", PrimitiveInputs::kInAndIn2, run_composite, true, true},
    {"feMerge", PrimitiveInputs::kMergeNodes, run_merge, true, true},
    {"feBlend", PrimitiveInputs::kInAndIn2, run_blend, true, true},
    {"feColorMatrix", PrimitiveInputs::kIn, run_color_matrix, true, true},
    {"feComponentTransfer", PrimitiveInputs::kIn, run_component_transfer, true, true},
    {"feTile", PrimitiveInputs::kIn, run_tile, false, false},
    {"feImage", PrimitiveInputs::kNone, run_image, false, false},
    {"feTurbulence", PrimitiveInputs::kNone, run_turbulence, false, false},
    {"feMorphology", PrimitiveInputs::kIn, run_morphology, false, false},
    {"feConvolveMatrix", PrimitiveInputs::kIn, run_convolve_matrix, false, false},
    {"feDisplacementMap", PrimitiveInputs::kInAndIn2, run_displacement_map, false, false},
    {"feDiffuseLighting", PrimitiveInputs::kIn, run_diffuse_lighting, false, false},
    {"feSpecularLighting", PrimitiveInputs::kIn, run_specular_lighting, false, false},
}};

constexpr std::array<std::string_view, 17> kAllPrimitives{"feBlend",
                                                          "feColorMatrix",
                                                          "feComponentTransfer",
                                                          "feComposite",
                                                          "feConvolveMatrix",
                                                          "feDiffuseLighting",
                                                          "feDisplacementMap",
                                                          "feDropShadow",
                                                          "feFlood",
                                                          "feGaussianBlur",
                                                          "feImage",
                                                          "feMerge",
                                                          "feMorphology",
                                                          "feOffset",
                                                          "feSpecularLighting",
                                                          "feTile",
                                                          "feTurbulence"};

}  // namespace

const PrimitiveEntry* find_primitive(std::string_view name) noexcept {
  for (const PrimitiveEntry& entry : kPrimitives) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

bool is_filter_primitive(std::string_view name) noexcept {
  return std::find(kAllPrimitives.begin(), kAllPrimitives.end(), name) != kAllPrimitives.end();
}

FilterColor primitive_color(const pugi::xml_node& node, std::string_view color_name,
                            std::string_view opacity_name, ColorSpace space,
                            const FilterEnvironment& environment, Diagnostics& diagnostics,
                            const Color& initial) {
  const css::StyleSheets* sheets = environment.style_sheets;
  Color color = initial;
  const auto is_keyword = [](std::string_view text, std::string_view keyword) {
    text = trim_whitespace(text);
    return text.size() == keyword.size() &&
           std::equal(text.begin(), text.end(), keyword.begin(),
                      [](char a, char b) { return std::tolower(a) == std::tolower(b); });
  };
  // `inherit` (CSS Cascade 4, 7.3) takes the parent's computed value: flood-color and lighting-color are
  // not inherited properties, so that is the parent's own declaration, else the initial value.
  // An invalid declaration is not part of the cascade (CSS Syntax 3, 9.1 / CSS Cascade 4, 4.1): the next
  // valid one (a presentation attribute included) applies, and the invalid one is named once.
  // `initial` and `unset` (and `revert`, which is `unset` in an author sheet) give the initial value of a
  // property that is not inherited; `unset` is also what a failed var() substitution leaves (CSS
  // Variables 1, 3.1), so it must win over the declarations below it.
  const auto is_initial = [&](std::string_view text) {
    return is_keyword(text, "initial") || is_keyword(text, "unset") || is_keyword(text, "revert");
  };
  const auto valid_color = [&](std::string_view text) {
    return is_keyword(text, "inherit") || is_keyword(text, "currentColor") || is_initial(text) ||
           parse_color(trim_whitespace(text)).is_ok();
  };
  std::optional<std::string> value = cascaded_value(node, color_name, sheets, valid_color);
  if (const std::optional<std::string> unchecked = cascaded_value(node, color_name, sheets);
      unchecked && unchecked != value) {
    diagnostics.warnings.push_back("<" + std::string(local_name(node)) + "> " + std::string(color_name) +
                                   " '" + *unchecked + "' is not a colour; ignored");
  }
  for (pugi::xml_node scope = node.parent(); value && is_keyword(*value, "inherit"); scope = scope.parent()) {
    if (!scope || scope.type() != pugi::node_element) {
      value.reset();
      break;
    }
    value = cascaded_value(scope, color_name, sheets, valid_color);
  }
  if (value && is_initial(*value)) value.reset();
  if (value && is_keyword(*value, "currentColor")) {
    // currentColor: the `color` property where the primitive is (inherited through its ancestors); its
    // initial value is black (CSS Color 4, 3.1: CanvasText, black in a document without a colour scheme).
    value = "black";
    for (pugi::xml_node scope = node; scope; scope = scope.parent()) {
      if (std::optional<std::string> inherited = cascaded_value(scope, "color", sheets);
          inherited && trim_whitespace(*inherited) != "inherit") {
        value = std::move(inherited);
        break;
      }
    }
  }
  if (value) {
    const Result<Color> parsed = parse_color(trim_whitespace(*value));
    if (parsed) {
      color = *parsed;
    } else {
      diagnostics.warnings.push_back("<" + std::string(local_name(node)) + "> " + std::string(color_name) +
                                     " '" + *value + "' is not a colour; its initial value is used");
    }
  }
  double alpha = color.a;
  if (!opacity_name.empty()) {
    if (const std::optional<std::string> opacity = cascaded_value(node, opacity_name, sheets)) {
      std::string_view text = trim_whitespace(*opacity);
      const bool percent = !text.empty() && text.back() == '%';
      if (percent) text.remove_suffix(1);
      const std::optional<double> number = parse_number(text);
      if (number && std::isfinite(*number)) {
        alpha *= std::clamp(percent ? *number / 100.0 : *number, 0.0, 1.0);
      } else {
        diagnostics.warnings.push_back("<" + std::string(local_name(node)) + "> " +
                                       std::string(opacity_name) + " '" + *opacity +
                                       "' is not a number; 1 used");
      }
    }
  }
  FilterColor result{static_cast<float>(color.r), static_cast<float>(color.g), static_cast<float>(color.b),
                     static_cast<float>(alpha)};
  if (space == ColorSpace::kLinearRgb) {
    result.r = srgb_to_linear(result.r);
    result.g = srgb_to_linear(result.g);
    result.b = srgb_to_linear(result.b);
  }
  return result;
}

ColorSpace color_interpolation_filters(const pugi::xml_node& node,
                                       const css::StyleSheets* style_sheets) noexcept {
  for (pugi::xml_node scope = node; scope && scope.type() == pugi::node_element; scope = scope.parent()) {
    const std::optional<std::string> value =
        cascaded_value(scope, "color-interpolation-filters", style_sheets);
    if (!value) continue;
    const std::string_view text = trim_whitespace(*value);
    if (css::ascii_equal_ignoring_case(text, "inherit")) continue;
    if (css::ascii_equal_ignoring_case(text, "sRGB")) return ColorSpace::kSrgb;
    if (css::ascii_equal_ignoring_case(text, "linearRGB") || css::ascii_equal_ignoring_case(text, "auto"))
      return ColorSpace::kLinearRgb;
  }
  return ColorSpace::kLinearRgb;
}

PixelRect input_needed(const pugi::xml_node& node, const FilterSpace& space, PixelRect result_needed,
                       PixelRect everything) {
  const std::string_view name = local_name(node);
  static constexpr std::array<std::string_view, 5> kSamePixel{"feComposite", "feMerge", "feBlend",
                                                              "feColorMatrix", "feComponentTransfer"};
  if (std::find(kSamePixel.begin(), kSamePixel.end(), name) != kSamePixel.end()) return result_needed;
  if (name == "feOffset") {
    const auto [shift_x, shift_y] = offset_pixels(node, space);
    return result_needed.moved(-shift_x, -shift_y);
  }
  if (name == "feGaussianBlur" || name == "feDropShadow") {
    const bool shadow = name == "feDropShadow";
    const std::pair<double, double> sigma = deviation_numbers(node, shadow ? 2.0 : 0.0);
    const pugi::xml_attribute edge = node.attribute("edgeMode");
    const std::optional<EdgeMode> mode = edge && !shadow ? parse_edge_mode(edge.value()) : EdgeMode::kNone;
    if (mode && *mode != EdgeMode::kNone) return everything;
    PixelRect wanted = result_needed;
    if (shadow) {
      // The source where it is (merged on top) and the shadow's source, moved back by the offset.
      const double dx = number_or_initial(node, "dx", 2.0), dy = number_or_initial(node, "dy", 2.0);
      wanted =
          wanted.unite(result_needed.moved(-whole_pixel_offset(space.x_to_pixels(space.user_width(dx))),
                                           -whole_pixel_offset(space.y_to_pixels(space.user_height(dy)))));
    }
    return wanted.grown(blur_reach(space.x_to_pixels(space.user_width(sigma.first))),
                        blur_reach(space.y_to_pixels(space.user_height(sigma.second))));
  }
  // The kernels that read a neighbourhood (their windows stop at the input's edge, which the needed
  // pixels' neighbourhoods do not reach further than this): grown by the neighbourhood.
  std::string ignored;
  if (name == "feMorphology") {
    const std::optional<MorphologyParams> params = read_morphology(node, ignored);
    if (!params) return everything;
    if (morphology_is_identity(*params)) return result_needed;  // the input itself
    const auto pixels = [](double v) {
      return static_cast<long long>(std::ceil(std::min(std::fabs(v), 1e9))) + 1;
    };
    return result_needed.grown(pixels(space.x_to_pixels(space.user_width(params->radius_x))),
                               pixels(space.y_to_pixels(space.user_height(params->radius_y))));
  }
  if (name == "feConvolveMatrix") {
    const std::optional<ConvolveMatrixParams> params = read_convolve_matrix(node, ignored);
    // edgeMode wrap reads across the subregion, from its far side: all of the input.
    if (!params || params->edge_mode == EdgeMode::kWrap) return everything;
    return result_needed.grown(std::max(params->target_x, params->order_x - 1 - params->target_x),
                               std::max(params->target_y, params->order_y - 1 - params->target_y));
  }
  if (name == "feDiffuseLighting" || name == "feSpecularLighting") return result_needed.grown(1, 1);
  if (name == "feDisplacementMap") {
    // in is read up to |scale| / 2 away (the map's channel minus one half, times scale); in2 at the pixel.
    const std::optional<DisplacementMapParams> params = read_displacement_map(node, ignored);
    if (!params) return everything;
    const auto pixels = [](double v) {
      return static_cast<long long>(std::ceil(std::min(std::fabs(v), 2e9))) + 1;
    };
    return result_needed.grown(pixels(space.x_to_pixels(space.user_width(params->scale)) / 2.0),
                               pixels(space.y_to_pixels(space.user_height(params->scale)) / 2.0));
  }
  return everything;
}

std::optional<std::pair<double, double>> primitive_reach(const pugi::xml_node& node,
                                                         const FilterSpace& space) {
  const std::string_view name = local_name(node);
  static constexpr std::array<std::string_view, 7> kPerPixel{
      "feFlood", "feComposite", "feMerge", "feBlend", "feColorMatrix", "feImage", "feComponentTransfer"};
  if (std::find(kPerPixel.begin(), kPerPixel.end(), name) != kPerPixel.end()) return std::pair{0.0, 0.0};
  // Noise depends on position only, but stitched noise on its tile, the whole subregion: kept whole.
  if (name == "feTurbulence") {
    if (std::string_view(node.attribute("stitchTiles").value()) == "stitch") return std::nullopt;
    return std::pair{0.0, 0.0};
  }
  std::string ignored;
  if (name == "feMorphology") {
    // The window reaches the radius (rounded to whole pixels: half a pixel more, which the caller's margin
    // covers); a negative radius, or both zero, is the input itself.
    const std::optional<MorphologyParams> params = read_morphology(node, ignored);
    if (!params || morphology_is_identity(*params)) return std::pair{0.0, 0.0};
    return std::pair{std::fabs(space.user_width(params->radius_x)),
                     std::fabs(space.user_height(params->radius_y))};
  }
  if (name == "feDisplacementMap") {
    // A pixel reads `in` at most |scale| / 2 away along each axis (scale times a channel minus one half).
    const std::optional<DisplacementMapParams> params = read_displacement_map(node, ignored);
    if (!params) return std::pair{0.0, 0.0};
    return std::pair{std::fabs(space.user_width(params->scale)) / 2.0,
                     std::fabs(space.user_height(params->scale)) / 2.0};
  }
  // feConvolveMatrix and the lighting primitives reach a number of filter pixels (the kernel's extent, the
  // surface normal's neighbours), not of user units, and feTile depends on where its input lies: unknown
  // here, the caller keeps the whole region.
  double x = 0.0, y = 0.0;
  if (name == "feGaussianBlur" || name == "feDropShadow") {
    const std::pair<double, double> sigma = deviation_numbers(node, name == "feDropShadow" ? 2.0 : 0.0);
    x += 3.0 * std::fabs(space.user_width(sigma.first)) + 1.0;
    y += 3.0 * std::fabs(space.user_height(sigma.second)) + 1.0;
  }
  if (name == "feOffset" || name == "feDropShadow") {
    const double fallback = name == "feDropShadow" ? 2.0 : 0.0;
    x += std::fabs(space.user_width(number_or_initial(node, "dx", fallback)));
    y += std::fabs(space.user_height(number_or_initial(node, "dy", fallback)));
    return std::pair{x, y};
  }
  if (name == "feGaussianBlur") return std::pair{x, y};
  return std::nullopt;
}

}  // namespace curvescan::svg::detail::filter
