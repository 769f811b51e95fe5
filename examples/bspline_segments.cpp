// example_bspline_segments [OUT_DIR]: writes OUT_DIR/bspline_segments.png and prints its caption
// (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("bspline_segments", argc, argv);
}
