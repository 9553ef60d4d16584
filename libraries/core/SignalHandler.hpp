#pragma once
// SIGINT and SIGTERM ask a run to stop: the time loop sees stopRequested() after the current step,
// writes the state and ends with a message. A second signal of the same kind ends the process
// at once (the default action), for a run stuck in a step. A run stopped by a signal exits with
// exitStatus(signal), 128 + the signal number (130 for SIGINT, 143 for SIGTERM) as a shell reports
// a process killed by it, so that scripts and batch systems can tell it from a finished run.
namespace mfdyn {

namespace SignalHandler {
void install();
// 0 when no signal arrived, else the signal number.
int stopRequested();
const char* name(int signal);
int exitStatus(int signal);
}  // namespace SignalHandler

}  // namespace mfdyn
