// example_filter_effects [OUT_DIR]: writes OUT_DIR/filter_effects.png and prints its caption
// (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("filter_effects", argc, argv);
}
