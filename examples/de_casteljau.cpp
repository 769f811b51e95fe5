// example_de_casteljau [OUT_DIR]: writes OUT_DIR/de_casteljau.png and prints its caption (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("de_casteljau", argc, argv);
}
