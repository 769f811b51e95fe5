#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

#include "curvescan/raster/png_io.h"
#include "figure/figures.h"

namespace curvescan::figure {

namespace {

constexpr std::array kFigures{
    FigureInfo{
        "bspline_basis",
        "B-spline basis functions N(i,p) for p = 0..3 on uniform knots, each drawn exactly as a B-spline "
        "curve (Umetani, Parametric Curve, Fig. 1, eq. 6-7)",
        render_bspline_basis},
    FigureInfo{"cox_de_boor",
               "Cox-de Boor: two p = 1 hat functions times their linear ramps sum to one p = 2 function "
               "(Umetani, Parametric Curve, Fig. 2, eq. 7)",
               render_cox_de_boor},
    FigureInfo{"knot_insertion",
               "A cubic B-spline before and after inserting the knot u = 0.45: same curve, one more control "
               "point on the old polygon (Umetani, Parametric Curve, section 3.3, eq. 8-9)",
               render_knot_insertion},
    FigureInfo{"nurbs_circle",
               "The exact circle as a quadratic NURBS: 9 control points on a square, weights 1 and sqrt(2)/2 "
               "(Umetani, Parametric Curve, section 4.1, eq. 10)",
               render_nurbs_circle},
    FigureInfo{"de_casteljau",
               "de Casteljau's construction of linear, quadratic and cubic Beziers at t = 0.4 "
               "(Ince, Curves, \"Bezier Curves\", Gallivan, Parametric Curves, \"DeCasteljau's Algorithm\")",
               render_de_casteljau},
    FigureInfo{
        "bspline_segments",
        "Quadratic and cubic uniform B-splines: each segment S_k in its own colour, knots at the joins "
        "(Ince, Curves, \"Quadratic/Cubic B-spline Curves\")",
        render_bspline_segments},
    FigureInfo{
        "bezier_degrees",
        "Bezier curves of degree 3, 4 and 10 with their control polygons (Ince, Curves, \"Bezier Curves\")",
        render_bezier_degrees},
    FigureInfo{"catmull_rom",
               "Uniform, chordal and centripetal Catmull-Rom splines through the same points "
               "(Ince, Curves, \"Spline Parametrization\")",
               render_catmull_rom},
    FigureInfo{"interpolating_vs_approximating",
               "The same points interpolated (C2 cubic spline) and approximated (cubic B-spline) "
               "(Ince, Curves, \"Interpolated / Approximated\")",
               render_interpolating_vs_approximating},
    FigureInfo{
        "teapot",
        "The Utah teapot (Newell's 32 bicubic Bezier patches) in wireframe: iso-curves projected exactly, "
        "as cubics in a parallel view and rational cubics in perspective (Ince, Curves, \"Bezier surfaces\")",
        render_teapot},
    FigureInfo{"curve_representations",
               "Explicit and implicit curves from certified polylines: y = tan x split at its poles, the "
               "lemniscate through its singular point, y^2 = x^3 - x in two components (Ince, Curves, "
               "\"Representations of Curves\")",
               render_curve_representations},
    FigureInfo{"hermite_blending",
               "The four Hermite blending functions (Dill, Introduction to Parametric Curves, \"Blending "
               "Functions\", U. of Toronto, Parametric Curves, \"Hermite "
               "Curves\")",
               render_hermite_blending},
    FigureInfo{
        "bezier_blending",
        "Bezier (Bernstein) blending functions of degree 2, 3 and 5, drawn exactly "
        "(Dill, Introduction to Parametric Curves, \"Bezier Blending Functions of degree 2, 3, and 5\")",
        render_bezier_blending},
    FigureInfo{"bezier_joins",
               "Two cubic Beziers joined with C0, C1 and C2 continuity, classified by classify_join "
               "(Dill, Introduction to Parametric Curves, \"Joining Bezier Curves\")",
               render_bezier_joins},
    FigureInfo{"degree_raising",
               "Degree raising: one cubic and the same curve as degree 4, 5 and 8 Beziers "
               "(Dill, Introduction to Parametric Curves, \"Degree Raising\")",
               render_degree_raising},
    FigureInfo{"circle_parametrization",
               "Cubic splines through unevenly spaced points on a circle, uniform vs arc-length parameters "
               "(Gallivan, Parametric Curves, \"Parameterization\")",
               render_circle_parametrization},
    FigureInfo{"closed_curve",
               "A closed C2 cubic spline and a closed cubic B-spline around the same points "
               "(Gallivan, Parametric Curves, \"Closed Curve Data\", \"repeating knots and control points "
               "closes the curve\")",
               render_closed_curve},
    FigureInfo{"first_example",
               "The four-constraint cubic: end points, midpoint and the tangent there, for several tangents "
               "(U. of Toronto, Parametric Curves, \"A First Example\")",
               render_first_example},
    FigureInfo{"piecewise_continuity",
               "Piecewise Hermite curve with its tangents, and the same pieces as Beziers with collinear "
               "control points at the joins (U. of Toronto, Parametric Curves, \"Hermite Curves\", "
               "\"Geometric and Parametric "
               "Continuity\")",
               render_piecewise_continuity},
    FigureInfo{"knot_multiplicity",
               "A cubic B-spline with an interior knot of multiplicity 1, 2 and 3, and its basis functions "
               "(U. of Toronto, Parametric Curves, \"Splines\", Gallivan, Parametric Curves, \"knots can "
               "have multiplicity\")",
               render_knot_multiplicity},
    FigureInfo{
        "illustration",
        "An illustration of curvescan's own: NURBS circles, Catmull-Rom and B-spline shapes, gradients "
        "and group opacity",
        render_illustration},
    FigureInfo{"text_specimen",
               "Text specimen: DejaVu Sans through FreeType outlines and HarfBuzz layout, and one glyph's "
               "quadratic control points",
               render_text_specimen},
    FigureInfo{"stroke_styles",
               "Stroke joins (miter, miter-clip, round, bevel), caps (butt, round, square) and dash patterns",
               render_stroke_styles},
    FigureInfo{
        "filter_effects",
        "SVG filter effects: drop shadow, glow, fractal noise, specular lighting, displacement, dilation, "
        "hue rotation and an edge-detecting convolution, each on its own shape",
        render_filter_effects},
};

}  // namespace

std::span<const FigureInfo> all_figures() noexcept {
  return kFigures;
}

const FigureInfo* find_figure(std::string_view name) noexcept {
  for (const FigureInfo& info : kFigures) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

int run_example(std::string_view name, int argc, char** argv) {
  const std::string program = "example_" + std::string(name);
  // An argument starting with '-' is an option, not a directory: -h and --help print the usage (and
  // must not create a directory called "--help"); anything else is a usage error.
  const bool asks_help =
      argc == 2 && (std::string_view(argv[1]) == "-h" || std::string_view(argv[1]) == "--help");
  if (asks_help) {
    std::printf("usage: %s [OUT_DIR]\nwrites %s.png into OUT_DIR (default: the current directory)\n",
                program.c_str(), std::string(name).c_str());
    return 0;
  }
  if (argc > 2 || (argc == 2 && argv[1][0] == '-')) {
    std::fprintf(stderr, "usage: %s [OUT_DIR]\n", program.c_str());
    return 64;
  }
  const FigureInfo* info = find_figure(name);
  if (info == nullptr) {
    std::fprintf(stderr, "%s: error: no figure is called \"%s\"\n", program.c_str(),
                 std::string(name).c_str());
    return 1;
  }
  const std::filesystem::path out_dir =
      argc == 2 ? std::filesystem::path(argv[1]) : std::filesystem::path(".");
  Result<Image> image = info->render();
  if (!image) {
    std::fprintf(stderr, "%s: error: %s\n", program.c_str(), image.error().message.c_str());
    return 1;
  }
  std::error_code ignored;
  std::filesystem::create_directories(out_dir, ignored);  // write_png reports the failure that matters
  const std::filesystem::path file = out_dir / (std::string(name) + ".png");
  if (Status written = write_png(*image, file); !written) {
    std::fprintf(stderr, "%s: error: %s\n", program.c_str(), written.error().message.c_str());
    return 1;
  }
  std::printf("%s\n", std::string(info->caption).c_str());
  return 0;
}

}  // namespace curvescan::figure
