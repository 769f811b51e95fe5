// example_bezier_joins [OUT_DIR]: writes OUT_DIR/bezier_joins.png and prints its caption (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("bezier_joins", argc, argv);
}
