// example_teapot [OUT_DIR]: writes OUT_DIR/teapot.png and prints its caption (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("teapot", argc, argv);
}
