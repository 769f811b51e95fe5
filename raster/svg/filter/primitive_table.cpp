// The primitive table (primitive_table.h): for each primitive, a reader of its attributes into values
// (Filter Effects 1, section 9, one subsection per primitive; run once per filter, resolved_filter.h) and an
// adapter that places those values for the filter image and calls the pixel function of its own file.
#include "primitive_table.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <tuple>
#include <variant>

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
#include "resolved_filter.h"
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

std::string name_of(const pugi::xml_node& node) {
  return "<" + std::string(local_name(node)) + ">";
}

// The warning channel of a reading.
std::function<void(const std::string&)> warner(const PrimitiveReading& reading) {
  return [&reading](const std::string& message) { reading.diagnostics.warnings.push_back(message); };
}

// A primitive whose pixel file's reader gave no values: NoParams, with the error it said.
PrimitiveParams in_error(const PrimitiveReading& reading) {
  if (reading.error.empty()) reading.error = name_of(reading.node) + " is in error";
  return NoParams{};
}

// What a pixel file's reader gave: its values, or NoParams with the error it said.
template <class Values>
PrimitiveParams values_or_error(std::optional<Values> values, const PrimitiveReading& reading) {
  if (values) return std::move(*values);
  return in_error(reading);
}

// feMerge and feTile have no values of their own to read.
PrimitiveParams read_nothing(const PrimitiveReading& /*reading*/) {
  return NoParams{};
}

// The input's ink inside the subregion: where a primitive that keeps transparent pixels transparent can
// have a result (FilterImage::extent).
PixelRect ink_of(const FilterImage& image, PixelRect subregion) noexcept {
  return image.extent.intersect(image.bounds()).intersect(subregion);
}

// feFlood (9.12).
PrimitiveParams read_flood_primitive(const PrimitiveReading& reading) {
  return FloodParams{primitive_color(reading.node, "flood-color", "flood-opacity", reading.color_space,
                                     reading.style_sheets, reading.diagnostics)};
}

void run_flood(const PrimitiveCall& call) {
  const FilterColor color = std::get<FloodParams>(call.params).color;
  call.out.extent = color.a > 0.0f ? call.subregion.intersect(call.needed) : PixelRect{};
  flood(color, call.out.extent, call.out);
}

// A number attribute that is absent or not a number counts as `fallback` (SVG 2, 6.7: an invalid value is
// as if the attribute were not specified); `warn` is told about a value that is present but unusable.
double number_or_initial(const pugi::xml_node& node, const char* name, double fallback,
                         const std::function<void(const std::string&)>& warn) {
  const std::optional<double> value = number_attribute(node, name, fallback);
  if (!value) {
    warn("<" + std::string(local_name(node)) + "> " + name + " '" + node.attribute(name).value() +
         "' is not a number; " + std::to_string(static_cast<int>(fallback)) + " is used");
  }
  return value.value_or(fallback);
}

// feOffset's dx, dy (9.17) in whole filter pixels.
std::pair<long long, long long> offset_pixels(const OffsetParams& params, const FilterSpace& space) {
  return std::pair{whole_pixel_offset(space.x_to_pixels(space.user_width(params.dx))),
                   whole_pixel_offset(space.y_to_pixels(space.user_height(params.dy)))};
}

// feOffset (9.17): dx, dy in primitiveUnits (a value that is not a number counts as 0), rounded to whole
// filter pixels (offset.h).
PrimitiveParams read_offset_primitive(const PrimitiveReading& reading) {
  const auto warn = warner(reading);
  return OffsetParams{number_or_initial(reading.node, "dx", 0.0, warn),
                      number_or_initial(reading.node, "dy", 0.0, warn)};
}

void run_offset(const PrimitiveCall& call) {
  const auto [shift_x, shift_y] = offset_pixels(std::get<OffsetParams>(call.params), call.space);
  call.out.extent = ink_of(*call.in, call.in->bounds())
                        .moved(shift_x, shift_y)
                        .intersect(call.subregion)
                        .intersect(call.needed);
  offset(*call.in, call.out.extent, shift_x, shift_y, call.out);
}

// stdDeviation (σx, σy) in primitive units: `fallback` when absent. Filter Effects 1, 9.13: "A negative
// value or a value of zero disables the effect of the given filter primitive (i.e., the result is the filter
// input image)"; a malformed value (not one or two numbers) is as if not specified, which for
// feGaussianBlur is 0 too. Both give {0, 0}, with a warning.
std::pair<double, double> deviation_numbers(const pugi::xml_node& node, double fallback,
                                            const std::function<void(const std::string&)>& warn) {
  const std::optional<std::pair<double, double>> sigma = number_pair(node, "stdDeviation", fallback);
  if (sigma && sigma->first >= 0.0 && sigma->second >= 0.0) return *sigma;
  warn("<" + std::string(local_name(node)) + "> stdDeviation '" + node.attribute("stdDeviation").value() +
       "' is not one or two non-negative numbers; the blur is disabled");
  return {0.0, 0.0};
}

// stdDeviation in pixels along x and y.
std::pair<double, double> deviation_pixels(const FilterSpace& space, double sigma_x, double sigma_y) {
  return std::pair{space.x_to_pixels(space.user_width(sigma_x)),
                   space.y_to_pixels(space.user_height(sigma_y))};
}

// feGaussianBlur (9.13).
PrimitiveParams read_gaussian_blur_primitive(const PrimitiveReading& reading) {
  BlurParams params;
  std::tie(params.sigma_x, params.sigma_y) = deviation_numbers(reading.node, 0.0, warner(reading));
  if (const pugi::xml_attribute edge = reading.node.attribute("edgeMode")) {
    const std::optional<EdgeMode> parsed = parse_edge_mode(edge.value());
    if (!parsed) {
      reading.diagnostics.warnings.push_back(name_of(reading.node) + " edgeMode '" + edge.value() +
                                             "' is not valid; none used");
    } else {
      params.edge_mode = *parsed;
    }
  }
  return params;
}

void run_gaussian_blur(const PrimitiveCall& call) {
  const BlurParams& params = std::get<BlurParams>(call.params);
  const auto [sigma_x, sigma_y] = deviation_pixels(call.space, params.sigma_x, params.sigma_y);
  const EdgeMode mode = params.edge_mode;
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
}

// feDropShadow (Filter Effects 1, 9.11): stdDeviation, dx and dy default to 2.
PrimitiveParams read_drop_shadow_primitive(const PrimitiveReading& reading) {
  ShadowParams params;
  const auto warn = warner(reading);
  std::tie(params.sigma_x, params.sigma_y) = deviation_numbers(reading.node, 2.0, warn);
  params.dx = number_or_initial(reading.node, "dx", 2.0, warn);
  params.dy = number_or_initial(reading.node, "dy", 2.0, warn);
  params.color = primitive_color(reading.node, "flood-color", "flood-opacity", reading.color_space,
                                 reading.style_sheets, reading.diagnostics);
  return params;
}

void run_drop_shadow(const PrimitiveCall& call) {
  const ShadowParams& values = std::get<ShadowParams>(call.params);
  DropShadowParams params;
  std::tie(params.sigma_x, params.sigma_y) = deviation_pixels(call.space, values.sigma_x, values.sigma_y);
  params.dx = call.space.x_to_pixels(call.space.user_width(values.dx));
  params.dy = call.space.y_to_pixels(call.space.user_height(values.dy));
  params.color = values.color;
  drop_shadow(*call.in, params, call.subregion, call.out, call.needed);
}

// feComposite (9.9): operator (default over), k1 to k4 (default 0; one that is not a number is an error).
PrimitiveParams read_composite_primitive(const PrimitiveReading& reading) {
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
  if (const pugi::xml_attribute op = reading.node.attribute("operator")) {
    const auto found = std::find_if(kOperators.begin(), kOperators.end(),
                                    [&](const auto& entry) { return entry.first == op.value(); });
    if (found == kOperators.end()) {
      reading.diagnostics.warnings.push_back(name_of(reading.node) + " operator '" + op.value() +
                                             "' is not valid; over used");
    } else {
      params.op = found->second;
    }
  }
  double* k[4] = {&params.k1, &params.k2, &params.k3, &params.k4};
  const char* names[4] = {"k1", "k2", "k3", "k4"};
  for (int i = 0; i < 4; ++i) {
    const std::optional<double> value = number_attribute(reading.node, names[i], 0.0);
    if (!value) {
      reading.error = name_of(reading.node) + " " + names[i] + " is not a number";
      return NoParams{};
    }
    *k[i] = *value;
  }
  return params;
}

void run_composite(const PrimitiveCall& call) {
  const CompositeParams& params = std::get<CompositeParams>(call.params);
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
}

// feMerge (9.16).
void run_merge(const PrimitiveCall& call) {
  PixelRect area;
  for (const FilterImage* input : call.merge_inputs) area = area.unite(ink_of(*input, call.subregion));
  call.out.extent = area.intersect(call.needed);
  if (call.merge_other_space.empty()) {
    merge(call.merge_inputs, area, call.out);
  } else {
    merge(call.merge_inputs, call.merge_other_space, call.color_space, area, call.out);
  }
}

// feBlend (9.6): mode, default normal.
PrimitiveParams read_blend_primitive(const PrimitiveReading& reading) {
  BlendParams params;
  if (const pugi::xml_attribute value = reading.node.attribute("mode")) {
    const std::optional<BlendMode> parsed = parse_blend_mode(value.value());
    if (!parsed) {
      reading.diagnostics.warnings.push_back(name_of(reading.node) + " mode '" + value.value() +
                                             "' is not valid; normal used");
    } else {
      params.mode = *parsed;
    }
  }
  return params;
}

void run_blend(const PrimitiveCall& call) {
  // Every mode blends two transparent pixels into a transparent one.
  call.out.extent =
      ink_of(*call.in, call.subregion).unite(ink_of(*call.in2, call.subregion)).intersect(call.needed);
  blend(*call.in, *call.in2, std::get<BlendParams>(call.params).mode, call.out.extent, call.out);
}

// feColorMatrix (9.8): type matrix (default) with 20 values, saturate (default 1), hueRotate (default 0),
// luminanceToAlpha. A values list of the wrong length is the identity, with a warning, as in Chrome and
// resvg. A type that is none of these is as if not specified (SVG 2, 6.7): matrix, its lacuna value.
PrimitiveParams read_color_matrix_primitive(const PrimitiveReading& reading) {
  const pugi::xml_node& node = reading.node;
  std::string_view type = node.attribute("type") ? attribute(node, "type") : "matrix";
  if (type != "matrix" && type != "saturate" && type != "hueRotate" && type != "luminanceToAlpha") {
    reading.diagnostics.warnings.push_back(name_of(node) + " type '" + std::string(type) +
                                           "' is not valid; matrix is used");
    type = "matrix";
  }
  const pugi::xml_attribute values = node.attribute("values");
  const NumberList list = parse_number_list(values.value());
  const bool usable = values && list.complete;
  ColorMatrix matrix = identity_color_matrix();
  const auto warn = [&](const std::string& what) {
    reading.diagnostics.warnings.push_back(name_of(node) + " " + what + "; the identity is used");
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
  return ColorMatrixParams{matrix};
}

void run_color_matrix(const PrimitiveCall& call) {
  const ColorMatrix& matrix = std::get<ColorMatrixParams>(call.params).matrix;
  // A transparent pixel stays transparent unless the alpha row adds a constant.
  call.out.extent =
      (matrix[19] <= 0.0 ? ink_of(*call.in, call.subregion) : call.subregion).intersect(call.needed);
  color_matrix(*call.in, matrix, call.out.extent, call.out);
}

// feComponentTransfer (9.10): the last feFuncR/G/B/A child of each kind counts.
PrimitiveParams read_component_transfer_primitive(const PrimitiveReading& reading) {
  TransferFunctions functions;
  static constexpr std::array<std::string_view, 4> kChildren{"feFuncR", "feFuncG", "feFuncB", "feFuncA"};
  for (pugi::xml_node child = reading.node.first_child(); child; child = child.next_sibling()) {
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
        reading.diagnostics.warnings.push_back("<" + std::string(local_name(child)) + "> tableValues '" +
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
      reading.diagnostics.warnings.push_back("<" + std::string(local_name(child)) + "> type '" +
                                             std::string(type) + "' is not valid; identity used");
    }
    functions[static_cast<std::size_t>(slot - kChildren.begin())] = std::move(f);
  }
  return TransferParams{std::move(functions)};
}

void run_component_transfer(const PrimitiveCall& call) {
  const TransferFunctions& functions = std::get<TransferParams>(call.params).functions;
  // A transparent pixel stays transparent unless the alpha function maps 0 above 0.
  call.out.extent = (functions[3].apply(0.0) > 0.0 ? call.subregion : ink_of(*call.in, call.subregion))
                        .intersect(call.needed);
  component_transfer(*call.in, functions, call.out.extent, call.out);
}

// feTile (9.20).
void run_tile(const PrimitiveCall& call) {
  tile(*call.in, call.in_subregion, call.subregion, call.out);
}

// feImage (9.14): href to an element of the document (drawn with the style it inherits from its own
// ancestors) or to an image (placed with preserveAspectRatio); drawn by the document
// (FilterEnvironment::draw_fe_image). A reference to nothing is said here, once.
PrimitiveParams read_image_primitive(const PrimitiveReading& reading) {
  ImageParams params;
  pugi::xml_attribute href = reading.node.attribute("href");
  if (!href) href = reading.node.attribute("xlink:href");
  params.reference = href.value();
  if (params.reference.empty()) return params;
  if (params.reference.front() == '#') {
    const auto found = reading.ids.find(params.reference.substr(1));
    if (found == reading.ids.end()) {
      reading.diagnostics.warnings.push_back("<feImage> refers to '" + params.reference +
                                             "', which does not exist");
    } else {
      params.target = found->second;
      params.target_parent_style =
          std::make_shared<const ComputedStyle>(reading.style_of(found->second.parent()));
    }
    return params;
  }
  if (const pugi::xml_attribute aspect = reading.node.attribute("preserveAspectRatio")) {
    const Result<PreserveAspectRatio> parsed = parse_preserve_aspect_ratio(aspect.value());
    if (parsed) {
      params.aspect = *parsed;
    } else {
      reading.diagnostics.warnings.push_back(parsed.error().message);
    }
  }
  params.pixelated = reading.style_of(reading.node).pixelated_images;
  return params;
}

void run_image(const PrimitiveCall& call) {
  if (call.environment.draw_fe_image) {
    call.environment.draw_fe_image(std::get<ImageParams>(call.params), call.space, call.user_subregion,
                                   call.subregion, call.out);
    convert_color_space(call.out, ColorSpace::kSrgb, call.color_space);
  }
}

// feTurbulence (9.26), no input: the noise is a function of user-space position (turbulence.h).
PrimitiveParams read_turbulence_primitive(const PrimitiveReading& reading) {
  return values_or_error(read_turbulence(reading.node, reading.error), reading);
}

void run_turbulence(const PrimitiveCall& call) {
  // Noise is a function of position alone: only the needed pixels are computed (the stitching tile stays
  // the subregion).
  call.out.extent = call.subregion.intersect(call.needed);
  render_turbulence(std::get<TurbulenceParams>(call.params), call.space, call.subregion, call.out,
                    call.needed);
}

// feMorphology (9.21).
PrimitiveParams read_morphology_primitive(const PrimitiveReading& reading) {
  return values_or_error(read_morphology(reading.node, reading.error), reading);
}

void run_morphology(const PrimitiveCall& call) {
  // The window reads the input where it exists, beyond this primitive's subregion too (morphology.h);
  // only the needed pixels are computed.
  call.out.extent = render_morphology(std::get<MorphologyParams>(call.params), call.space, call.subregion,
                                      *call.in, call.out, call.in_subregion, call.needed);
}

// kernelUnitLength is read and checked by the kernels, then approximated at device resolution: say so.
void warn_kernel_unit_length(const std::optional<NumberPair>& kernel_unit_length, Diagnostics& diagnostics) {
  if (kernel_unit_length) diagnostics.unsupported("kernelUnitLength (approximated at device resolution)");
}

// feConvolveMatrix (9.10).
PrimitiveParams read_convolve_matrix_primitive(const PrimitiveReading& reading) {
  std::optional<ConvolveMatrixParams> params = read_convolve_matrix(reading.node, reading.error);
  if (params) warn_kernel_unit_length(params->kernel_unit_length, reading.diagnostics);
  return values_or_error(std::move(params), reading);
}

void run_convolve_matrix(const PrimitiveCall& call) {
  // Only the needed pixels (input_needed grew the input's needed pixels by the kernel's reach).
  // edgeMode extends the input at its own subregion's edge, beyond this primitive's (convolve_matrix.h).
  render_convolve_matrix(std::get<ConvolveMatrixParams>(call.params), call.space, call.subregion, *call.in,
                         call.out, call.needed, call.in_subregion);
}

// feDisplacementMap (9.12): in displaced by the channels of in2.
PrimitiveParams read_displacement_map_primitive(const PrimitiveReading& reading) {
  return values_or_error(read_displacement_map(reading.node, reading.error), reading);
}

void run_displacement_map(const PrimitiveCall& call) {
  render_displacement_map(std::get<DisplacementMapParams>(call.params), call.space, call.subregion, *call.in,
                          *call.in2, call.out);
}

// lighting-color (initial: white) in the primitive's colour space, for the two lighting primitives.
std::array<float, 3> lighting_color(const PrimitiveReading& reading) {
  const FilterColor color =
      primitive_color(reading.node, "lighting-color", "", reading.color_space, reading.style_sheets,
                      reading.diagnostics, Color{1.0, 1.0, 1.0, 1.0});
  return {color.r, color.g, color.b};
}

// feDiffuseLighting (9.11) and feSpecularLighting (9.22): the alpha of in as a height map, lit.
PrimitiveParams read_diffuse_lighting_primitive(const PrimitiveReading& reading) {
  std::optional<DiffuseLightingParams> params = read_diffuse_lighting(reading.node, reading.error);
  if (!params) return in_error(reading);
  warn_kernel_unit_length(params->kernel_unit_length, reading.diagnostics);
  return DiffuseParams{std::move(*params), lighting_color(reading)};
}

void run_diffuse_lighting(const PrimitiveCall& call) {
  const DiffuseParams& params = std::get<DiffuseParams>(call.params);
  render_diffuse_lighting(params.lighting, call.space, call.subregion, *call.in, params.color, call.out,
                          call.needed, call.in_subregion);
}

PrimitiveParams read_specular_lighting_primitive(const PrimitiveReading& reading) {
  std::optional<SpecularLightingParams> params = read_specular_lighting(reading.node, reading.error);
  if (!params) return in_error(reading);
  warn_kernel_unit_length(params->kernel_unit_length, reading.diagnostics);
  return SpecularParams{std::move(*params), lighting_color(reading)};
}

void run_specular_lighting(const PrimitiveCall& call) {
  const SpecularParams& params = std::get<SpecularParams>(call.params);
  render_specular_lighting(params.lighting, call.space, call.subregion, *call.in, params.color, call.out,
                           call.needed, call.in_subregion);
}

// The table: every primitive of Filter Effects 1 and feDropShadow.
// writes_whole_extent and in_place (primitive_table.h) are set where the kernel's loops make them true.
constexpr std::array<PrimitiveEntry, 17> kPrimitives{{
    {"feFlood", PrimitiveInputs::kNone, read_flood_primitive, run_flood, true, false},
    {"feOffset", PrimitiveInputs::kIn, read_offset_primitive, run_offset, true, true},
    {"feGaussianBlur", PrimitiveInputs::kIn, read_gaussian_blur_primitive, run_gaussian_blur, true, false},
    {"feDropShadow", PrimitiveInputs::kIn, read_drop_shadow_primitive, run_drop_shadow, false, false},
    {"feComposite", PrimitiveInputs::kInAndIn2, read_composite_primitive, run_composite, true, true},
    {"feMerge", PrimitiveInputs::kMergeNodes, read_nothing, run_merge, true, true},
    {"feBlend", PrimitiveInputs::kInAndIn2, read_blend_primitive, run_blend, true, true},
    {"feColorMatrix", PrimitiveInputs::kIn, read_color_matrix_primitive, run_color_matrix, true, true},
    {"feComponentTransfer", PrimitiveInputs::kIn, read_component_transfer_primitive, run_component_transfer,
     true, true},
    {"feTile", PrimitiveInputs::kIn, read_nothing, run_tile, false, false},
    {"feImage", PrimitiveInputs::kNone, read_image_primitive, run_image, false, false},
    {"feTurbulence", PrimitiveInputs::kNone, read_turbulence_primitive, run_turbulence, false, false},
    {"feMorphology", PrimitiveInputs::kIn, read_morphology_primitive, run_morphology, false, false},
    {"feConvolveMatrix", PrimitiveInputs::kIn, read_convolve_matrix_primitive, run_convolve_matrix, false,
     false},
    {"feDisplacementMap", PrimitiveInputs::kInAndIn2, read_displacement_map_primitive, run_displacement_map,
     false, false},
    {"feDiffuseLighting", PrimitiveInputs::kIn, read_diffuse_lighting_primitive, run_diffuse_lighting, false,
     false},
    {"feSpecularLighting", PrimitiveInputs::kIn, read_specular_lighting_primitive, run_specular_lighting,
     false, false},
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
                            std::string_view opacity_name, ColorSpace space, const css::StyleSheets* sheets,
                            Diagnostics& diagnostics, const Color& initial) {
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

PixelRect input_needed(const ResolvedPrimitive& primitive, const FilterSpace& space, PixelRect result_needed,
                       PixelRect everything) {
  const std::string_view name = primitive.entry->name;
  const PrimitiveParams& values = primitive.params;
  static constexpr std::array<std::string_view, 5> kSamePixel{"feComposite", "feMerge", "feBlend",
                                                              "feColorMatrix", "feComponentTransfer"};
  if (std::find(kSamePixel.begin(), kSamePixel.end(), name) != kSamePixel.end()) return result_needed;
  if (const auto* offset = std::get_if<OffsetParams>(&values)) {
    const auto [shift_x, shift_y] = offset_pixels(*offset, space);
    return result_needed.moved(-shift_x, -shift_y);
  }
  if (const auto* blur = std::get_if<BlurParams>(&values)) {
    if (blur->edge_mode != EdgeMode::kNone) return everything;
    return result_needed.grown(blur_reach(space.x_to_pixels(space.user_width(blur->sigma_x))),
                               blur_reach(space.y_to_pixels(space.user_height(blur->sigma_y))));
  }
  if (const auto* shadow = std::get_if<ShadowParams>(&values)) {
    // The source where it is (merged on top) and the shadow's source, moved back by the offset.
    const PixelRect wanted = result_needed.unite(
        result_needed.moved(-whole_pixel_offset(space.x_to_pixels(space.user_width(shadow->dx))),
                            -whole_pixel_offset(space.y_to_pixels(space.user_height(shadow->dy)))));
    return wanted.grown(blur_reach(space.x_to_pixels(space.user_width(shadow->sigma_x))),
                        blur_reach(space.y_to_pixels(space.user_height(shadow->sigma_y))));
  }
  // The kernels that read a neighbourhood (their windows stop at the input's edge, which the needed
  // pixels' neighbourhoods do not reach further than this): grown by the neighbourhood. Attributes in
  // error (no values) need everything.
  if (const auto* morphology = std::get_if<MorphologyParams>(&values)) {
    if (morphology_is_identity(*morphology)) return result_needed;  // the input itself
    const auto pixels = [](double v) {
      return static_cast<long long>(std::ceil(std::min(std::fabs(v), 1e9))) + 1;
    };
    return result_needed.grown(pixels(space.x_to_pixels(space.user_width(morphology->radius_x))),
                               pixels(space.y_to_pixels(space.user_height(morphology->radius_y))));
  }
  if (const auto* convolve = std::get_if<ConvolveMatrixParams>(&values)) {
    // edgeMode wrap reads across the subregion, from its far side: all of the input.
    if (convolve->edge_mode == EdgeMode::kWrap) return everything;
    return result_needed.grown(std::max(convolve->target_x, convolve->order_x - 1 - convolve->target_x),
                               std::max(convolve->target_y, convolve->order_y - 1 - convolve->target_y));
  }
  if (std::holds_alternative<DiffuseParams>(values) || std::holds_alternative<SpecularParams>(values))
    return result_needed.grown(1, 1);
  if (const auto* displacement = std::get_if<DisplacementMapParams>(&values)) {
    // in is read up to |scale| / 2 away (the map's channel minus one half, times scale); in2 at the pixel.
    const auto pixels = [](double v) {
      return static_cast<long long>(std::ceil(std::min(std::fabs(v), 2e9))) + 1;
    };
    return result_needed.grown(pixels(space.x_to_pixels(space.user_width(displacement->scale)) / 2.0),
                               pixels(space.y_to_pixels(space.user_height(displacement->scale)) / 2.0));
  }
  return everything;
}

std::optional<std::pair<double, double>> primitive_reach(const ResolvedPrimitive& primitive,
                                                         const FilterSpace& space) {
  const std::string_view name = primitive.entry->name;
  const PrimitiveParams& values = primitive.params;
  static constexpr std::array<std::string_view, 7> kPerPixel{
      "feFlood", "feComposite", "feMerge", "feBlend", "feColorMatrix", "feImage", "feComponentTransfer"};
  if (std::find(kPerPixel.begin(), kPerPixel.end(), name) != kPerPixel.end()) return std::pair{0.0, 0.0};
  // Noise depends on position only, but stitched noise on its tile, the whole subregion: kept whole.
  if (name == "feTurbulence") {
    const auto* turbulence = std::get_if<TurbulenceParams>(&values);
    if (turbulence != nullptr && turbulence->stitch_tiles) return std::nullopt;
    return std::pair{0.0, 0.0};
  }
  // A primitive in error makes the filter's result transparent: it carries nothing.
  if (name == "feMorphology") {
    // The window reaches the radius (rounded to whole pixels: half a pixel more, which the caller's margin
    // covers); a negative radius, or both zero, is the input itself.
    const auto* morphology = std::get_if<MorphologyParams>(&values);
    if (morphology == nullptr || morphology_is_identity(*morphology)) return std::pair{0.0, 0.0};
    return std::pair{std::fabs(space.user_width(morphology->radius_x)),
                     std::fabs(space.user_height(morphology->radius_y))};
  }
  if (name == "feDisplacementMap") {
    // A pixel reads `in` at most |scale| / 2 away along each axis (scale times a channel minus one half).
    const auto* displacement = std::get_if<DisplacementMapParams>(&values);
    if (displacement == nullptr) return std::pair{0.0, 0.0};
    return std::pair{std::fabs(space.user_width(displacement->scale)) / 2.0,
                     std::fabs(space.user_height(displacement->scale)) / 2.0};
  }
  // feConvolveMatrix and the lighting primitives reach a number of filter pixels (the kernel's extent, the
  // surface normal's neighbours), not of user units, and feTile depends on where its input lies: unknown
  // here, the caller keeps the whole region.
  if (const auto* blur = std::get_if<BlurParams>(&values)) {
    return std::pair{3.0 * std::fabs(space.user_width(blur->sigma_x)) + 1.0,
                     3.0 * std::fabs(space.user_height(blur->sigma_y)) + 1.0};
  }
  if (const auto* offset = std::get_if<OffsetParams>(&values))
    return std::pair{std::fabs(space.user_width(offset->dx)), std::fabs(space.user_height(offset->dy))};
  if (const auto* shadow = std::get_if<ShadowParams>(&values)) {
    return std::pair{
        3.0 * std::fabs(space.user_width(shadow->sigma_x)) + 1.0 + std::fabs(space.user_width(shadow->dx)),
        3.0 * std::fabs(space.user_height(shadow->sigma_y)) + 1.0 + std::fabs(space.user_height(shadow->dy))};
  }
  return std::nullopt;
}

}  // namespace curvescan::svg::detail::filter
