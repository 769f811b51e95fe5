#include "termination_signals.h"

#include <signal.h>
#include <unistd.h>

#include "curvescan/raster/file_io.h"

namespace curvescan::cli {
namespace {

// Only async-signal-safe calls: unlink(2) inside remove_temporary_output_files, then _exit(2).
void on_termination_signal(int signal_number) {
  remove_temporary_output_files();
  ::_exit(128 + signal_number);
}

}  // namespace

void install_termination_handlers() {
  struct sigaction action {};
  action.sa_handler = on_termination_signal;
  sigfillset(&action.sa_mask);  // no second signal runs the handler again half way
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(signal_number, &action, nullptr);
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  ::sigaction(SIGPIPE, &ignore, nullptr);
}

}  // namespace curvescan::cli
