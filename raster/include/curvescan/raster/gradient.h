// Gradients: SVG 1.1 / SVG 2 linear and radial gradient paints (SVG 1.1 section 13.2, SVG 2 "Paint
// Servers" section 14), evaluated the way Cairo's pixman evaluates them so that curvescan, Cairo and
// rsvg-convert paint the same bytes.
//
// Spaces. The stops live on a parameter t: t = 0 at the start (linear: (x1, y1); radial: the focal
// circle), t = 1 at the end (linear: (x2, y2); radial: the circle (cx, cy, r)). Geometry is given in
// gradient space; `gradient_to_user` maps it to user space (the SVG renderer composes gradientTransform
// with the objectBoundingBox mapping into this one Affine), and the fill's transform maps user space to
// device pixels. Each pixel is evaluated at its centre, mapped back through the inverse of the composed
// transform.
//
// Colour. Stops are straight-alpha colours; between two stops colour and alpha are interpolated
// separately, straight (not premultiplied), then premultiplied — that is what pixman does
// (pixman-gradient-walker.c: alpha and the straight channels are lerped in float, then multiplied), and
// a probe of Cairo 1.16 / pixman 0.42 confirms it: a red-opaque to blue-transparent gradient paints
// (r, b, a) = (62, 64, 126) at its middle, where premultiplied interpolation would give (127, 0, 127).
// docs/paint.md discusses the choice.
//
// Degenerate input, as SVG prescribes (SVG 1.1 13.2.2, 13.2.3, 13.2.4; SVG 2 14.4):
//  - no stops: the paint is "none" (nothing is painted);
//  - one stop: a solid paint of that stop's colour;
//  - a zero-length linear vector (start == end) or r = 0: a solid paint of the last stop's colour;
//  - offsets are clamped to [0, 1] and each to at least the largest offset before it; NaN offsets count
//    as that largest offset; colour channels are clamped to [0, 1] with NaN -> 0 (as Paint::solid);
//  - a negative r or fr, a non-finite coordinate, or a singular or non-finite gradient_to_user: "none"
//    (SVG 2 calls a negative radius an error, and a singular objectBoundingBox mapping disables the
//    paint); identical start and end circles: "none" (the canvas rule SVG 2 refers to).
//  - focal point outside the end circle: moved towards the centre onto the circle of radius
//    kFocalClampRatio·r, which is SVG 1.1's rule (intersection with the circle) kept strictly inside so
//    that every pixel lies on some circle of the family. SVG 2 / Cairo would instead draw a cone and leave
//    part of the plane unpainted; we follow SVG 1.1 because it is what SVG 1.1 content expects and what
//    the renderer can always honour. With fr > 0 the focal *circle* may still stick out of the end circle:
//    that case is drawn as SVG 2's cone (pixels on no circle are left unpainted).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "curvescan/curves/affine.h"
#include "curvescan/curves/point.h"
#include "curvescan/raster/image.h"
#include "curvescan/raster/paint.h"

namespace curvescan {

/// SVG spreadMethod: what the gradient shows for t outside [0, 1].
enum class SpreadMethod : std::uint8_t {
  kPad,      ///< the end colours continue (t clamped to [0, 1])
  kReflect,  ///< the gradient mirrors back and forth (period 2)
  kRepeat,   ///< the gradient restarts (period 1)
};

/// One gradient stop: an offset along t and a straight-alpha colour, channels as doubles in [0, 1]
/// (stop-color and stop-opacity; fill-opacity folds in by multiplying `a`, since alpha is interpolated
/// linearly and separately from colour).
struct GradientStop {
  double offset = 0.0;
  Color color;  ///< straight alpha; fold the paint's opacity into color.a
  bool operator==(const GradientStop&) const = default;
};

/// SVG linearGradient geometry in gradient space: the vector (x1, y1) -> (x2, y2).
struct LinearGradient {
  Point start{0.0, 0.0};
  Point end{1.0, 0.0};
};

/// SVG radialGradient geometry in gradient space: end circle (cx, cy, r), focal circle (fx, fy, fr).
/// SVG 1.1 has no fr (it is 0); SVG 2 adds it. When the focal point is absent SVG sets it to the centre.
struct RadialGradient {
  Point center{0.5, 0.5};
  double radius = 0.5;
  Point focal{0.5, 0.5};
  double focal_radius = 0.0;
};

/// Distance from the centre, as a fraction of r, to which an outside focal point is moved (see above).
inline constexpr double kFocalClampRatio = 0.999;

/// Stops as SVG resolves them: offsets clamped to [0, 1] and made non-decreasing, channels clamped to
/// [0, 1] (NaN -> 0), and, when the first offset is above 0 or the last below 1, a copy of the first stop
/// at 0 and of the last at 1 (SVG: the end colours fill the rest of [0, 1]; with this the same stops mean
/// the same thing under every spread method, in pixman too). Empty in, empty out.
[[nodiscard]] std::vector<GradientStop> normalize_gradient_stops(std::span<const GradientStop> stops);

/// The focal point actually used for `radial` (SVG 1.1 clamp above); NaN in, NaN out.
[[nodiscard]] Point clamped_focal_point(const RadialGradient& radial) noexcept;

/// A linear gradient paint (or the solid / "none" paint SVG prescribes for degenerate input, see above).
[[nodiscard]] Paint linear_gradient_paint(const LinearGradient& geometry, std::span<const GradientStop> stops,
                                          SpreadMethod spread,
                                          const Affine& gradient_to_user = Affine::identity());
/// A radial gradient paint (or the solid / "none" paint SVG prescribes for degenerate input, see above).
[[nodiscard]] Paint radial_gradient_paint(const RadialGradient& geometry, std::span<const GradientStop> stops,
                                          SpreadMethod spread,
                                          const Affine& gradient_to_user = Affine::identity());

/// A prepared gradient: normalized stops, geometry (focal point already clamped) and spread. Immutable
/// once built, shared between Paints. Only the factories above make one, and only for non-degenerate input
/// (at least two stops, a finite invertible gradient_to_user, a non-degenerate shape).
class GradientShader {
 public:
  enum class Shape : std::uint8_t { kLinear, kRadial };

  [[nodiscard]] Shape shape() const noexcept { return shape_; }
  [[nodiscard]] SpreadMethod spread() const noexcept { return spread_; }
  [[nodiscard]] const std::vector<GradientStop>& stops() const noexcept { return stops_; }
  [[nodiscard]] const LinearGradient& linear() const noexcept { return linear_; }
  /// The radial geometry with the focal point already clamped (clamped_focal_point).
  [[nodiscard]] const RadialGradient& radial() const noexcept { return radial_; }
  [[nodiscard]] const Affine& gradient_to_user() const noexcept { return gradient_to_user_; }

  /// The gradient parameter t at a point of gradient space (before spreading). For a radial gradient it
  /// is the largest t whose circle (radius >= 0) passes through the point, NaN when there is none (only
  /// when the focal circle is not inside the end circle); NaN in, NaN out.
  [[nodiscard]] double parameter_at(Point gradient_point) const noexcept;

  /// The premultiplied colour at parameter t, spread applied, computed with pixman's gradient walker
  /// arithmetic (t on a 16.16 fixed grid, float lerp of straight channels and alpha, premultiply, round).
  /// NaN t gives transparent. This is the fast path the span compositor uses.
  [[nodiscard]] Rgba8 color_at(double t) const noexcept;
  /// The same colour computed plainly in double from the unquantized stops: the reference color_at is
  /// held to (within one level, tests/unit/paint).
  [[nodiscard]] Rgba8 color_at_reference(double t) const noexcept;

  /// Pixman-ready stops: the normalized stops as 16.16 offsets and 16-bit straight channels (Cairo's
  /// conversion), with the sentinels pixman places before and after them for this spread method.
  struct WalkerStop {
    std::int64_t x = 0;
    std::uint16_t r = 0, g = 0, b = 0, a = 0;
  };
  /// walker_stops()[0] and .back() are the sentinels.
  [[nodiscard]] const std::vector<WalkerStop>& walker_stops() const noexcept { return walker_stops_; }

  // Use the factories; public so that std::make_shared can construct it.
  GradientShader(Shape shape, std::vector<GradientStop> stops, SpreadMethod spread,
                 const LinearGradient& linear, const RadialGradient& radial, const Affine& gradient_to_user);

 private:
  Shape shape_;
  SpreadMethod spread_;
  std::vector<GradientStop> stops_;
  std::vector<WalkerStop> walker_stops_;
  LinearGradient linear_;
  RadialGradient radial_;
  Affine gradient_to_user_;
};

}  // namespace curvescan
