// Every B-spline and knot-vector builder rejects malformed input with an Error and a message.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "curvescan/curves/bspline.h"
#include "curvescan/curves/knot_vector.h"

namespace curvescan {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

template <class R>
void require_error(const R& result, const std::string& fragment) {
  REQUIRE_FALSE(result.is_ok());
  REQUIRE(result.status().error().kind == ErrorKind::kInvalidArgument);
  INFO("message: " << result.status().error().message);
  REQUIRE(result.status().error().message.find(fragment) != std::string::npos);
}

const std::vector<Point> kFour{{0, 0}, {1, 0}, {1, 1}, {0, 1}};

TEST_CASE("BSpline::create rejects malformed knot vectors", "[bspline][errors]") {
  require_error(BSpline::create(kFour, {0, 0, 0, 1, 1, 1}, 2), "knot count 6 != n + p + 1 = 7");
  require_error(BSpline::create(kFour, {0, 0, 0, 2, 1, 1, 1}, 2), "knots decrease at index 4");
  require_error(BSpline::create(kFour, {0, 0, 0, kNaN, 1, 1, 1}, 2), "knot 3 is not finite");
  require_error(BSpline::create(kFour, {0, 0, 0, 0, 1, 1, 1}, 2), "multiplicity above degree + 1");
  require_error(BSpline::create(kFour, {0, 1, 1, 1, 1, 1, 2, 3}, 3), "multiplicity");
  require_error(BSpline::create(kFour, {0, 0, 1, 1, 1, 2, 3}, 2), "is empty");  // u_2 = u_4 = 1
  require_error(BSpline::create(kFour, {0, 1, 2, 3, 4, 5, 6, 7, 8}, 4),
                "degree must be below the point count");
  require_error(BSpline::create(kFour, {0, 1, 2, 3}, -1), "degree -1");
}

TEST_CASE("BSpline factories reject bad points and degrees", "[bspline][errors]") {
  std::vector<Point> bad = kFour;
  bad[2].y = kNaN;
  require_error(BSpline::create(bad, {0, 0, 0, 0.5, 1, 1, 1}, 2), "control point 2");
  require_error(BSpline::clamped(bad, 2), "control point 2");
  require_error(BSpline::clamped(kFour, 4), "at least 5 control points");
  require_error(BSpline::uniform({}, 1), "got 0");
  require_error(BSpline::closed(kFour, 0), "below the minimum 1");
  require_error(BSpline::closed(kFour, 4), "at least 5 control points");
  require_error(BSpline::closed(bad, 2), "control point 2");
}

TEST_CASE("Knot generators reject impossible counts", "[knots][errors]") {
  require_error(clamped_knots(2, 2), "at least 3");
  require_error(uniform_knots(0, 0), "at least 1");
  require_error(periodic_knots(3, 0), "minimum 1");
  REQUIRE(clamped_knots(3, 2).is_ok());
  REQUIRE(validate_knots(std::vector<double>{0, 0, 0, 1, 1, 1}, 3, 2).is_ok());
}

TEST_CASE("Generated knot vectors are valid and have the documented shape", "[knots]") {
  for (int degree = 0; degree <= 5; ++degree) {
    for (std::size_t count = static_cast<std::size_t>(degree) + 1; count < 12; ++count) {
      auto clamped = clamped_knots(count, degree);
      auto uniform = uniform_knots(count, degree);
      REQUIRE(clamped.is_ok());
      REQUIRE(uniform.is_ok());
      REQUIRE(validate_knots(*clamped, count, degree).is_ok());
      REQUIRE(validate_knots(*uniform, count, degree).is_ok());
      REQUIRE(clamped->at(static_cast<std::size_t>(degree)) == 0.0);
      REQUIRE(clamped->at(count) == 1.0);
      if (degree >= 1) {
        auto periodic = periodic_knots(count, degree);
        REQUIRE(periodic.is_ok());
        REQUIRE(validate_knots(*periodic, count + static_cast<std::size_t>(degree), degree).is_ok());
      }
    }
  }
}

}  // namespace
}  // namespace curvescan
