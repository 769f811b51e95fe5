// `curvescan curve`: the spec of every family, its errors, and the contract of its output, end to end.
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "curvescan/curves/nurbs.h"
#include "curve_cli.h"
#include "run_command.h"

namespace curvescan::test {
namespace {


Point point_of(const nlohmann::json& pair) { return {pair[0].get<double>(), pair[1].get<double>()}; }

}  // namespace

TEST_CASE("curve: every family prints exact pieces and a polyline from the first to the last point", "[cli]") {
  const char* specs[] = {
      R"({"type": "bezier", "points": [[0,0],[10,30],[40,-20],[50,10]]})",
      R"({"type": "rational", "points": [[0,0],[10,10],[20,0]], "weights": [1, 3, 1]})",
      R"({"type": "bspline", "degree": 3, "points": [[0,0],[10,20],[20,-10],[30,20],[40,0],[50,5]]})",
      R"({"type": "bspline", "degree": 2, "points": [[0,0],[10,20],[20,0],[10,-10]], "closed": true})",
      R"({"type": "nurbs", "degree": 2, "points": [[0,0],[10,20],[20,0]], "weights": [1, 0.5, 1]})",
      R"({"type": "hermite", "points": [[0,0],[10,0],[20,5]], "tangents": [[10,10],[10,0],[0,10]]})",
      R"({"type": "catmull-rom", "points": [[0,0],[10,10],[11,10],[20,0]], "alpha": 0.5})",
      R"({"type": "interpolate", "points": [[0,0],[10,10],[20,0],[30,10]], "parameterization": "uniform"})",
  };
  for (const char* spec : specs) {
    INFO(spec);
    const CurveRun run = run_curve_spec(spec);
    REQUIRE(run.output.exit_code == 0);
    const auto& segments = run.json.at("segments");
    const auto& polyline = run.json.at("polyline");
    REQUIRE(!segments.empty());
    REQUIRE(polyline.size() >= 2);
    // The polyline starts and ends where the exact pieces do (bitwise: vertices are copied control points).
    CHECK(point_of(polyline.front()) == point_of(segments.front().at("points").front()));
    CHECK(point_of(polyline.back()) == point_of(segments.back().at("points").back()));
  }
}

TEST_CASE("curve: the NURBS circle spec yields a polyline on the circle within the tolerance", "[cli]") {
  const double tolerance = 0.01;
  const CurveRun run = run_curve_spec(R"({"type": "nurbs", "degree": 2,
    "points": [[100,0],[100,100],[0,100],[-100,100],[-100,0],[-100,-100],[0,-100],[100,-100],[100,0]],
    "weights": [1,0.7071067811865476,1,0.7071067811865476,1,0.7071067811865476,1,0.7071067811865476,1],
    "knots": [0,0,0,0.25,0.25,0.5,0.5,0.75,0.75,1,1,1]})",
                                      "--tolerance 0.01");
  REQUIRE(run.output.exit_code == 0);
  CHECK(run.json.at("segments").size() == 4);
  const auto& polyline = run.json.at("polyline");
  // Vertices lie on the circle up to the 1e-12 exactness of the NURBS circle (relative to r = 100), and
  // each chord's midpoint, the farthest chord point from an arc, is within the tolerance of the circle.
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
    const Point a = point_of(polyline[i]), b = point_of(polyline[i + 1]);
    CHECK(std::abs(a.to_vec().length() - 100.0) < 1e-10);
    CHECK(100.0 - midpoint(a, b).to_vec().length() <= tolerance);
  }
  // A quarter circle of radius 100 within 0.01 needs at least pi/2 / (2 acos(1 - 0.01/100)) = 55.5 chords
  // per quarter (the sagitta bound), so fewer than 4 * 56 vertices would be a violation somewhere.
  CHECK(polyline.size() >= 4 * 56);
}

TEST_CASE("curve: malformed specs get one clear error line and exit code 3", "[cli]") {
  struct Case {
    std::string spec;
    const char* message;
  };
  const Case cases[] = {
      {R"({"type": "bspline", "degree": 2, "points": [[0,0],[1,1],[2,0]], "knots": [0,0,0,1,1]})",
       "knot count"},
      {R"({"type": "bspline", "degree": 2, "points": [[0,0],[1,1],[2,0]], "knots": [0,0,1,0.5,1,1]})",
       "decrease"},
      {R"({"type": "nurbs", "degree": 2, "points": [[0,0],[1,1],[2,0]], "weights": [1,0,1]})", "weights"},
      {R"({"type": "nurbs", "degree": 2, "points": [[0,0],[1,1],[2,0]], "weights": [1,-2,1]})", "weights"},
      {R"({"type": "bspline", "degree": 3, "points": [[0,0],[1,1],[2,0]]})", "degree"},
      {R"({"type": "bezier", "points": [[0,0],[NaN,1]]})", "not valid JSON"},
      {R"({"type": "bezier", "points": [[0,0],["1",1]]})", "points'[1]"},
      {R"({"type": "spiral", "points": [[0,0],[1,1]]})", "unknown curve type"},
      {R"({"type": "bezier", "points": [[0,0],[1,1]], "weigths": [1,1]})", "unknown field 'weigths'"},
      {R"({"points": [[0,0],[1,1]]})", "missing field 'type'"},
      {R"([1, 2, 3])", "JSON object"},
      {R"({"type": "bezier", "points": [[0,0)", "not valid JSON"},
      // Where the text stops being JSON: line and column (1-based) of the offending character.
      {"{\n  \"type\": \"bezier\",\n  \"points\": [1,, 2]\n}",
       "not valid JSON: line 3, column 16: syntax error"},
      {R"({"type": "catmull-rom", "points": [[0,0]]})", "point"},
      // A NUL byte ends the text for the JSON parser: what follows it must not be ignored.
      {std::string(R"({"type": "bezier", "points": [[0,0],[1,1]]})") + '\0' + "junk",
       "is not valid JSON: a NUL byte at offset 43"},
      // A number no double holds: nlohmann's exception tag is not shown.
      {R"({"type": "bezier", "points": [[0,0],[1e400,1]]})",
       "is not valid JSON: number overflow parsing '1e400'"},
  };
  for (const Case& c : cases) {
    INFO(c.spec);
    const CurveRun run = run_curve_spec(c.spec);
    CHECK(run.output.exit_code == 3);
    CHECK(run.output.out.empty());
    CHECK(run.output.err.find(c.message) != std::string::npos);
    // One line, prefixed with the command, so scripts can grep it.
    CHECK(run.output.err.rfind("curvescan curve: error: ", 0) == 0);
    // It names the spec file, whichever part of the spec is wrong.
    CHECK_THAT(run.output.err, Catch::Matches("curvescan curve: error: '[^']*/spec\\.json'[ :].*\n"));
    CHECK_THAT(run.output.err, !Catch::Contains("json.exception"));
    CHECK(std::count(run.output.err.begin(), run.output.err.end(), '\n') == 1);
  }
}

TEST_CASE("curve: bad command lines and option values are usage errors (64), a missing spec an error (3)", "[cli]") {
  const auto dir = scratch_directory("curve-usage");
  CHECK(run_curvescan("curve", dir).exit_code == 64);
  CHECK(run_curvescan("curve spec.json --tolerance -1", dir).exit_code == 64);
  write_text(dir / "spec.json", R"({"type": "bezier", "points": [[0,0],[1,1]]})");
  // NaN passes CLI::Range's comparisons; the finite-number validator makes it a usage error like -1.
  CHECK(run_curvescan("curve " + shell_quote((dir / "spec.json").string()) + " --tolerance nan", dir).exit_code ==
        64);
  CHECK(run_curvescan("curve " + shell_quote((dir / "missing.json").string()), dir).exit_code == 3);
  CHECK(run_curvescan("curve --help", dir).exit_code == 0);
}

TEST_CASE("curve: -o writes the file atomically and a failure leaves an existing file untouched", "[cli]") {
  const auto dir = scratch_directory("curve-output");
  write_text(dir / "good.json", R"({"type": "bezier", "points": [[0,0],[5,9],[10,0]]})");
  write_text(dir / "bad.json", R"({"type": "bezier", "points": [[0,0]]})");
  write_text(dir / "out.json", "previous");
  const auto quoted = [&](const char* name) { return shell_quote((dir / name).string()); };
  CHECK(run_curvescan("curve " + quoted("bad.json") + " -o " + quoted("out.json"), dir).exit_code == 3);
  CHECK(read_text(dir / "out.json") == "previous");
  CHECK(run_curvescan("curve " + quoted("good.json") + " -o " + quoted("out.json"), dir).exit_code == 0);
  CHECK(nlohmann::json::parse(read_text(dir / "out.json")).at("type") == "bezier");
}

}  // namespace curvescan::test
