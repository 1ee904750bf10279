#pragma once
// SIGINT and SIGTERM during a run: the handler only records the signal (no I/O, nothing that is
// not async-signal-safe); the run loop polls stopRequested() after each step, writes a final
// checkpoint and exits with 128 + the signal number (130 for SIGINT, 143 for SIGTERM). A second
// signal of either kind while the first is pending ends the process at once, for a user who does
// not want to wait for the checkpoint.
namespace kessler::app {

// Installs the handlers for its lifetime and restores the previous ones afterwards.
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // The signal received (SIGINT or SIGTERM), 0 if none.
  static int received();
};

const char* signalName(int signal);

}  // namespace kessler::app
