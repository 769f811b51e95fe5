// A filter primitive's attributes read into values (Filter Effects 1, section 9, one subsection per
// primitive), once per filter and viewport (resolved_filter.h), in the primitive's own units: numbers in
// primitiveUnits, colours in the primitive's colour space. Placing them for a use (the bounding box of
// objectBoundingBox units, the filter image's resolution) is FilterSpace's work, when the primitive runs.
#pragma once

#include <array>
#include <memory>
#include <pugixml.hpp>
#include <string>
#include <variant>

#include "../computed_style.h"
#include "blend.h"
#include "color_matrix.h"
#include "component_transfer.h"
#include "composite.h"
#include "convolve_matrix.h"
#include "curvescan/svg/viewport.h"
#include "displacement_map.h"
#include "edge_mode.h"
#include "flood.h"
#include "lighting.h"
#include "morphology.h"
#include "turbulence.h"

namespace curvescan::svg::detail::filter {

/// feMerge and feTile, and a primitive whose attributes are in error.
struct NoParams {};

/// feFlood (9.12): flood-color with flood-opacity as alpha, unpremultiplied, in the primitive's space.
struct FloodParams {
  FilterColor color;
};

/// feOffset (9.17): dx, dy in primitiveUnits.
struct OffsetParams {
  double dx = 0.0, dy = 0.0;
};

/// feGaussianBlur (9.13): stdDeviation in primitiveUnits ({0, 0} when disabled), edgeMode.
struct BlurParams {
  double sigma_x = 0.0, sigma_y = 0.0;
  EdgeMode edge_mode = EdgeMode::kNone;
};

/// feDropShadow (9.11): stdDeviation, dx, dy in primitiveUnits, the flood colour as for feFlood.
struct ShadowParams {
  double sigma_x = 2.0, sigma_y = 2.0, dx = 2.0, dy = 2.0;
  FilterColor color;
};

/// feBlend (9.6).
struct BlendParams {
  BlendMode mode = BlendMode::kNormal;
};

/// feColorMatrix (9.8): the matrix its type and values give.
struct ColorMatrixParams {
  ColorMatrix matrix{};
};

/// feComponentTransfer (9.10): the functions of its last feFuncR, feFuncG, feFuncB, feFuncA.
struct TransferParams {
  TransferFunctions functions;
};

/// feDiffuseLighting (9.11) and feSpecularLighting (9.22) with lighting-color in the primitive's space.
struct DiffuseParams {
  DiffuseLightingParams lighting;
  std::array<float, 3> color{};
};
struct SpecularParams {
  SpecularLightingParams lighting;
  std::array<float, 3> color{};
};

/// feImage (9.14): what its href names, for the document to draw (FilterEnvironment::draw_fe_image).
struct ImageParams {
  std::string reference;  ///< href (or xlink:href); "" draws nothing
  /// A "#id" reference: the element it names (null when none), and the style it inherits, its parent's
  /// (SVG 1.1 6.7: a referenced element's styles come from its own ancestors).
  pugi::xml_node target;
  std::shared_ptr<const ComputedStyle> target_parent_style;
  /// An image reference: preserveAspectRatio, and image-rendering (inherited along the feImage's ancestors)
  /// asking for nearest sampling.
  PreserveAspectRatio aspect;
  bool pixelated = false;
};

using PrimitiveParams =
    std::variant<NoParams, FloodParams, OffsetParams, BlurParams, ShadowParams, CompositeParams, BlendParams,
                 ColorMatrixParams, TransferParams, TurbulenceParams, MorphologyParams, ConvolveMatrixParams,
                 DisplacementMapParams, DiffuseParams, SpecularParams, ImageParams>;

}  // namespace curvescan::svg::detail::filter
