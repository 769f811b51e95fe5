// The gallery: every figure as a function that renders it, and the registry the example programs and the
// golden test (tests/golden/figures_test.cpp) share. Each figure cites the note and section it redraws.
#pragma once

#include <span>
#include <string_view>

#include "curvescan/raster/image.h"
#include "curvescan/status.h"

namespace curvescan::figure {

// Umetani, "Parametric Curve"
[[nodiscard]] Result<Image> render_bspline_basis();
[[nodiscard]] Result<Image> render_cox_de_boor();
[[nodiscard]] Result<Image> render_knot_insertion();
[[nodiscard]] Result<Image> render_nurbs_circle();
// Ince (after Elias), "Lecture 11: Curves"
[[nodiscard]] Result<Image> render_de_casteljau();
[[nodiscard]] Result<Image> render_bspline_segments();
[[nodiscard]] Result<Image> render_bezier_degrees();
[[nodiscard]] Result<Image> render_catmull_rom();
[[nodiscard]] Result<Image> render_interpolating_vs_approximating();
// Dill, "Introduction to Parametric Curves"
[[nodiscard]] Result<Image> render_hermite_blending();
[[nodiscard]] Result<Image> render_bezier_blending();
[[nodiscard]] Result<Image> render_bezier_joins();
[[nodiscard]] Result<Image> render_degree_raising();
// Gallivan, "Parametric Curves"
[[nodiscard]] Result<Image> render_circle_parametrization();
[[nodiscard]] Result<Image> render_closed_curve();
// "Parametric Curves" (U. of Toronto course notes)
[[nodiscard]] Result<Image> render_first_example();
[[nodiscard]] Result<Image> render_piecewise_continuity();
[[nodiscard]] Result<Image> render_knot_multiplicity();
// scenes of the project's own
[[nodiscard]] Result<Image> render_illustration();
[[nodiscard]] Result<Image> render_text_specimen();
[[nodiscard]] Result<Image> render_stroke_styles();
[[nodiscard]] Result<Image> render_filter_effects();
// Ince, *Lecture 11: Curves*: Bézier surface patches; explicit and implicit representations
[[nodiscard]] Result<Image> render_teapot();
[[nodiscard]] Result<Image> render_curve_representations();

struct FigureInfo {
  std::string_view name;     ///< file stem of the PNG and of the example program (example_<name>)
  std::string_view caption;  ///< what the figure shows and which note it comes from
  Result<Image> (*render)();
};

/// Every figure, in gallery order.
[[nodiscard]] std::span<const FigureInfo> all_figures() noexcept;
/// The figure called `name`, or null.
[[nodiscard]] const FigureInfo* find_figure(std::string_view name) noexcept;

/// The main() of example_<name>: renders the figure into OUT_DIR/<name>.png (OUT_DIR = argv[1], default
/// the current directory) and prints its caption on one line. Errors: one line on stderr, exit code 1
/// (64 for a malformed command line).
int run_example(std::string_view name, int argc, char** argv);

}  // namespace curvescan::figure
