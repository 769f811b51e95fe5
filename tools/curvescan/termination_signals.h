// How curvescan ends when it is told to stop: SIGINT, SIGTERM and SIGHUP remove the temporary file of an
// output being written and exit with 128 + the signal's number, as a shell reports a killed command.
// SIGPIPE is ignored, so writing into a closed pipe (`curvescan render in.svg -o - | head -c1`) fails
// with EPIPE and ends as a clear error (exit 3) instead of a silent kill.
#pragma once

namespace curvescan::cli {

/// Installs the handlers; called once at the start of main().
void install_termination_handlers();

}  // namespace curvescan::cli
