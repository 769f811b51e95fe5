// The Utah teapot in wireframe (Ince after Elias, *Lecture 11: Curves*, "Bézier surfaces": 32 bicubic
// Bézier patches make the teapot). Every line is an isoparametric curve of a patch, projected exactly:
// a cubic under the parallel view, a rational cubic under the perspective one (bezier_patch.h,
// view_transform.h), stroked through the ordinary path pipeline — nothing is sampled.
#include <string>

#include "curvescan/curves/bezier_patch.h"
#include "curvescan/curves/view_transform.h"
#include "curvescan/raster/path_builder.h"
#include "figure/figure.h"
#include "figure/figures.h"
#include "figure/palette.h"
#include "figure/utah_teapot.h"

namespace curvescan::figure {
namespace {

// Iso-curves per patch and direction, the boundaries included: 0, 1/3, 2/3, 1.
constexpr int kIsoCurves = 4;

// Strokes the teapot's iso-curves under `view`: patch boundaries (parameter 0 and 1) dark, the curves
// between lighter.
void draw_teapot(Figure& figure, const ViewTransform& view) {
  PathBuilder boundaries, interior;
  for (std::size_t p = 0; p < kTeapotPatchCount; ++p) {
    const BezierPatch patch = teapot_patch(p);
    for (int k = 0; k < 2 * kIsoCurves; ++k) {
      const double t = static_cast<double>(k % kIsoCurves) / (kIsoCurves - 1);
      const Result<ProjectedCubic> cubic =
          project_cubic(k < kIsoCurves ? patch.curve_at_u(t) : patch.curve_at_v(t), view);
      if (!cubic) {
        figure.record(cubic.error());
        return;
      }
      PathBuilder& builder = (t == 0.0 || t == 1.0) ? boundaries : interior;
      builder.move_to(cubic->points[0]);
      if (cubic->is_rational()) {
        builder.rational_bezier_to(std::span(cubic->points).subspan(1), cubic->weights);
      } else {
        builder.bezier_to(std::span(cubic->points).subspan(1));
      }
    }
  }
  StrokeStyle style;
  style.join = LineJoin::kRound;
  style.cap = LineCap::kRound;
  style.width = 1.0;
  figure.stroke(interior.build(), kBlue, style);
  style.width = 1.6;
  figure.stroke(boundaries.build(), kInk, style);
}

}  // namespace

Result<Image> render_teapot() {
  Result<Figure> made = Figure::create(960, 480);
  if (!made) return made.error();
  Figure& figure = *made;
  figure.text("The Utah teapot: 32 bicubic B\u00e9zier patches, iso-curves projected exactly", {480.0, 30.0},
              18.0, kInk, TextAnchor::kMiddle);
  Camera camera;
  camera.eye = {6.5, -9.0, 6.0};
  camera.target = {0.2, 0.0, 1.3};
  camera.up = {0.0, 0.0, 1.0};
  // Left: a parallel (orthographic) view — the iso-curves are polynomial cubics.
  camera.scale = 72.0;
  camera.centre = {240.0, 245.0};
  Result<ViewTransform> parallel = ViewTransform::look_at(camera);
  if (!parallel) return parallel.error();
  draw_teapot(figure, *parallel);
  figure.text("parallel view: cubic B\u00e9ziers", {240.0, 440.0}, 14.0, kMutedInk, TextAnchor::kMiddle);
  // Right: a perspective view from the same eye — rational cubics, weights the depths of the control points.
  camera.scale = 1.0;
  camera.focal = 800.0;
  camera.centre = {700.0, 240.0};
  Result<ViewTransform> perspective = ViewTransform::look_at(camera);
  if (!perspective) return perspective.error();
  draw_teapot(figure, *perspective);
  figure.text("perspective view: rational cubic B\u00e9ziers", {700.0, 440.0}, 14.0, kMutedInk,
              TextAnchor::kMiddle);
  return std::move(figure).finish();
}

}  // namespace curvescan::figure
