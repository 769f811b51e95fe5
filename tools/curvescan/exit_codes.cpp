#include "exit_codes.h"

#include <iostream>

namespace curvescan::cli {

std::string printable(std::string_view message) {
  std::string out;
  out.reserve(message.size());
  for (const char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    if ((byte < 0x20 && c != '\t') || byte == 0x7f) {
      constexpr const char* kHex = "0123456789ABCDEF";
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 0xf];
    } else {
      out += c;
    }
  }
  return out;
}

int report_error(std::string_view command, std::string_view message) {
  std::cerr << "curvescan" << (command.empty() ? "" : " ") << command << ": error: " << printable(message)
            << '\n';
  return kExitError;
}

int report_error(std::string_view command, const Error& error) { return report_error(command, error.message); }

int report_usage_error(std::string_view command, std::string_view message) {
  std::cerr << "curvescan " << command << ": usage error: " << printable(message) << "\n(run 'curvescan "
            << command << " --help')\n";
  return kExitUsage;
}

void report_warning(std::string_view command, std::string_view message) {
  std::cerr << "curvescan" << (command.empty() ? "" : " ") << command << ": warning: " << printable(message)
            << '\n';
}

}  // namespace curvescan::cli
