// `curvescan curve` run on a JSON spec written to a scratch file: its output, and its standard output
// parsed as JSON when it succeeded. Shared by the curve command tests.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "run_command.h"

namespace curvescan::test {

struct CurveRun {
  CommandOutput output;
  nlohmann::json json;
};

inline CurveRun run_curve_spec(const std::string& spec, const std::string& flags = "") {
  const auto dir = scratch_directory("curve");
  write_text(dir / "spec.json", spec);
  CurveRun run;
  run.output = run_curvescan("curve " + shell_quote((dir / "spec.json").string()) + " " + flags, dir);
  if (run.output.exit_code == 0) run.json = nlohmann::json::parse(run.output.out);
  return run;
}

}  // namespace curvescan::test
