// example_nurbs_circle [OUT_DIR]: writes OUT_DIR/nurbs_circle.png and prints its caption (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("nurbs_circle", argc, argv);
}
