// Fuzz target expression: the formula language of explicit and implicit curves (expression.h). The input
// is the expression text. A parsed expression is evaluated in double, in interval arithmetic and as an
// interval gradient, and the inclusion property is checked: at every sample point of a box the double
// value is NaN (then the box's enclosure must say `partial`) or inside the enclosure — a violation traps,
// so a wrong enclosure is reported like a crash. Then the expression is drawn as a small explicit curve and
// a small implicit curve, with low limits so that one input stays fast.
#include "curvescan/curves/expression.h"

#include <cmath>
#include <string_view>

#include "curvescan/curves/explicit_curve.h"
#include "curvescan/curves/implicit_curve.h"
#include "fuzz_targets.h"

namespace curvescan::fuzz {
namespace {

constexpr ExpressionVariable kVariables[] = {ExpressionVariable::kX, ExpressionVariable::kY,
                                             ExpressionVariable::kT};
// Work per input: graph pieces and quadtree cells examined (each a few evaluations of up to 4096 nodes),
// and their product with the expression's size.
constexpr std::size_t kMaxPieces = 100;

struct Box {
  double x0, x1, y0, y1;
};
// Boxes from a point to the huge, around 0 and the poles of tan, the domain edges of log and asin.
constexpr Box kBoxes[] = {
    {-2.0, 2.0, -1.5, 1.0},
    {0.5, 0.5, -0.25, -0.25},
    {1.5707963267948966, 1.5707963267948968, 0.0, 1.0},
    {-1e-300, 1e-300, 0.0, 0.0},
    {-1e300, 1e300, -1.0, 1.0},
    {0.999, 1.001, -1.001, -0.999},
};

void check_inclusion(const Expression& f, const Box& box) {
  const Interval x{box.x0, box.x1}, y{box.y0, box.y1}, t = Interval::point(0.5);
  const Interval enclosure = f.evaluate(x, y, t);
  for (int i = 0; i <= 4; ++i) {
    for (int j = 0; j <= 4; ++j) {
      const double px = i == 4 ? box.x1 : box.x0 + (box.x1 - box.x0) * 0.25 * i;
      const double py = j == 4 ? box.y1 : box.y0 + (box.y1 - box.y0) * 0.25 * j;
      if (!(px >= box.x0 && px <= box.x1 && py >= box.y0 && py <= box.y1)) continue;  // x1 − x0 overflowed
      const double value = f.evaluate(px, py, 0.5);
      if (std::isnan(value) ? !enclosure.partial : !enclosure.contains(value)) __builtin_trap();
    }
  }
}

}  // namespace

int fuzz_expression(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);  // bytes as characters
  const Result<Expression> f = Expression::parse(text, kVariables);
  if (!f) {
    if (f.error().message.empty()) __builtin_trap();  // every error says what is wrong
    return 0;
  }
  for (const Box& box : kBoxes) check_inclusion(*f, box);
  (void)f->evaluate_gradient(Interval{-2.0, 2.0}, Interval{-1.0, 1.0});
  ExplicitCurveOptions explicit_options;
  explicit_options.tolerance = 0.05;
  explicit_options.max_pieces = kMaxPieces;
  explicit_options.max_work = kMaxPieces * 64;
  (void)flatten_explicit_curve(*f, -2.0, 2.0, explicit_options);
  ImplicitCurveOptions implicit_options;
  implicit_options.tolerance = 0.1;
  implicit_options.max_cells = kMaxPieces;
  implicit_options.max_work = kMaxPieces * 64;
  (void)contour_implicit_curve(*f, {-2.0, -1.5}, {2.0, 1.0}, implicit_options);
  return 0;
}

}  // namespace curvescan::fuzz
