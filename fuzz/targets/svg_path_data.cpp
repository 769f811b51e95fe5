// Fuzz target svg_path_data: the SVG attribute micro-syntaxes of raster/svg/include/curvescan/svg/.
//
// The bytes are one attribute value, given to every parser (path data, number, number list, length,
// colour, transform, style attribute, viewBox, preserveAspectRatio): each must return a value or an
// error, never crash. A path that parses (up to its first error, SVG 1.1 appendix F.2) is then filled on a
// small canvas under the parsed transform, so that coordinates the parser lets through (1e300, denormals)
// reach the flattener and the rasterizer the way a document would send them.
#include <cstdint>
#include <string_view>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/svg/color.h"
#include "curvescan/svg/length.h"
#include "curvescan/svg/number.h"
#include "curvescan/svg/path_data.h"
#include "curvescan/svg/style_attribute.h"
#include "curvescan/svg/transform.h"
#include "curvescan/svg/viewport.h"
#include "fuzz_targets.h"

namespace curvescan::fuzz {

int fuzz_svg_path_data(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);  // bytes as characters

  (void)svg::parse_number(text);
  (void)svg::parse_number_list(text);
  if (const Result<svg::Length> length = svg::parse_length(text)) {
    (void)svg::length_to_pixels(*length, svg::LengthContext{96.0, 16.0, 100.0});
  }
  (void)svg::parse_color(text);
  (void)svg::parse_style_attribute(text);
  const Result<svg::ViewBox> view_box = svg::parse_view_box(text);
  const Result<svg::PreserveAspectRatio> aspect = svg::parse_preserve_aspect_ratio(text);
  if (view_box && aspect) (void)svg::view_box_transform(*view_box, *aspect, 0.0, 0.0, 32.0, 32.0);
  const Result<Affine> transform = svg::parse_transform(text);

  PathBuilder builder;
  (void)svg::append_path_data(text, builder);
  const Result<Path> path = builder.build();
  if (!path) return 0;
  // A render budget of 2^16 segments instead of the default 2^22: a path that flattens past it on a
  // 32 x 32 canvas is refused by the same check, sooner (the default is tested in tests/bad_input).
  RenderLimits limits;
  limits.max_segments = std::int64_t{1} << 16;
  Result<Canvas> canvas = Canvas::create(32, 32, limits);
  if (!canvas) return 0;
  const Paint paint = Paint::solid({0.2, 0.4, 0.6, 0.8});
  (void)canvas->fill(*path, paint, FillRule::kNonZero);
  if (transform) (void)canvas->fill(*path, paint, FillRule::kEvenOdd, *transform);
  return 0;
}

}  // namespace curvescan::fuzz
