// Canvas layers (group opacity) and clip masks: nesting, limits, errors, and the clip-once semantics.
#include <catch2/catch.hpp>
#include <limits>
#include <utility>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/gradient.h"
#include "curvescan/raster/layer.h"
#include "curvescan/raster/limits.h"
#include "curvescan/raster/mask.h"
#include "curvescan/raster/path_builder.h"

using namespace curvescan;

namespace {

Path rect_path(double x, double y, double w, double h) {
  return *PathBuilder()
              .move_to({x, y})
              .line_to({x + w, y})
              .line_to({x + w, y + h})
              .line_to({x, y + h})
              .close()
              .build();
}

const Paint kRed = Paint::solid(Color::from_rgba8(255, 0, 0, 255));

}  // namespace

TEST_CASE("layer_alpha converts opacity as cairo_paint_with_alpha does", "[paint][layer]") {
  CHECK(layer_alpha(1.0) == 255);
  CHECK(layer_alpha(0.0) == 0);
  CHECK(layer_alpha(0.5) == 128);  // 0.5·65535 + 0.5 = 32768 -> high byte 128
  CHECK(layer_alpha(2.0) == 255);
  CHECK(layer_alpha(-1.0) == 0);
  CHECK(layer_alpha(std::numeric_limits<double>::quiet_NaN()) == 0);
}

TEST_CASE("an opaque group at opacity 1 equals drawing directly — opacity 0 draws nothing", "[paint][layer]") {
  Canvas direct{Image(20, 16)};
  REQUIRE(direct.fill(rect_path(2.5, 3.25, 9, 7), kRed, FillRule::kNonZero).is_ok());
  Canvas grouped{Image(20, 16)};
  REQUIRE(grouped.push_layer().is_ok());
  CHECK(grouped.layer_depth() == 1);
  REQUIRE(grouped.fill(rect_path(2.5, 3.25, 9, 7), kRed, FillRule::kNonZero).is_ok());
  CHECK(grouped.image() == Image(20, 16));  // nothing reaches the canvas before pop_layer
  REQUIRE(grouped.pop_layer(1.0).is_ok());
  CHECK(grouped.image() == direct.image());
  Canvas hidden{Image(20, 16)};
  REQUIRE(hidden.push_layer().is_ok());
  REQUIRE(hidden.fill(rect_path(0, 0, 20, 16), kRed, FillRule::kNonZero).is_ok());
  REQUIRE(hidden.pop_layer(0.0).is_ok());
  CHECK(hidden.image() == Image(20, 16));
}

TEST_CASE("group opacity applies to the group as a whole, not to each shape", "[paint][layer]") {
  // Two overlapping opaque rectangles in a group at opacity 0.5: the overlap is 128 once, not 192.
  Canvas canvas{Image(10, 4)};
  REQUIRE(canvas.push_layer().is_ok());
  REQUIRE(canvas.fill(rect_path(0, 0, 6, 4), kRed, FillRule::kNonZero).is_ok());
  REQUIRE(canvas.fill(rect_path(4, 0, 6, 4), kRed, FillRule::kNonZero).is_ok());
  REQUIRE(canvas.pop_layer(0.5).is_ok());
  CHECK(canvas.image().at(5, 1) == Rgba8{128, 0, 0, 128});
  CHECK(canvas.image().at(1, 1) == Rgba8{128, 0, 0, 128});
}

TEST_CASE("layers nest up to kMaxLayerDepth and unbalanced pops fail", "[paint][layer][limits]") {
  Canvas canvas{Image(8, 8)};
  CHECK_FALSE(canvas.pop_layer(1.0).is_ok());
  for (int i = 0; i < kMaxLayerDepth; ++i) REQUIRE(canvas.push_layer().is_ok());
  const Status refused = canvas.push_layer();
  REQUIRE_FALSE(refused.is_ok());
  CHECK(refused.error().kind == ErrorKind::kLimitExceeded);
  REQUIRE(canvas.fill(rect_path(0, 0, 8, 8), kRed, FillRule::kNonZero).is_ok());
  for (int i = 0; i < kMaxLayerDepth; ++i) REQUIRE(canvas.pop_layer(1.0).is_ok());
  CHECK(canvas.layer_depth() == 0);
  CHECK(canvas.image().at(3, 3) == Rgba8{255, 0, 0, 255});  // through 16 opaque layers unchanged
}

TEST_CASE("a layer covers only the clip rectangle at push time", "[paint][layer]") {
  Canvas canvas{Image(12, 12)};
  canvas.set_clip({2, 2, 6, 6});
  REQUIRE(canvas.push_layer().is_ok());
  canvas.reset_clip();
  REQUIRE(canvas.fill(rect_path(0, 0, 12, 12), kRed, FillRule::kNonZero).is_ok());
  REQUIRE(canvas.pop_layer(1.0).is_ok());
  CHECK(canvas.image().at(3, 3) == Rgba8{255, 0, 0, 255});
  CHECK(canvas.image().at(8, 8) == Rgba8{});
  CHECK(canvas.image().at(1, 3) == Rgba8{});
}

TEST_CASE("a clip mask multiplies coverage — nested clips intersect — pop restores", "[paint][clip]") {
  Canvas canvas{Image(16, 8)};
  REQUIRE(canvas.push_clip(rect_path(0, 0, 8.5, 8), FillRule::kNonZero).is_ok());  // column 8 half covered
  REQUIRE(canvas.push_clip(rect_path(4, 0, 12, 8), FillRule::kNonZero).is_ok());
  CHECK(canvas.clip_depth() == 2);
  REQUIRE(canvas.fill(rect_path(0, 0, 16, 8), kRed, FillRule::kNonZero).is_ok());
  CHECK(canvas.image().at(2, 2) == Rgba8{});                // outside the second clip
  CHECK(canvas.image().at(5, 2) == Rgba8{255, 0, 0, 255});  // inside both
  CHECK(canvas.image().at(8, 2) == Rgba8{128, 0, 0, 128});  // half covered by the first clip
  CHECK(canvas.image().at(12, 2) == Rgba8{});               // outside the first
  REQUIRE(canvas.pop_clip().is_ok());
  REQUIRE(canvas.fill(rect_path(0, 0, 16, 1), kRed, FillRule::kNonZero).is_ok());
  CHECK(canvas.image().at(2, 0) == Rgba8{255, 0, 0, 255});  // first clip only: 0..8.5
  CHECK(canvas.image().at(12, 0) == Rgba8{});
  REQUIRE(canvas.pop_clip().is_ok());
  CHECK_FALSE(canvas.pop_clip().is_ok());
}

TEST_CASE("even-odd and transformed clip paths", "[paint][clip]") {
  const Path frame = *PathBuilder()
                          .move_to({0, 0})
                          .line_to({4, 0})
                          .line_to({4, 4})
                          .line_to({0, 4})
                          .close()
                          .move_to({1, 1})
                          .line_to({3, 1})
                          .line_to({3, 3})
                          .line_to({1, 3})
                          .close()
                          .build();
  Canvas canvas{Image(8, 8)};
  REQUIRE(canvas.push_clip(frame, FillRule::kEvenOdd, Affine::scale(2)).is_ok());
  REQUIRE(canvas.fill(rect_path(0, 0, 8, 8), kRed, FillRule::kNonZero).is_ok());
  CHECK(canvas.image().at(0, 0) == Rgba8{255, 0, 0, 255});
  CHECK(canvas.image().at(4, 4) == Rgba8{});  // the hole
  CHECK(canvas.image().at(7, 7) == Rgba8{255, 0, 0, 255});
  Canvas bad{Image(8, 8)};
  CHECK_FALSE(bad.push_clip(frame, FillRule::kNonZero, Affine::scale(std::numeric_limits<double>::infinity()))
                  .is_ok());
  FillOptions zero_tolerance;
  zero_tolerance.tolerance = 0.0;
  CHECK_FALSE(bad.push_clip(frame, FillRule::kNonZero, Affine::identity(), zero_tolerance).is_ok());
  CHECK(bad.clip_depth() == 0);
}

TEST_CASE("a clip around a group is applied once, to the group's result", "[paint][clip][layer]") {
  // Column 4 is half inside the clip. Drawing the group through the clip and clipping its result again
  // would give 64 there (coverage squared, what cairo_clip + cairo_push_group does); SVG wants 128.
  Canvas canvas{Image(8, 2)};
  REQUIRE(canvas.push_clip(rect_path(0, 0, 4.5, 2), FillRule::kNonZero).is_ok());
  REQUIRE(canvas.push_layer().is_ok());
  REQUIRE(canvas.fill(rect_path(0, 0, 8, 2), kRed, FillRule::kNonZero).is_ok());
  CHECK_FALSE(canvas.pop_clip().is_ok());  // the clip belongs to the level below the layer
  REQUIRE(canvas.pop_layer(1.0).is_ok());
  REQUIRE(canvas.pop_clip().is_ok());
  CHECK(canvas.image().at(4, 0) == Rgba8{128, 0, 0, 128});
  CHECK(canvas.image().at(6, 0) == Rgba8{});
}

TEST_CASE("pop_layer refuses while a clip pushed inside the layer is open", "[paint][clip][layer]") {
  Canvas canvas{Image(8, 8)};
  REQUIRE(canvas.push_layer().is_ok());
  REQUIRE(canvas.push_clip(rect_path(0, 0, 4, 4), FillRule::kNonZero).is_ok());
  CHECK_FALSE(canvas.pop_layer(1.0).is_ok());
  REQUIRE(canvas.pop_clip().is_ok());
  CHECK(canvas.pop_layer(1.0).is_ok());
}

TEST_CASE("clips nest up to kMaxClipDepth", "[paint][clip][limits]") {
  Canvas canvas{Image(8, 8)};
  for (int i = 0; i < kMaxClipDepth; ++i)
    REQUIRE(canvas.push_clip(rect_path(0, 0, 8, 8), FillRule::kNonZero).is_ok());
  const Status refused = canvas.push_clip(rect_path(0, 0, 8, 8), FillRule::kNonZero);
  REQUIRE_FALSE(refused.is_ok());
  CHECK(refused.error().kind == ErrorKind::kLimitExceeded);
}

TEST_CASE("ClipMask::intersect multiplies with pixman rounding and intersects bounds", "[paint][clip]") {
  ClipMask a(4, 1), b(4, 1);
  const Span sa[] = {{0, 0, 3, 200}};
  const Span sb[] = {{1, 0, 3, 100}};
  a.write_spans(sa);
  b.write_spans(sb);
  a.intersect(b);
  CHECK(a.at(0, 0) == 0);
  CHECK(a.at(1, 0) == 78);  // 200·100/255 = 78.4 -> 78
  CHECK(a.at(3, 0) == 0);
  CHECK(a.bounds() == IntRect{1, 0, 3, 1});
  for (unsigned x = 0; x < 256; ++x) {
    for (unsigned y = 0; y < 256; y += 5) CHECK(multiply_coverage(x, y) == (x * y + 127) / 255);
  }
}

TEST_CASE("gradients draw into layers and through clips at device positions", "[paint][gradient][layer]") {
  const std::vector<GradientStop> stops{{0.0, {0, 0, 0, 1}}, {1.0, {1, 1, 1, 1}}};
  const Paint ramp = linear_gradient_paint({{0, 0}, {16, 0}}, stops, SpreadMethod::kPad);
  Canvas direct{Image(16, 4)};
  REQUIRE(direct.fill(rect_path(0, 0, 16, 4), ramp, FillRule::kNonZero).is_ok());
  Canvas layered{Image(16, 4)};
  layered.set_clip({5, 1, 14, 3});
  REQUIRE(layered.push_layer().is_ok());  // a layer with its origin at (5, 1)
  REQUIRE(layered.fill(rect_path(0, 0, 16, 4), ramp, FillRule::kNonZero).is_ok());
  REQUIRE(layered.pop_layer(1.0).is_ok());
  for (int x = 5; x < 14; ++x) CHECK(layered.image().at(x, 2) == direct.image().at(x, 2));
  CHECK(layered.image().at(4, 2) == Rgba8{});
  CHECK(direct.image().at(0, 0).r < direct.image().at(15, 0).r);
}

TEST_CASE("push_clip_mask: a ready-made coverage mask clips like a clip path and intersects with one",
          "[paint][clip]") {
  // A 4 x 1 mask 0, 64, 128, 255: a layer of opaque red composited through it keeps exactly those alphas
  // (MUL_UN8(255, m) = m), and a half-covering clip path pushed first halves them (pixman rounding).
  std::vector<std::uint8_t> values{0, 64, 128, 255};
  ClipMask mask = ClipMask::from_values(4, 1, values);
  CHECK(mask.bounds().x0 == 1);  // tight: column 0 is 0
  CHECK(mask.bounds().x1 == 4);
  Canvas canvas{Image(4, 1)};
  REQUIRE(canvas.push_clip_mask(mask).is_ok());
  REQUIRE(canvas.push_layer().is_ok());
  REQUIRE(canvas.fill(rect_path(0, 0, 4, 1), kRed, FillRule::kNonZero).is_ok());
  REQUIRE(canvas.pop_layer(1.0).is_ok());
  REQUIRE(canvas.pop_clip().is_ok());
  CHECK(canvas.image().at(0, 0) == Rgba8{});
  CHECK(canvas.image().at(1, 0) == Rgba8{64, 0, 0, 64});
  CHECK(canvas.image().at(2, 0) == Rgba8{128, 0, 0, 128});
  CHECK(canvas.image().at(3, 0) == Rgba8{255, 0, 0, 255});

  Canvas halved{Image(4, 1)};
  REQUIRE(halved.push_clip(rect_path(0, 0, 4, 0.5), FillRule::kNonZero).is_ok());  // coverage 128
  REQUIRE(halved.push_clip_mask(ClipMask::from_values(4, 1, values)).is_ok());
  REQUIRE(halved.fill(rect_path(0, 0, 4, 1), kRed, FillRule::kNonZero).is_ok());
  CHECK(halved.image().at(3, 0).a == multiply_coverage(255, 128));
  CHECK(halved.image().at(2, 0).a == multiply_coverage(128, 128));

  CHECK_FALSE(canvas.push_clip_mask(ClipMask(3, 1)).is_ok());      // not the canvas's size
  CHECK(ClipMask::from_values(2, 2, {1, 2, 3}).bounds().empty());  // wrong count: lets nothing through
}
