// <mask> (SVG 1.1 section 14.4, CSS Masking 1 sections 7.1-7.3): where the mask applies and how its
// rendered content becomes coverage.
//
// The renderer (document.cpp) draws the mask's children into an offscreen canvas of the part of the output
// the mask region covers (device_box), clipped to the region, then turns that image into a ClipMask of the
// output's size (mask_coverage, zero outside that part) and composites the
// masked element's group through it. A mask on the <mask> element itself multiplies in (the luminance of
// content seen through a mask is the content's luminance times that mask, so applying both masks to the
// element is the same thing). Recursion -- a mask whose content, or whose own mask, refers back to a mask
// being applied -- is broken where it closes, as resvg does: the reference that closes the loop counts as
// `none`, with a warning.
#pragma once

#include <optional>
#include <pugixml.hpp>

#include "computed_style.h"
#include "curvescan/curves/affine.h"
#include "curvescan/curves/rect.h"
#include "curvescan/raster/image.h"
#include "curvescan/raster/mask.h"

namespace curvescan::svg::detail {

/// Deepest nesting of masks being applied (a mask in the content of a mask, or on a mask); each level
/// holds an offscreen image of at most the output's size, so this bounds the memory of one element to
/// kMaxMaskDepth + 1 images.
inline constexpr int kMaxMaskDepth = 8;

/// A <mask> with its attributes read (resolve_mask), once per mask and viewport in a render
/// (resolved_references.h): everything but the masked element's box.
struct ResolvedMask {
  pugi::xml_node element;     ///< the <mask>, whose children the drawing walk draws
  ComputedStyle style;        ///< its computed style (its mask-type; its own mask is style.painting.mask_id)
  bool region_in_box = true;  ///< maskUnits="objectBoundingBox" (the default)
  bool content_in_box = false;  ///< maskContentUnits="objectBoundingBox"
  /// The region: fractions of the box (region_in_box) or user units; defaults -10 %, -10 %, 120 %, 120 %.
  double x = -0.1, y = -0.1, width = 1.2, height = 1.2;
};

/// Reads `mask` whose computed style is `style`; warnings for bad values go to `diagnostics`.
[[nodiscard]] ResolvedMask resolve_mask(const pugi::xml_node& mask, ComputedStyle style,
                                        const ResolveContext& context, Diagnostics& diagnostics);

/// A <mask> placed for one masked element.
struct MaskSetup {
  Rect region;               ///< the mask region (x, y, width, height) in the element's user space
  Affine content_transform;  ///< maskContentUnits: identity, or the bounding-box transform
  MaskType type = MaskType::kLuminance;  ///< mask-type of the <mask> element
};

/// `mask` for an element whose user-space bounding box is `bbox` (nullopt or empty: an element without
/// geometry). nullopt means the element is not rendered at all: a region with zero or negative size, or
/// objectBoundingBox units on an element whose box has no area (SVG 1.1 7.11: the effect is disabled;
/// Chrome and resvg mask everything).
[[nodiscard]] std::optional<MaskSetup> place_mask(const ResolvedMask& mask, const std::optional<Rect>& bbox);

/// The coverage of `content` (premultiplied RGBA8, the mask's rendered children) as a mask:
///  - luminance (CSS Masking 1, 7.3): 0.2125·R + 0.7154·G + 0.0721·B of the premultiplied channels, which
///    is the colour's luminance times its alpha, rounded to nearest. The coefficients are applied to the
///    sRGB values: color-interpolation on the mask is ignored, as Chrome, Firefox and resvg ignore it.
///  - alpha: the alpha channel.
[[nodiscard]] ClipMask mask_coverage(const Image& content, MaskType type);

/// A part of the output in whole pixels: columns [x0, x1), rows [y0, y1), not empty.
struct PixelBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  [[nodiscard]] int width() const noexcept { return x1 - x0; }
  [[nodiscard]] int height() const noexcept { return y1 - y0; }
};

/// The pixels of a `width` x `height` output that `region` (user space, mapped by `ctm`) touches: the box
/// of its mapped corners grown to whole pixels, within the output; nullopt when that is empty (or not
/// finite).
[[nodiscard]] std::optional<PixelBox> device_box(const Rect& region, const Affine& ctm, int width,
                                                 int height);

/// mask_coverage of `content`, an image of the pixels of a `width` x `height` output from column `x0` and
/// row `y0` on, as a mask of the whole output: 0 outside the part `content` covers.
[[nodiscard]] ClipMask mask_coverage(const Image& content, MaskType type, int width, int height, int x0,
                                     int y0);

}  // namespace curvescan::svg::detail
