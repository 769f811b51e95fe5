// GradientSpanReference: the plain gradient compositor, pixel by pixel, that the fast one
// (gradient_span_compositor.h) is held to byte for byte by tests/unit/paint/span_fast_paths_test.cpp.
//
// Each covered pixel is evaluated at its centre (x + 0.5, y + 0.5) in device space, mapped to gradient
// space by the inverse of device_from_user · user_from_gradient (gradient.h), where the shader gives t and
// the walker (gradient_walker.h) the premultiplied colour; compositing is paint.h's composite_source_over.
// A linear gradient's t is affine in device coordinates, so it is computed from three coefficients per
// pixel (no point transform); a radial one maps the point and solves its quadratic (parameter_at).
//
// Pixels are written to `target` at (x − origin_x, y − origin_y): a layer (layer.h) covers only part of
// the canvas, while spans and gradient evaluation stay in canvas device coordinates.
#pragma once

#include <algorithm>
#include <span>

#include "curvescan/curves/affine.h"
#include "curvescan/raster/gradient.h"
#include "curvescan/raster/image.h"
#include "curvescan/raster/paint.h"
#include "curvescan/raster/rasterizer.h"
#include "gradient_walker.h"

namespace curvescan::detail {

class GradientSpanReference final : public SpanSink {
 public:
  /// `device_to_gradient` is the inverse of device_from_user · shader.gradient_to_user().
  GradientSpanReference(Image& target, int origin_x, int origin_y, const GradientShader& shader,
                        const Affine& device_to_gradient) noexcept
      : target_(target),
        origin_x_(origin_x),
        origin_y_(origin_y),
        shader_(shader),
        device_to_gradient_(device_to_gradient),
        walker_(shader) {
    if (shader.shape() == GradientShader::Shape::kLinear) {
      // t(X, Y) = ((M·(X, Y) − start) · axis) / |axis|², affine in (X, Y).
      const LinearGradient& linear = shader.linear();
      const Vec2 axis = linear.end - linear.start;
      const Vec2 scaled = axis / axis.length_squared();
      const Affine& m = device_to_gradient;
      t_per_x_ = m.a * scaled.x + m.b * scaled.y;
      t_per_y_ = m.c * scaled.x + m.d * scaled.y;
      t_at_origin_ = (Point{m.e, m.f} - linear.start).dot(scaled);
    }
  }

  void blend(std::span<const Span> spans) override {
    const bool linear = shader_.shape() == GradientShader::Shape::kLinear;
    for (const Span& span : spans) {
      if (span.coverage == 0) continue;
      Rgba8* row = target_.row(span.y - origin_y_) + (span.x - origin_x_);
      const double center_y = span.y + 0.5;
      for (int i = 0; i < span.len; ++i) {
        const double center_x = span.x + i + 0.5;
        const double t = linear ? t_at_origin_ + t_per_x_ * center_x + t_per_y_ * center_y
                                : shader_.parameter_at(device_to_gradient_.apply(Point{center_x, center_y}));
        const Rgba8 color = walker_.color_at(t);
        if (color.a == 0) continue;  // transparent source: the destination stays
        row[i] = (color.a == 255 && span.coverage == 255)
                     ? color
                     : composite_source_over(row[i], color, span.coverage);
      }
    }
  }

 private:
  Image& target_;
  int origin_x_, origin_y_;
  const GradientShader& shader_;
  Affine device_to_gradient_;
  GradientWalker walker_;
  double t_per_x_ = 0.0, t_per_y_ = 0.0, t_at_origin_ = 0.0;
};

}  // namespace curvescan::detail
