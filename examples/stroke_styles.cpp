// example_stroke_styles [OUT_DIR]: writes OUT_DIR/stroke_styles.png and prints its caption
// (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("stroke_styles", argc, argv);
}
