// `curvescan curve` on bad JSON specs: empty, cut at many offsets, wrong types, garbage, absurd numbers,
// deep nesting, degenerate knots and weights, and every limit (degree, points, segments, input size).
// Each: exit 3 and one line naming the problem, no output file after a failure (bad_input_case.h).
#include <random>
#include <string>
#include <vector>

#include "bad_input_case.h"

namespace curvescan::test {
namespace {

const std::string kNurbs =
    R"json({"type": "nurbs", "degree": 2,
 "points": [[1,0],[1,1],[0,1],[-1,1],[-1,0],[-1,-1],[0,-1],[1,-1],[1,0]],
 "weights": [1,0.7071067811865476,1,0.7071067811865476,1,0.7071067811865476,1,0.7071067811865476,1],
 "knots": [0,0,0,0.25,0.25,0.5,0.5,0.75,0.75,1,1,1]}
)json";

std::string seeded_garbage(unsigned seed, std::size_t size) {
  std::mt19937 random(seed);
  std::string bytes(size, '\0');
  for (char& c : bytes) c = static_cast<char>(random() & 0xff);
  return bytes;
}

BadInputCase spec_case(const std::string& name, const std::string& spec, int exit_code, const std::string& message,
                       const std::string& extra_arguments = "") {
  BadInputCase c{name, "curve {in} -o {out}" + extra_arguments, spec, exit_code, message};
  c.output_kind = OutputKind::kJson;
  return c;
}

TEST_CASE("curve: empty, cut, wrong-type and garbage specs are one clear error", "[bad_input][curve]") {
  const std::string kNotJson = "'[^']*input' is not valid JSON";
  std::vector<BadInputCase> cases = {
      spec_case("empty file", "", 3, kNotJson),
      spec_case("seeded binary garbage", seeded_garbage(13, 4096), 3, kNotJson),
      spec_case("a PNG signature", std::string("\x89PNG\r\n\x1a\n", 8) + std::string(16, '\0'), 3, kNotJson),
      spec_case("an SVG document", R"(<svg xmlns="http://www.w3.org/2000/svg"/>)", 3, kNotJson),
      spec_case("a JSON array", "[]", 3, "the spec must be a JSON object"),
      spec_case("a JSON string", "\"bezier\"", 3, "the spec must be a JSON object"),
      spec_case("type is a number", R"({"type": 5})", 3, "'type' must be a string"),
      spec_case("unknown type", R"({"type": "nope", "points": [[0,0],[1,1]]})", 3, "unknown curve type \"nope\""),
      spec_case("10^5 nested arrays", std::string(100'000, '[') + std::string(100'000, ']'), 3,
                "the spec must be a JSON object"),
      spec_case("10^5 nested arrays as points",
                R"({"type": "bezier", "points": )" + std::string(100'000, '[') + std::string(100'000, ']') + "}",
                3, "'points'\\[0\\] must be a pair \\[x, y\\] of finite numbers"),
  };
  // Cut inside a key, after a colon, inside a string, a number, a nested array, between elements, and one
  // byte short: every one leaves the JSON unfinished.
  for (const std::size_t cut : {std::size_t{1}, std::size_t{4}, std::size_t{9}, std::size_t{14}, std::size_t{31},
                                std::size_t{50}, std::size_t{53}, std::size_t{120}, std::size_t{200},
                                kNurbs.size() - 2}) {
    cases.push_back(spec_case("cut after " + std::to_string(cut) + " bytes", kNurbs.substr(0, cut), 3, kNotJson));
  }
  BadInputCase directory = spec_case("a directory", "", 3, "cannot read '[^']*input': it is a directory");
  directory.input_kind = InputKind::kDirectory;
  cases.push_back(directory);
  BadInputCase missing = spec_case("a missing file", "", 3, "cannot open '[^']*input' for reading: No such file");
  missing.input_kind = InputKind::kMissing;
  cases.push_back(missing);
  run_bad_inputs(cases);
}

TEST_CASE("curve: absurd numbers, degenerate data and every limit are one clear error", "[bad_input][curve][limits]") {
  const std::string kNotJson = "'[^']*input' is not valid JSON";
  std::vector<BadInputCase> cases = {
      spec_case("1e400 (beyond double)", R"({"type": "bezier", "points": [[0,0],[1,1e400],[3,1]]})", 3, kNotJson),
      spec_case("NaN (not JSON)", R"({"type": "bezier", "points": [[0,0],[1,NaN],[3,1]]})", 3, kNotJson),
      spec_case("-0 and 1e300: a valid line", R"({"type": "bezier", "points": [[-0,-0],[1e300,1e300]]})", 0, "^$"),
      // Regression (fuzz slow unit): below the coordinates' resolution the flattener walked up to 2^22
      // segments before the command refused the result; now one segment decides, with this message.
      spec_case("a control point at 1e308 (tolerance below the coordinates' resolution)",
                R"({"type": "bezier", "points": [[0,0],[1e308,1],[0,2],[3,3]]})", 3,
                "the tolerance 0.1 is finer than doubles resolve at coordinates up to 1e\\+308 \\(about 7.11e\\+293\\), "
                "so the curve cannot be flattened to it \\(raise --tolerance\\)"),
      spec_case("control points 2e308 apart",
                R"({"type": "bezier", "points": [[0,-1e308],[1,1e308],[3,0]]})", 3,
                "the curve cannot be flattened: its control points are further apart than the largest double"),
      spec_case("a straight line at 1e300, below the coordinates' resolution but flat: valid",
                R"({"type": "bezier", "points": [[0,1e300],[1,1e300],[2,1e300]]})", 0, "^$"),
      spec_case("a negative weight", R"({"type": "nurbs", "degree": 2, "points": [[0,0],[1,1],[2,0]], "weights": [1,-1,1]})",
                3, "'weights'\\[1\\] must be > 0"),
      spec_case("knots all equal",
                R"({"type": "bspline", "degree": 2, "points": [[0,0],[1,1],[2,0]], "knots": [0,0,0,0,0,0]})", 3,
                "multiplicity above degree \\+ 1"),
      spec_case("decreasing knots",
                R"({"type": "bspline", "degree": 2, "points": [[0,0],[1,1],[2,0]], "knots": [1,1,1,0,0,0]})", 3,
                "knots decrease"),
      spec_case("coincident Catmull-Rom points", R"({"type": "catmull-rom", "points": [[0,0],[0,0],[0,0]]})", 3,
                "needs at least 2 distinct points"),
      // --max-memory counts the parsed spec (48 bytes a value): 40 000 points are 120 000 values, 5.5 MiB.
      spec_case("a spec past --max-memory 1", [] {
        std::string points;
        for (int i = 0; i < 40000; ++i) points += (i ? ",[" : "[") + std::to_string(i) + ",0]";
        return R"({"type": "bspline", "degree": 3, "points": [)" + points + "]}";
      }(), 3, "parsing the spec needs [0-9]+ MiB, beyond the memory limit of 1 MiB \\(raise --max-memory\\)",
                " --max-memory 1"),
      // ... then the polyline and its text (72 bytes a point): at tolerance 1e-9 a cubic needs far more
      // than the 14 545 points 1 MiB holds, fewer than --max-segments' default.
      spec_case("a polyline past --max-memory 1", R"({"type": "bezier", "points": [[0,0],[10,30],[40,-20],[50,10]]})",
                3, "the polyline needs more than [0-9]+ segments at this tolerance, more than the memory limit of 1 "
                   "MiB holds with its JSON text \\(raise --max-memory or --tolerance\\)",
                " --max-memory 1 --tolerance 1e-9"),
      spec_case("degree 10^9", R"({"type": "bspline", "degree": 1000000000, "points": [[0,0],[1,1],[3,1]]})", 3,
                "'degree' 1000000000 is above the degree limit of 64 \\(raise --max-degree\\)"),
      spec_case("a Bezier of degree 100", [] {
        std::string points;
        for (int i = 0; i <= 100; ++i) points += (i ? ",[" : "[") + std::to_string(i) + ",0]";
        return R"({"type": "bezier", "points": [)" + points + "]}";
      }(), 3, "'points' has 101 points, above the limit of 65 \\(raise --max-points, or --max-degree"),
      spec_case("points past --max-points", kNurbs, 3,
                "'points' has 9 points, above the limit of 4 \\(raise --max-points", " --max-points 4"),
      spec_case("segments past --max-segments", kNurbs, 3,
                "more than 3 segments at this tolerance, the segment limit \\(raise --max-segments or --tolerance\\)",
                " --max-segments 3"),
      spec_case("input past --max-input-size", kNurbs + std::string(std::size_t{3} << 19, ' '), 3,
                "larger than the input size limit of 1 MiB \\(raise --max-input-size\\)", " --max-input-size 1"),
      spec_case("--tolerance NaN", kNurbs, 64, "--tolerance: the value 'nan' is not a finite number",
                " --tolerance nan"),
      {"output in a missing directory", "curve {in} -o {dir}/missing/out.json", kNurbs, 3, "cannot create"},
      {"output path is a directory", "curve {in} -o {dir}", kNurbs, 3, "cannot write '[^']*'"},
  };
  // Inputs without a size stop at the bound: a FIFO offering 3 MiB, and /dev/zero on standard input.
  BadInputCase fifo = spec_case("a FIFO offering 3 MiB past --max-input-size 1", "", 3,
                                "input '[^']*input' is larger than the input size limit of 1 MiB \\(raise --max-input-size\\)",
                                " --max-input-size 1");
  fifo.input_kind = InputKind::kFifo;
  fifo.fifo_bytes = std::size_t{3} << 20;
  cases.push_back(fifo);
  if (std::filesystem::exists("/dev/zero")) {
    BadInputCase zero{"/dev/zero on standard input past --max-input-size 1", "curve - -o {out} --max-input-size 1 < /dev/zero",
                      "", 3, "input '<stdin>' is larger than the input size limit of 1 MiB \\(raise --max-input-size\\)"};
    zero.output_kind = OutputKind::kJson;
    cases.push_back(zero);
  }
  run_bad_inputs(cases);
}

}  // namespace
}  // namespace curvescan::test
