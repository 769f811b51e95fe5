// example_illustration [OUT_DIR]: writes OUT_DIR/illustration.png and prints its caption (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("illustration", argc, argv);
}
