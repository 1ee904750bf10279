#pragma once
// Wall-clock timing of named phases; used for the per-phase breakdown in summary.json.
#include <chrono>
#include <map>
#include <string>

namespace kessler {

class Stopwatch {
 public:
  Stopwatch() : start_(Clock::now()) {}
  void restart() { start_ = Clock::now(); }
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
};

// Accumulates time per phase name. Not thread-safe: time phases from the serial driver.
class PhaseTimers {
 public:
  void add(const std::string& phase, double seconds) { totals_[phase] += seconds; }
  const std::map<std::string, double>& totals() const { return totals_; }

 private:
  std::map<std::string, double> totals_;
};

// Adds the lifetime of the scope to one phase.
class ScopedPhase {
 public:
  ScopedPhase(PhaseTimers& timers, const char* phase) : timers_(timers), phase_(phase) {}
  ~ScopedPhase() { timers_.add(phase_, watch_.seconds()); }
  ScopedPhase(const ScopedPhase&) = delete;
  ScopedPhase& operator=(const ScopedPhase&) = delete;

 private:
  PhaseTimers& timers_;
  const char* phase_;
  Stopwatch watch_;
};

}  // namespace kessler
