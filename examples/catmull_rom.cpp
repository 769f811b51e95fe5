// example_catmull_rom [OUT_DIR]: writes OUT_DIR/catmull_rom.png and prints its caption (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("catmull_rom", argc, argv);
}
