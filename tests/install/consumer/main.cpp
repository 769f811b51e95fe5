// A program outside the project, built against an installed curvescan: what a user of the library does.
#include <cstdio>
#include "curvescan/curves/nurbs.h"
#include "curvescan/raster/canvas.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/png_io.h"
int main(int argc, char** argv) {
  if (argc != 2) return 64;
  using namespace curvescan;
  auto circle = Nurbs::circle({50, 50}, 40);
  PathBuilder builder;
  for (const auto& piece : circle->to_rational_beziers()) builder.append(piece);
  builder.close();
  auto path = builder.build();
  auto canvas = Canvas::create(100, 100);
  if (!path || !canvas) return 1;
  if (!canvas->fill(*path, Paint::solid({200, 30, 30, 255}), FillRule::kNonZero)) return 2;
  if (!write_png(canvas->image(), argv[1])) return 3;
  std::puts("ok");
}
