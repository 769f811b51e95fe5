// example_knot_multiplicity [OUT_DIR]: writes OUT_DIR/knot_multiplicity.png and prints its caption
// (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("knot_multiplicity", argc, argv);
}
