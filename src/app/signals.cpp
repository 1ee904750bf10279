#include "app/signals.hpp"

#include <atomic>
#include <csignal>

namespace kessler::app {
namespace {

// Lock-free, hence safe to write from a signal handler.
std::atomic<int> pending{0};
static_assert(std::atomic<int>::is_always_lock_free);

struct sigaction previous_int {
}, previous_term{};

extern "C" void onStopSignal(int signal) {
  int expected = 0;
  if (!pending.compare_exchange_strong(expected, signal)) {
    // Second signal: give up on the clean stop. signal() and raise() are async-signal-safe.
    std::signal(signal, SIG_DFL);
    std::raise(signal);
  }
}

}  // namespace

StopSignals::StopSignals() {
  pending.store(0);
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  // SA_RESTART: a signal during a file write must not make the write fail with EINTR.
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
}

StopSignals::~StopSignals() {
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
}

int StopSignals::received() {
  return pending.load();
}

const char* signalName(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "a signal";
  }
}

}  // namespace kessler::app
