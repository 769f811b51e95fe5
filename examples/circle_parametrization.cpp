// example_circle_parametrization [OUT_DIR]: writes OUT_DIR/circle_parametrization.png and prints its caption
// (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("circle_parametrization", argc, argv);
}
