// SVG path data: every command absolute and relative, implicit repeats, compact numbers and flags,
// smooth-curve reflection, and the error rule (render up to the first error).
#include "curvescan/svg/path_data.h"

#include <catch2/catch.hpp>
#include <vector>

using namespace curvescan;
using namespace curvescan::svg;

namespace {

struct Parsed {
  Path path;
  std::optional<PathDataError> error;
};

Parsed parse(std::string_view data) {
  PathBuilder builder;
  Parsed parsed;
  parsed.error = append_path_data(data, builder);
  auto path = builder.build();
  REQUIRE(path.is_ok());  // the parser must never feed the builder something it refuses
  parsed.path = *path;
  return parsed;
}

// The same path, written out with PathBuilder calls.
template <class Build>
Path expected(Build build) {
  PathBuilder builder;
  build(builder);
  return *builder.build();
}

}  // namespace

TEST_CASE("absolute and relative lines, H and V, implicit linetos after a moveto, close") {
  const Parsed parsed = parse("M10 20 30 40 l5 5 H0 v-3 h2 V1 z m1 1 2 2 Z");
  CHECK_FALSE(parsed.error);
  CHECK(parsed.path == expected([](PathBuilder& b) {
          b.move_to({10, 20}).line_to({30, 40}).line_to({35, 45}).line_to({0, 45}).line_to({0, 42});
          b.line_to({2, 42}).line_to({2, 1}).close();
          // After z the current point is the subpath start (10, 20), so m1 1 goes to (11, 21).
          b.move_to({11, 21}).line_to({13, 23}).close();
        }));
}

TEST_CASE("compact numbers: '1.5.5', signs as separators, exponents") {
  const Parsed parsed = parse("M1.5.5L-1-2e1,3E-1.5");
  CHECK_FALSE(parsed.error);
  CHECK(parsed.path == expected([](PathBuilder& b) {
          b.move_to({1.5, 0.5}).line_to({-1, -20}).line_to({0.3, 0.5});
        }));
}

TEST_CASE("cubic and smooth cubic reflect the previous control point only after C or S") {
  const Parsed parsed = parse("M0 0 C1 2 3 4 5 6 S9 10 11 12 s1 1 2 0 L20 0 S21 1 22 0");
  CHECK_FALSE(parsed.error);
  CHECK(parsed.path == expected([](PathBuilder& b) {
          b.move_to({0, 0}).cubic_to({1, 2}, {3, 4}, {5, 6});
          b.cubic_to({7, 8}, {9, 10}, {11, 12});     // reflection of (3, 4) about (5, 6)
          b.cubic_to({13, 14}, {12, 13}, {13, 12});  // reflection of (9, 10) about (11, 12); relative
          b.line_to({20, 0});
          b.cubic_to({20, 0}, {21, 1}, {22, 0});  // after L, the first control point is the current point
        }));
}

TEST_CASE("quadratic and smooth quadratic, relative") {
  const Parsed parsed = parse("m0 0 q1 1 2 0 t2 0 T6 0 c0 0 0 0 1 1 t1 0");
  CHECK_FALSE(parsed.error);
  CHECK(parsed.path == expected([](PathBuilder& b) {
          b.move_to({0, 0}).quad_to({1, 1}, {2, 0});
          b.quad_to({3, -1}, {4, 0});
          b.quad_to({5, 1}, {6, 0});
          b.cubic_to({6, 0}, {6, 0}, {7, 1});
          b.quad_to({7, 1}, {8, 1});  // T after C: control point = current point
        }));
}

TEST_CASE("arcs: flags without separators, relative end points, degrees converted") {
  const Parsed compact = parse("M0 0a1 1 0 00 1 1A2,3,90,1,1,5,5");
  const Parsed spaced = parse("M0 0 a 1 1 0 0 0 1 1 A 2 3 90 1 1 5 5");
  CHECK_FALSE(compact.error);
  CHECK(compact.path == spaced.path);
  CHECK(compact.path == expected([](PathBuilder& b) {
          b.move_to({0, 0}).svg_arc_to(1, 1, 0, false, false, {1, 1});
          b.svg_arc_to(2, 3, std::numbers::pi / 2, true, true, {5, 5});
        }));
  // A flag is exactly one character, so "a1 1 0 10 1 1" reads large_arc=1, sweep=0, then x=1 y=1.
  CHECK(parse("M0 0a1 1 0 10 1 1").path == expected([](PathBuilder& b) {
          b.move_to({0, 0}).svg_arc_to(1, 1, 0, true, false, {1, 1});
        }));
  const Parsed bad_flag = parse("M0 0 L1 1 A1 1 0 2 0 3 3");
  REQUIRE(bad_flag.error);
  CHECK(bad_flag.error->message == "path data: expected an arc flag (0 or 1) at offset 17");
}

TEST_CASE("errors: the path is kept up to the segment before the first error") {
  const Parsed truncated = parse("M1 1 L2 2 L3 3 4");
  REQUIRE(truncated.error);
  CHECK(truncated.error->offset == 16);
  CHECK(truncated.path == expected([](PathBuilder& b) {
          b.move_to({1, 1}).line_to({2, 2}).line_to({3, 3});
        }));

  const Parsed junk = parse("M1 1 L2 2 X 5 5");
  REQUIRE(junk.error);
  CHECK(junk.error->message == "path data: unexpected character 'X' at offset 10");
  CHECK(junk.path == expected([](PathBuilder& b) { b.move_to({1, 1}).line_to({2, 2}); }));

  const Parsed no_move = parse("L1 1");
  REQUIRE(no_move.error);
  CHECK(no_move.path.empty());

  const Parsed after_close = parse("M0 0 L1 0 1 1 Z 5");
  REQUIRE(after_close.error);
  CHECK(after_close.path == expected([](PathBuilder& b) {
          b.move_to({0, 0}).line_to({1, 0}).line_to({1, 1}).close();
        }));

  // A relative coordinate that overflows is an error at its segment, never a non-finite point.
  const Parsed overflow = parse("M1e308 0 l1 1 l1e308 0");
  REQUIRE(overflow.error);
  CHECK(overflow.path == expected([](PathBuilder& b) { b.move_to({1e308, 0}).line_to({1e308 + 1, 1}); }));
}

TEST_CASE("empty and whitespace-only data is valid and draws nothing") {
  CHECK_FALSE(parse("").error);
  CHECK_FALSE(parse(" \n\t").error);
  CHECK(parse(" \n\t").path.empty());
}

TEST_CASE("a zero-length closed subpath 'M x y Z' is kept so that round caps can stroke it as a dot") {
  const Parsed parsed = parse("M5 5 Z m10 0 z M1 1 L2 2 Z");
  CHECK_FALSE(parsed.error);
  CHECK(parsed.path == expected([](PathBuilder& b) {
          b.move_to({5, 5}).line_to({5, 5}).close();
          b.move_to({15, 5}).line_to({15, 5}).close();
          b.move_to({1, 1}).line_to({2, 2}).close();  // a drawn contour gets no extra segment
        }));
}
