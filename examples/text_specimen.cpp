// example_text_specimen [OUT_DIR]: writes OUT_DIR/text_specimen.png and prints its caption
// (figure/figures.h).
#include "figure/figures.h"

int main(int argc, char** argv) {
  return curvescan::figure::run_example("text_specimen", argc, argv);
}
