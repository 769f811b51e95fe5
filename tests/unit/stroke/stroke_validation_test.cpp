// stroke_path() and dash_path() refuse invalid styles with an actionable message, accept the degenerate
// inputs SVG defines (zero width, lone moves), and NaN never reaches them (PathBuilder rejects it).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "curvescan/raster/stroke.h"
#include "curvescan/raster/limits.h"
#include "stroke_render.h"

namespace curvescan {
namespace {

using testing::polyline_path;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST_CASE("invalid stroke styles are refused with kInvalidArgument", "[stroke][errors]") {
  const Path line = polyline_path({{0, 0}, {10, 0}});
  StrokeStyle style;
  style.width = kNaN;
  CHECK(stroke_path(line, style, 0.1).error().kind == ErrorKind::kInvalidArgument);
  style.width = -1.0;
  CHECK(stroke_path(line, style, 0.1).error().message.find("width") != std::string::npos);
  style.width = 1.0;
  style.miter_limit = 0.5;
  CHECK(stroke_path(line, style, 0.1).error().message.find("miter limit") != std::string::npos);
  style.miter_limit = 4.0;
  style.dash_array = {5.0, -1.0};
  const Result<Path> negative = stroke_path(line, style, 0.1);
  REQUIRE_FALSE(negative.is_ok());
  CHECK(negative.error().message.find("entry 1") != std::string::npos);
  style.dash_array = {5.0, kNaN};
  CHECK_FALSE(stroke_path(line, style, 0.1).is_ok());
  style.dash_array = {5.0};
  style.dash_offset = std::numeric_limits<double>::infinity();
  CHECK_FALSE(stroke_path(line, style, 0.1).is_ok());
  style.dash_offset = 0.0;
  CHECK_FALSE(stroke_path(line, style, 0.0).is_ok());
  CHECK_FALSE(stroke_path(line, style, kNaN).is_ok());
  CHECK(stroke_path(line, style, 0.1).is_ok());
}

TEST_CASE("NaN coordinates are rejected when the path is built, before any stroking", "[stroke][errors]") {
  PathBuilder builder;
  builder.move_to({0, 0}).cubic_to({1, 1}, {kNaN, 2}, {3, 3});
  const Result<Path> path = builder.build();
  REQUIRE_FALSE(path.is_ok());
  CHECK(path.error().kind == ErrorKind::kInvalidArgument);
}

TEST_CASE("zero width and empty paths stroke to nothing — a lone moveto draws nothing", "[stroke]") {
  StrokeStyle style;
  style.width = 0.0;
  CHECK(stroke_path(polyline_path({{0, 0}, {10, 0}}), style, 0.1)->empty());
  style.width = 4.0;
  style.cap = LineCap::kRound;
  PathBuilder lone;
  lone.move_to({5, 5});
  CHECK(stroke_path(*lone.build(), style, 0.1)->empty());
  CHECK(stroke_path(Path(), style, 0.1)->empty());
}

TEST_CASE("a dash pattern with a tiny period on a long path hits kMaxDashSegments quickly", "[stroke][limits]") {
  const Path long_line = polyline_path({{0, 0}, {1e7, 0}});
  StrokeStyle style;
  style.dash_array = {0.001, 0.001};
  const Result<Path> stroked = stroke_path(long_line, style, 0.1);
  REQUIRE_FALSE(stroked.is_ok());
  CHECK(stroked.error().kind == ErrorKind::kLimitExceeded);
  CHECK(stroked.error().message.find("more than " + std::to_string(kMaxDashSegments) + " dashes") !=
        std::string::npos);
  const double dashes[] = {0.001};
  CHECK(dash_path(long_line, dashes, 0.0, 0.1).error().kind == ErrorKind::kLimitExceeded);
}

TEST_CASE("a huge width whose outline overflows double is refused, not drawn as NaN", "[stroke][limits]") {
  StrokeStyle style;
  style.width = 1e308;
  style.cap = LineCap::kSquare;
  const Result<Path> stroked = stroke_path(polyline_path({{-1e308, 0}, {1e308, 0}}), style, 0.1);
  REQUIRE_FALSE(stroked.is_ok());
  CHECK(stroked.error().kind == ErrorKind::kLimitExceeded);
}

TEST_CASE("stroke_user_tolerance divides by the largest singular value", "[stroke]") {
  CHECK(stroke_user_tolerance(Affine::identity(), 0.1) == Approx(0.1));
  CHECK(stroke_user_tolerance(Affine::scale(2, 5), 0.1) == Approx(0.02));
  CHECK(stroke_user_tolerance(Affine::rotate(0.7) * Affine::scale(3, 0.5), 0.3) == Approx(0.1));
  // Skew x' = x + y: singular values of [[1 1],[0 1]] are the golden ratio and its inverse.
  CHECK(stroke_user_tolerance(Affine{1, 0, 1, 1, 0, 0}, 1.0) == Approx(2.0 / (1.0 + std::sqrt(5.0))));
  CHECK(std::isinf(stroke_user_tolerance(Affine::scale(0), 0.1)));
}

}  // namespace
}  // namespace curvescan
