// example_bezier_degrees [OUT_DIR]: writes OUT_DIR/bezier_degrees.png and prints its caption
// (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("bezier_degrees", argc, argv);
}
