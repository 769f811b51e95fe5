// example_curve_representations [OUT_DIR]: writes OUT_DIR/curve_representations.png and prints its caption
// (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("curve_representations", argc, argv);
}
