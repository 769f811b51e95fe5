// example_closed_curve [OUT_DIR]: writes OUT_DIR/closed_curve.png and prints its caption (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("closed_curve", argc, argv);
}
