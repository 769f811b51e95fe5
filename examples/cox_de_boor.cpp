// example_cox_de_boor [OUT_DIR]: writes OUT_DIR/cox_de_boor.png and prints its caption (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("cox_de_boor", argc, argv);
}
