// Fuzz target raster_stroke: a scene decoded from the bytes (fuzz_input.h) — a path whose coordinates come
// partly from the table of hostile values, a transform, a fill rule, a tolerance and a stroke style — drawn
// on a 32 x 32 canvas: filled, stroked (dashed or not), used as a clip, inside a group layer.
//
// Layout of the bytes, in order (each field as FuzzInput decodes it):
//   options   1 byte: bit 0 even-odd, bit 1 aliased, bit 2 hand non-finite coordinates to the builder
//             (else commands with one are skipped, so the rest of the path is still drawn), bit 3 clip,
//             bit 4 group layer
//   transform 1 byte kind (identity, scale, rotation about a point, six free coefficients) + numbers
//   tolerance 1 byte: an index into kTolerances (valid ones and invalid ones)
//   style     width, join, cap, miter limit, dash count (0..6), dashes, dash offset
//   commands  until the input ends (at most kMaxCommands): 1 byte verb + its points and parameters; a
//             point whose first byte is 0 repeats the previous point exactly (zero-length segments)
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/path_builder.h"
#include "fuzz_input.h"
#include "fuzz_targets.h"

namespace curvescan::fuzz {
namespace {

constexpr int kCanvasSize = 32;
constexpr int kMaxCommands = 64;
constexpr double kCentre = kCanvasSize / 2.0;

constexpr double kTolerances[] = {0.1, 0.25, 1.0,  0.01,
                                  4.0, 0.0,  -1.0, std::numeric_limits<double>::quiet_NaN()};

class SceneDecoder {
 public:
  explicit SceneDecoder(FuzzInput& input) noexcept : input_(input) {}

  Point point() noexcept {
    if (input_.byte() == 0) return previous_;
    previous_ = Point{input_.number(kCentre), input_.number(kCentre)};
    return previous_;
  }

  Affine transform() noexcept {
    switch (input_.choice(4)) {
      case 0:
        return Affine::identity();
      case 1:
        return Affine::scale(input_.number(1.0), input_.number(1.0));
      case 2: {
        const Point pivot{input_.number(kCentre), input_.number(kCentre)};
        return Affine::translate(pivot.x, pivot.y) * Affine::rotate(input_.number()) *
               Affine::translate(-pivot.x, -pivot.y);
      }
      default:
        return Affine{input_.number(1.0), input_.number(), input_.number(),
                      input_.number(1.0), input_.number(), input_.number()};
    }
  }

  StrokeStyle stroke_style() noexcept {
    StrokeStyle style;
    style.width = input_.number(1.0);
    style.join = static_cast<LineJoin>(input_.choice(4));
    style.cap = static_cast<LineCap>(input_.choice(3));
    style.miter_limit = input_.number(4.0);
    const int dashes = input_.choice(7);
    for (int i = 0; i < dashes; ++i) style.dash_array.push_back(input_.number(2.0));
    style.dash_offset = dashes > 0 ? input_.number() : 0.0;
    return style;
  }

  /// Decodes one command into `builder`; with `skip_non_finite`, a command with a non-finite value is
  /// decoded but not given to the builder (which would refuse it and every later command).
  void command(PathBuilder& builder, bool skip_non_finite) {
    values_.clear();
    switch (input_.choice(9)) {
      case 0: {
        const Point p = point();
        if (keep(skip_non_finite, {p})) builder.move_to(p);
        break;
      }
      case 1: {
        const Point p = point();
        if (keep(skip_non_finite, {p})) builder.line_to(p);
        break;
      }
      case 2: {
        const Point c = point(), p = point();
        if (keep(skip_non_finite, {c, p})) builder.quad_to(c, p);
        break;
      }
      case 3: {
        const Point c1 = point(), c2 = point(), p = point();
        if (keep(skip_non_finite, {c1, c2, p})) builder.cubic_to(c1, c2, p);
        break;
      }
      case 4: {
        const Point c = point(), p = point();
        values_.push_back(input_.number(1.0));
        if (keep(skip_non_finite, {c, p})) builder.conic_to(c, p, values_[0]);
        break;
      }
      case 5:
        builder.close();
        break;
      case 6: {
        const Point centre = point();
        for (int i = 0; i < 5; ++i) values_.push_back(input_.number());
        if (keep(skip_non_finite, {centre})) {
          builder.arc(centre, values_[0], values_[1], values_[2], values_[3], values_[4]);
        }
        break;
      }
      case 7: {
        for (int i = 0; i < 3; ++i) values_.push_back(input_.number(4.0));
        const bool large_arc = input_.flag(), sweep = input_.flag();
        const Point to = point();
        if (keep(skip_non_finite, {to}))
          builder.svg_arc_to(values_[0], values_[1], values_[2], large_arc, sweep, to);
        break;
      }
      default: {
        // A polynomial or rational Bézier of degree 1..8 (higher degrees: limits.h allows up to 64).
        std::vector<Point> points(static_cast<std::size_t>(1 + input_.choice(8)));
        for (Point& p : points) p = point();
        const bool rational = input_.flag();
        if (!keep(skip_non_finite, points)) break;
        if (rational) {
          std::vector<double> weights(points.size() + 1);
          for (double& w : weights) w = input_.number(1.0);
          builder.rational_bezier_to(points, weights);
        } else {
          builder.bezier_to(points);
        }
        break;
      }
    }
  }

 private:
  [[nodiscard]] bool keep(bool skip_non_finite, std::initializer_list<Point> points) const noexcept {
    return keep(skip_non_finite, std::span<const Point>(points.begin(), points.size()));
  }
  [[nodiscard]] bool keep(bool skip_non_finite, std::span<const Point> points) const noexcept {
    if (!skip_non_finite) return true;
    for (const Point p : points) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
    }
    for (const double v : values_) {
      if (!std::isfinite(v)) return false;
    }
    return true;
  }

  FuzzInput& input_;
  Point previous_{kCentre, kCentre};
  std::vector<double> values_;
};

}  // namespace

int fuzz_raster_stroke(const std::uint8_t* data, std::size_t size) {
  FuzzInput input(data, size);
  SceneDecoder scene(input);
  const std::uint8_t options = input.byte();
  const FillRule rule = (options & 1) != 0 ? FillRule::kEvenOdd : FillRule::kNonZero;
  FillOptions fill_options;
  fill_options.antialias = (options & 2) != 0 ? Antialias::kNone : Antialias::kExact;
  const bool skip_non_finite = (options & 4) == 0;
  const Affine transform = scene.transform();
  fill_options.tolerance = kTolerances[input.choice(static_cast<int>(std::size(kTolerances)))];
  const StrokeStyle style = scene.stroke_style();

  PathBuilder builder;
  for (int i = 0; i < kMaxCommands && !input.empty(); ++i) scene.command(builder, skip_non_finite);
  const Result<Path> path = builder.build();
  if (!path) return 0;

  // Budgets far below the defaults keep one input to milliseconds under ASan (the default 2^22 segments
  // is seconds there); what they bound is tested at the default size in tests/bad_input. 2^14 segments:
  // a scene of kMaxCommands curves stroked at the finest tolerance of kTolerances on this canvas needs a
  // few thousand, while the inputs that reach the budget (curves a hostile coordinate makes 1e7 wide,
  // flattened for the stroke before anything is clipped) were spending most of the fuzzing time walking
  // 2^16 segments to the same refusal.
  RenderLimits limits;
  limits.max_segments = std::int64_t{1} << 14;
  limits.max_dashes = std::int64_t{1} << 12;
  limits.max_memory_bytes = std::int64_t{64} << 20;
  Result<Canvas> canvas = Canvas::create(kCanvasSize, kCanvasSize, limits);
  if (!canvas) return 0;
  const Paint paint = Paint::solid({0.1, 0.5, 0.9, 0.7});
  const bool layer = (options & 16) != 0 && canvas->push_layer().is_ok();
  const bool clip = (options & 8) != 0 && canvas->push_clip(*path, rule, transform, fill_options).is_ok();
  (void)canvas->fill(*path, paint, rule, transform, fill_options);
  (void)canvas->stroke(*path, paint, style, transform, fill_options);
  if (clip) (void)canvas->pop_clip();
  if (layer) (void)canvas->pop_layer(0.5);
  return 0;
}

}  // namespace curvescan::fuzz
