// A page of stroke styles (SVG 2 §13.5 "Stroke properties", stroke.h): the four joins on the same
// zig-zag, the three caps on the same segment, and dash patterns along a curve, each with its centre line
// drawn thin on top so that the geometry of the outline can be read against the path.
#include <array>
#include <string>
#include <vector>

#include "curvescan/raster/path_builder.h"
#include "figure/figure.h"
#include "figure/figures.h"
#include "figure/palette.h"

namespace curvescan::figure {

namespace {

void centre_line(Figure& figure, const Result<Path>& path) {
  StrokeStyle thin;
  thin.width = 1.25;
  thin.join = LineJoin::kRound;
  figure.stroke(path, kInk, thin);
}

}  // namespace

Result<Image> render_stroke_styles() {
  Result<Figure> made = Figure::create(960, 640);
  if (!made) return made.error();
  Figure& figure = *made;
  figure.text("Stroke joins, caps and dashes", {480.0, 32.0}, 18.0, kInk, TextAnchor::kMiddle);

  // Joins: a zig-zag with a sharp (about 29.4°) and a wide corner; miter limit 3, so the sharp corner's
  // miter (ratio 1/sin(14.7°) ≈ 3.9) is over the limit: kMiter falls back to a bevel there, kMiterClip
  // cuts it at 3 half-widths from the vertex.
  struct JoinCase {
    LineJoin join;
    const char* name;
  };
  const std::array<JoinCase, 4> joins{
      JoinCase{LineJoin::kMiter, "miter (limit 3)"}, JoinCase{LineJoin::kMiterClip, "miter-clip (limit 3)"},
      JoinCase{LineJoin::kRound, "round"}, JoinCase{LineJoin::kBevel, "bevel"}};
  for (std::size_t k = 0; k < joins.size(); ++k) {
    const double x = 50.0 + 225.0 * static_cast<double>(k);
    const Result<Path> zigzag = PathBuilder()
                                    .move_to({x, 190.0})
                                    .line_to({x + 50.0, 90.0})
                                    .line_to({x + 55.0, 190.0})
                                    .line_to({x + 140.0, 120.0})
                                    .build();
    StrokeStyle style;
    style.width = 22.0;
    style.join = joins[k].join;
    style.miter_limit = 3.0;
    figure.stroke(zigzag, series(k), style);
    centre_line(figure, zigzag);
    figure.text(joins[k].name, {x + 75.0, 230.0}, 13.0, kInk, TextAnchor::kMiddle);
  }

  // Caps: the same horizontal segment; thin guides mark where the path ends.
  struct CapCase {
    LineCap cap;
    const char* name;
  };
  const std::array<CapCase, 3> caps{CapCase{LineCap::kButt, "butt"}, CapCase{LineCap::kRound, "round"},
                                    CapCase{LineCap::kSquare, "square"}};
  for (std::size_t k = 0; k < caps.size(); ++k) {
    const double x = 90.0 + 300.0 * static_cast<double>(k);
    const Result<Path> segment = PathBuilder().move_to({x, 300.0}).line_to({x + 180.0, 300.0}).build();
    for (double end : {x, x + 180.0}) {
      StrokeStyle guide;
      guide.width = 1.0;
      figure.stroke(PathBuilder().move_to({end, 275.0}).line_to({end, 325.0}).build(), kControl, guide);
    }
    StrokeStyle style;
    style.width = 28.0;
    style.cap = caps[k].cap;
    figure.stroke(segment, with_alpha(series(k + 4), 220), style);
    centre_line(figure, segment);
    figure.text(caps[k].name, {x + 90.0, 350.0}, 13.0, kInk, TextAnchor::kMiddle);
  }

  // Dashes along one wave (a cubic and its smooth continuation), measured by arc length (stroke.h).
  struct DashCase {
    std::vector<double> dashes;
    double offset;
    LineCap cap;
    const char* name;
  };
  const std::array<DashCase, 4> dashes{
      DashCase{{24.0, 12.0}, 0.0, LineCap::kButt, "24 12, butt caps"},
      DashCase{{24.0, 12.0}, 18.0, LineCap::kButt, "24 12, offset 18"},
      DashCase{{36.0, 10.0, 4.0, 10.0}, 0.0, LineCap::kRound, "36 10 4 10, round caps"},
      DashCase{{0.0, 16.0}, 0.0, LineCap::kRound, "0 16, round caps: dots"}};
  for (std::size_t k = 0; k < dashes.size(); ++k) {
    const double y = 410.0 + 58.0 * static_cast<double>(k);
    const Result<Path> wave = PathBuilder()
                                  .move_to({60.0, y})
                                  .cubic_to({180.0, y - 45.0}, {260.0, y + 45.0}, {380.0, y})
                                  .cubic_to({500.0, y - 45.0}, {580.0, y + 45.0}, {700.0, y})
                                  .build();
    StrokeStyle style;
    style.width = 9.0;
    style.cap = dashes[k].cap;
    style.join = LineJoin::kRound;
    style.dash_array = dashes[k].dashes;
    style.dash_offset = dashes[k].offset;
    figure.stroke(wave, series(k), style);
    figure.text(dashes[k].name, {730.0, y + 5.0}, 13.0, kInk);
  }
  return std::move(figure).finish();
}

}  // namespace curvescan::figure
