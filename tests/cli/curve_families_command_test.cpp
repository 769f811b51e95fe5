// `curvescan curve` for explicit and implicit curves and Bézier patches: the output fields, the notes,
// and errors naming the field and the column.
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "curve_cli.h"
#include "run_command.h"

namespace curvescan::test {

TEST_CASE("curve: an explicit graph is one polyline, or several where it is split", "[cli]") {
  const CurveRun sine = run_curve_spec(
      R"J({"type": "explicit", "f": "sin(x)", "x": [0, 6.283185307179586]})J", "--tolerance 0.01");
  REQUIRE(sine.output.exit_code == 0);
  const auto& polyline = sine.json.at("polyline");
  REQUIRE(polyline.size() > 2);
  for (const auto& p : polyline) {
    // Vertices are (x, sin x) in double: exact up to libm's rounding.
    CHECK(p[1].get<double>() == Approx(std::sin(p[0].get<double>())).margin(1e-15));
  }
  CHECK_FALSE(sine.json.contains("notes"));
  const CurveRun tangent =
      run_curve_spec(R"J({"type": "explicit", "f": "tan(x)", "x": [-3, 3], "y": [-10, 10]})J");
  REQUIRE(tangent.output.exit_code == 0);
  CHECK(tangent.json.at("polylines").size() == 3);
  CHECK(tangent.json.at("notes").size() == 3);  // two splits and the band
  CHECK(tangent.output.err.find("warning: the graph is split for x in [-1.5708") != std::string::npos);
}

TEST_CASE("curve: an implicit curve gives one polyline per component and reports singular points", "[cli]") {
  const CurveRun circles = run_curve_spec(
      R"J({"type": "implicit", "f": "((x-2)^2 + y^2 - 1) * ((x+2)^2 + y^2 - 1)", "box": [[-4, -2], [4.3, 2.1]]})J");
  REQUIRE(circles.output.exit_code == 0);
  REQUIRE(circles.json.at("polylines").size() == 2);
  for (const auto& line : circles.json.at("polylines")) CHECK(line.front() == line.back());  // closed
  const CurveRun lemniscate = run_curve_spec(
      R"J({"type": "implicit", "f": "(x^2 + y^2)^2 - 2*(x^2 - y^2)", "box": [[-2, -1.1], [2.2, 1.3]]})J");
  REQUIRE(lemniscate.output.exit_code == 0);
  CHECK(lemniscate.json.at("polylines").size() == 1);
  REQUIRE(lemniscate.json.contains("notes"));
  CHECK(lemniscate.json.at("notes")[0].get<std::string>().rfind("singular point near (", 0) == 0);
}

TEST_CASE("curve: Bezier patches print their iso-curves as rational cubics under perspective", "[cli]") {
  const std::string patch = R"J([[0,0,0],[1,0,0],[2,0,0],[3,0,0],[0,1,0],[1,1,1],[2,1,1],[3,1,0],
                                 [0,2,0],[1,2,1],[2,2,1],[3,2,0],[0,3,0],[1,3,0],[2,3,0],[3,3,0]])J";
  const CurveRun run =
      run_curve_spec(R"J({"type": "bezier-patch", "patches": [)J" + patch +
                      R"J(], "view": {"eye": [-5, -6, 4], "target": [1.5, 1.5, 0], "focal": 300,
                                        "centre": [100, 100]}, "iso": [3, 4]})J");
  REQUIRE(run.output.exit_code == 0);
  REQUIRE(run.json.at("segments").size() == 7);
  REQUIRE(run.json.at("polylines").size() == 7);
  for (const auto& segment : run.json.at("segments")) {
    CHECK(segment.at("degree") == 3);
    CHECK(segment.contains("weights"));
  }
  // The default view (none given) is orthographic onto (x, y): polynomial cubics.
  const CurveRun flat =
      run_curve_spec(R"J({"type": "bezier-patch", "patches": [)J" + patch + R"J(], "iso": [2, 0]})J");
  REQUIRE(flat.output.exit_code == 0);
  REQUIRE(flat.json.at("segments").size() == 2);
  CHECK_FALSE(flat.json.at("segments")[0].contains("weights"));
  CHECK(flat.json.at("segments")[0].at("points")[3] == nlohmann::json::array({3.0, 0.0}));
}

TEST_CASE("curve: family specs with errors get one clear line", "[cli]") {
  struct Case {
    const char* spec;
    const char* message;
  };
  const Case cases[] = {
      {R"J({"type": "explicit", "f": "sin(x", "x": [0, 1]})J",
       "'f': column 6: expected ')' to close the '('"},
      {R"J({"type": "explicit", "f": "sin(y)", "x": [0, 1]})J", "'f': column 5: unknown name 'y'"},
      {R"J({"type": "explicit", "f": "x", "x": [1, 0]})J", "'x' must be [x0, x1] with x0 < x1"},
      {R"J({"type": "implicit", "f": "x^2 + y^2 - 1", "box": [[1, 1], [0, 0]]})J", "'box' must be"},
      {R"J({"type": "implicit", "f": "x", "box": [[0, 0], [1, 1]], "tolerance": 1})J",
       "unknown field 'tolerance'"},
      {R"J({"type": "bezier-patch", "patches": [[[0,0,0]]]})J", "'patches'[0] must list 16 control points"},
      {R"J({"type": "bezier-patch", "vertices": [[0,0,0]], "patches": [[0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,7]]})J",
       "'patches'[0][15] must be an index into 'vertices'"},
  };
  for (const Case& c : cases) {
    INFO(c.spec);
    const CurveRun run = run_curve_spec(c.spec);
    CHECK(run.output.exit_code == 3);
    CHECK(run.output.err.find(c.message) != std::string::npos);
  }
  // Hostile input: a range wider than the doubles, a formula past the length and depth limits.
  const CurveRun wide = run_curve_spec(R"J({"type": "explicit", "f": "x", "x": [-1e308, 1e308]})J");
  CHECK(wide.output.exit_code == 3);
  CHECK(wide.output.err.find("x1 − x0 finite") != std::string::npos);
  std::string long_formula = "x";
  for (int i = 0; i < 3000; ++i) long_formula += "+x";
  const CurveRun long_run =
      run_curve_spec(R"J({"type": "explicit", "x": [0, 1], "f": ")J" + long_formula + R"J("})J");
  CHECK(long_run.output.exit_code == 3);
  CHECK(long_run.output.err.find("more than the limit of 4096") != std::string::npos);
  const CurveRun deep = run_curve_spec(R"J({"type": "implicit", "box": [[0, 0], [1, 1]], "f": ")J" +
                                         std::string(200, '(') + "x" + std::string(200, ')') + R"J("})J");
  CHECK(deep.output.exit_code == 3);
  CHECK(deep.output.err.find("'f': column 65: the expression nests deeper than 64 levels") !=
        std::string::npos);
  const CurveRun huge =
      run_curve_spec(R"J({"type": "implicit", "f": "sin(50*x)*sin(50*y)", "box": [[-9, -9], [9, 9]]})J",
                      "--tolerance 0.0001 --max-segments 10000");
  CHECK(huge.output.exit_code == 3);
  CHECK(huge.output.err.find("raise --max-segments") != std::string::npos);
}

}  // namespace curvescan::test
