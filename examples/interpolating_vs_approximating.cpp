// example_interpolating_vs_approximating [OUT_DIR]: writes OUT_DIR/interpolating_vs_approximating.png and
// prints its caption (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("interpolating_vs_approximating", argc, argv);
}
