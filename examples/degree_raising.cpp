// example_degree_raising [OUT_DIR]: writes OUT_DIR/degree_raising.png and prints its caption
// (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("degree_raising", argc, argv);
}
