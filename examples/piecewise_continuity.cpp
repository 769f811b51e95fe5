// example_piecewise_continuity [OUT_DIR]: writes OUT_DIR/piecewise_continuity.png and prints its caption
// (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("piecewise_continuity", argc, argv);
}
