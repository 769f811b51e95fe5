// GradientSpanCompositor: the SpanSink that paints a gradient, source-over, with each span's coverage.
//
// Each covered pixel is evaluated at its centre (x + 0.5, y + 0.5) in device space, mapped to gradient
// space by the inverse of device_from_user · user_from_gradient (gradient.h): the parameter t
// (gradient_parameter.h), then the premultiplied colour at t (gradient_walker.h), then paint.h's
// composite_source_over. The work is split as pixman splits it: a span is shaded into a buffer of colours,
// then the buffer is blended (blend_color_span, four pixels at a time); a linear gradient whose t is
// constant along rows is one colour per span, blended as a solid colour (blend_solid_span, fill_pixels).
// Once a pad gradient has shaded kTableAfterPixels pixels with the walker, the exact 16.16 colour table
// (gradient_color_table.h) is built and the rest is looked up. The table lives in a GradientTableSlot
// (gradient_table_cache.h) that the bands of a fill, and the canvas's later fills of the same gradient,
// share: the count of pixels shaded and the table are the slot's, so the table is built once. Building the
// table costs about what the walker spends on that many pixels (callgrind: ≈ 0.9 M instructions, against ≈ 45
// per pixel through the walker and ≈ 18 through the table), so a fill pays at most about twice the cheaper of
// the two ways, and a small one never builds it (the rent-or-buy rule).
//
// The output is GradientSpanReference's (gradient_span_reference.h), the plain per-pixel compositor, byte
// for byte (tests/unit/paint/span_fast_paths_test.cpp).
//
// Pixels are written to `target` at (x − origin_x, y − origin_y): a layer (layer.h) covers only part of
// the canvas, while spans and gradient evaluation stay in canvas device coordinates.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <span>
#include <type_traits>

#include "color_span_blend.h"
#include "curvescan/curves/affine.h"
#include "curvescan/raster/gradient.h"
#include "curvescan/raster/image.h"
#include "curvescan/raster/rasterizer.h"
#include "gradient_color_table.h"
#include "gradient_parameter.h"
#include "gradient_table_cache.h"
#include "gradient_walker.h"
#include "pixel_fill.h"
#include "solid_span_compositor.h"

namespace curvescan::detail {

class GradientSpanCompositor final : public SpanSink {
 public:
  /// Pixels a pad gradient shades with the walker before it switches to the colour table.
  static constexpr long kTableAfterPixels = 16384;

  /// `device_to_gradient` is the inverse of device_from_user · shader.gradient_to_user(). The colour
  /// table, when the gradient earns one, is kept in `table_slot` (shared with other compositors of the same
  /// shader); without a slot (the render's memory budget has no room for PadColorTable::kBytes) every
  /// colour comes from the walker: the same bytes, more slowly.
  GradientSpanCompositor(Image& target, int origin_x, int origin_y, const GradientShader& shader,
                         const Affine& device_to_gradient,
                         std::shared_ptr<GradientTableSlot> table_slot) noexcept
      : table_slot_(shader.spread() == SpreadMethod::kPad ? std::move(table_slot) : nullptr),
        table_(table_slot_ != nullptr ? table_slot_->table() : nullptr),
        target_(target),
        origin_x_(origin_x),
        origin_y_(origin_y),
        shader_(shader),
        walker_(shader),
        linear_(shader.linear(), device_to_gradient),
        radial_(shader, device_to_gradient) {}

  /// A compositor with a table slot of its own when `table_allowed` (as above; the slot goes with it).
  GradientSpanCompositor(Image& target, int origin_x, int origin_y, const GradientShader& shader,
                         const Affine& device_to_gradient, bool table_allowed = true)
      : GradientSpanCompositor(target, origin_x, origin_y, shader, device_to_gradient,
                               table_allowed ? std::make_shared<GradientTableSlot>() : nullptr) {}

  void blend(std::span<const Span> spans) override {
    const bool linear = shader_.shape() == GradientShader::Shape::kLinear;
    for (const Span& span : spans) {
      if (span.coverage == 0) continue;
      Rgba8* row = target_.row(span.y - origin_y_) + (span.x - origin_x_);
      const double center_y = span.y + 0.5;
      if (linear && linear_.constant_along_rows()) {
        blend_one_color(row, span, color_at(linear_.at(span.x + 0.5, center_y)));
        continue;
      }
      for (int start = 0; start < span.len; start += kChunk) {
        const int n = std::min(kChunk, span.len - start);
        if (linear) {
          shade(linear_, span.x + start, center_y, n);
        } else {
          shade(radial_, span.x + start, center_y, n);
        }
        blend_color_span(row + start, colors_.data(), n, span.coverage);
      }
    }
  }

 private:
  static constexpr int kChunk = 256;

  [[nodiscard]] Rgba8 color_at(double t) noexcept {
    return table_ != nullptr ? table_->color_at(t) : walker_.color_at(t);
  }

  /// colors_[0..n) = the colours of pixels x .. x + n − 1 of the row whose centre is at center_y.
  template <class Parameter>
  void shade(const Parameter& parameter, int x, double center_y, int n) {
    if (table_ == nullptr && table_slot_ != nullptr) {
      // Another band or fill may have built the slot's table meanwhile; otherwise the table is built once
      // the slot's gradient has shaded kTableAfterPixels with the walker (a failed build leaves the walker,
      // which gives the same colours).
      table_ = table_slot_->table();
      if (table_ == nullptr && table_slot_->add_shaded(n) >= kTableAfterPixels) {
        table_ = table_slot_->build(walker_);
        if (table_ == nullptr) table_slot_.reset();
      }
    }
    if (table_ != nullptr) {
      shade_from(parameter, *table_, x, center_y, n);
    } else {
      shade_from(parameter, walker_, x, center_y, n);
    }
  }

  template <class Parameter, class Colors>
  void shade_from(const Parameter& parameter, Colors& colors, int x, double center_y, int n) {
    parameter.fill(x, center_y, n, parameters_.data());
    if constexpr (std::is_same_v<Colors, PadColorTable>) {
      colors.colors_at(parameters_.data(), n, colors_.data());
    } else {
      for (int i = 0; i < n; ++i)
        colors_[static_cast<std::size_t>(i)] = colors.color_at(parameters_[static_cast<std::size_t>(i)]);
    }
  }

  /// Every pixel of the span has the colour `color`.
  void blend_one_color(Rgba8* row, const Span& span, Rgba8 color) noexcept {
    if (color.a == 0) return;  // premultiplied: transparent, the destination stays
    if (color.a == 255 && span.coverage == 255) {
      fill_pixels(row, static_cast<std::size_t>(span.len), color);
      return;
    }
    blend_solid_span(row, span.len, color, span.coverage);
  }

  std::shared_ptr<GradientTableSlot> table_slot_;  // null: the walker only
  const PadColorTable* table_;                     // the slot's table once built, else null
  Image& target_;
  int origin_x_, origin_y_;
  const GradientShader& shader_;
  GradientWalker walker_;
  LinearParameter linear_;
  RadialParameter radial_;
  std::array<double, kChunk> parameters_{};
  std::array<Rgba8, kChunk> colors_{};
};

}  // namespace curvescan::detail
