// Exit codes shared by every curvescan subcommand (documented in README.md, "Exit codes").
#pragma once

#include <string_view>

#include "curvescan/status.h"

namespace curvescan::cli {

inline constexpr int kExitOk = 0;            ///< success (diff: images the same within tolerance)
inline constexpr int kExitDifferent = 1;     ///< diff only: the images differ beyond tolerance
inline constexpr int kExitSizeMismatch = 2;  ///< diff only: the images have different sizes
inline constexpr int kExitError = 3;         ///< bad input, I/O failure or a limit exceeded
inline constexpr int kExitUsage = 64;        ///< the command line itself is wrong (sysexits EX_USAGE)

/// Prints "curvescan <command>: error: <message>" on one line of stderr and returns kExitError.
int report_error(std::string_view command, const Error& error);
int report_error(std::string_view command, std::string_view message);

/// A wrong command line found after parsing (options that need each other): prints "curvescan <command>:
/// usage error: <message>" and the --help hint, as main() does for CLI11's errors, and returns kExitUsage.
int report_usage_error(std::string_view command, std::string_view message);

/// Prints "curvescan <command>: warning: <message>" on stderr.
void report_warning(std::string_view command, std::string_view message);

}  // namespace curvescan::cli
