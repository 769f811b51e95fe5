// Test support: the Cairo oracle. Renders a Shape into an A8 surface with CAIRO_ANTIALIAS_DEFAULT and
// returns its coverage mask, for comparison with curvescan's.
#pragma once

#include <cairo.h>

#include "coverage_mask.h"

namespace curvescan::testing {

inline CoverageMask render_cairo(const Shape& shape, int width, int height, FillRule rule) {
  CoverageMask mask(width, height);
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_A8, width, height);
  cairo_t* cr = cairo_create(surface);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
  cairo_set_fill_rule(cr, rule == FillRule::kNonZero ? CAIRO_FILL_RULE_WINDING : CAIRO_FILL_RULE_EVEN_ODD);
  cairo_set_source_rgba(cr, 0.0, 0.0, 0.0, 1.0);
  for (const Contour& contour : shape) {
    if (contour.empty()) continue;
    cairo_move_to(cr, contour[0].x, contour[0].y);
    for (std::size_t i = 1; i < contour.size(); ++i) cairo_line_to(cr, contour[i].x, contour[i].y);
    cairo_close_path(cr);
  }
  cairo_fill(cr);
  cairo_surface_flush(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) mask.at(x, y) = data[static_cast<std::size_t>(y) * stride + x];
  }
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  return mask;
}

}  // namespace curvescan::testing
