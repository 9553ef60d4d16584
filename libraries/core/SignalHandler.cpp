#include "core/SignalHandler.hpp"

#include <csignal>

namespace mfdyn {

namespace {
volatile std::sig_atomic_t received = 0;

extern "C" void onStopSignal(int signal) {
    received = signal;
    std::signal(signal, SIG_DFL);
}
}  // namespace

void SignalHandler::install() {
    std::signal(SIGINT, onStopSignal);
    std::signal(SIGTERM, onStopSignal);
}

int SignalHandler::stopRequested() {
    return received;
}

int SignalHandler::exitStatus(int signal) {
    return 128 + signal;
}

const char* SignalHandler::name(int signal) {
    switch (signal) {
        case SIGINT:
            return "SIGINT";
        case SIGTERM:
            return "SIGTERM";
        default:
            return "signal";
    }
}

}  // namespace mfdyn
