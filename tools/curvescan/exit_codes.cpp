#include "exit_codes.h"

#include <iostream>

namespace curvescan::cli {

int report_error(std::string_view command, std::string_view message) {
  std::cerr << "curvescan" << (command.empty() ? "" : " ") << command << ": error: " << message << '\n';
  return kExitError;
}

int report_error(std::string_view command, const Error& error) { return report_error(command, error.message); }

int report_usage_error(std::string_view command, std::string_view message) {
  std::cerr << "curvescan " << command << ": usage error: " << message << "\n(run 'curvescan " << command
            << " --help')\n";
  return kExitUsage;
}

void report_warning(std::string_view command, std::string_view message) {
  std::cerr << "curvescan" << (command.empty() ? "" : " ") << command << ": warning: " << message << '\n';
}

}  // namespace curvescan::cli
