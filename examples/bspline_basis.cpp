// example_bspline_basis [OUT_DIR]: writes OUT_DIR/bspline_basis.png and prints its caption
// (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("bspline_basis", argc, argv);
}
