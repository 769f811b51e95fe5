// example_first_example [OUT_DIR]: writes OUT_DIR/first_example.png and prints its caption
// (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("first_example", argc, argv);
}
