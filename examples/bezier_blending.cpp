// example_bezier_blending [OUT_DIR]: writes OUT_DIR/bezier_blending.png and prints its caption
// (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("bezier_blending", argc, argv);
}
