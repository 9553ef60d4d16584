#pragma once
// SIGINT and SIGTERM ask a run to stop: the time loop sees stopRequested() after the current step,
// writes the state and ends with a message. A second signal of the same kind ends the process
// at once (the default action), for a run stuck in a step.
namespace mfdyn {

namespace SignalHandler {
void install();
// 0 when no signal arrived, else the signal number.
int stopRequested();
const char* name(int signal);
}  // namespace SignalHandler

}  // namespace mfdyn
