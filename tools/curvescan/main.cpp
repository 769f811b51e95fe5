// curvescan: one program, one subcommand per use (curve, render, text, diff, ...).
//
// Every failure ends as one line on stderr and a documented exit code (exit_codes.h); nothing escapes
// as an uncaught exception or a crash.
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstring>
#include <exception>
#include <iostream>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "commands.h"
#include "exit_codes.h"
#include "help_formatter.h"
#include "termination_signals.h"

namespace {

/// The subcommand's name when `word` (the first argument) is one of the program's subcommands, else "".
std::string named_subcommand(const CLI::App& app, const std::string& word) {
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->check_name(word)) return sub->get_name();
  return {};
}

/// The name of the subcommand the command line chose ("" before one is parsed).
std::string chosen_subcommand(CLI::App& app) {
  const std::vector<CLI::App*> chosen = app.get_subcommands();
  return chosen.empty() ? std::string{} : chosen.front()->get_name();
}

/// ": REASON" for "cannot write to standard output: REASON", or "" when the reason is lost. `flush_errno` is
/// errno right after the last flush; a stream that failed earlier may leave it 0 or stale, so a pipe or
/// socket whose reader is gone is recognised by itself (poll reports POLLERR on its write end, pipe(7)).
std::string standard_output_failure(int flush_errno) {
  struct stat status {};
  if (::fstat(STDOUT_FILENO, &status) == 0 && (S_ISFIFO(status.st_mode) || S_ISSOCK(status.st_mode))) {
    pollfd poll_output{STDOUT_FILENO, POLLOUT, 0};
    if (::poll(&poll_output, 1, 0) == 1 && (poll_output.revents & POLLERR) != 0)
      return std::string(": ") + std::strerror(EPIPE);
  }
  return flush_errno != 0 ? std::string(": ") + std::strerror(flush_errno) : std::string{};
}

}  // namespace

int main(int argc, char** argv) {
  using namespace curvescan::cli;
  install_termination_handlers();
  CLI::App app{"curvescan: an exact-area vector-graphics rasterizer and curve toolkit", "curvescan"};
  app.set_version_flag("--version", kVersionText);
  // Before the subcommands are added: each takes its parent's formatter when it is made.
  app.formatter(std::make_shared<PlainHelpFormatter>());
  app.require_subcommand(1);
  app.footer("Run 'curvescan COMMAND --help' for a command's options and examples.");
  CommandResult result;
  add_curve_command(app, result);
  add_diff_command(app, result);
  add_render_command(app, result);
  add_text_command(app, result);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // CLI11's own errors (an unknown option, a missing value) read like ours: they name the subcommand the
    // user typed, so the hint points at that subcommand's help.
    const std::string command = argc > 1 ? named_subcommand(app, argv[1]) : std::string{};
    if (!command.empty()) return report_usage_error(command, e.what());
    if (argc > 1 && argv[1][0] != '-') {  // a word where the command should be, but not one of them
      std::cerr << "curvescan: usage error: '" << argv[1]
                << "' is not a curvescan command; the commands are curve, diff, render and text\n"
                   "(run 'curvescan --help')\n";
      return kExitUsage;
    }
    std::cerr << "curvescan: usage error: " << e.what() << "\n(run 'curvescan --help')\n";
    return kExitUsage;
  } catch (const std::bad_alloc&) {
    return report_error("", "out of memory");
  } catch (const std::exception& e) {
    return report_error("", e.what());
  }
  // A report printed on standard output into a closed pipe or a full disk must not end as success.
  errno = 0;
  std::cout.flush();
  const int flush_errno = errno;
  if (!std::cout && result.exit_code != kExitError)
    return report_error(chosen_subcommand(app),
                        "cannot write to standard output" + standard_output_failure(flush_errno));
  return result.exit_code;
}
