#include "app/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace kessler::app {

Progress::Progress(double end_time, long points, bool enabled)
    : end_time_(end_time),
      points_(points),
      enabled_(enabled),
      terminal_(isatty(fileno(stdout)) != 0),
      interval_(terminal_ ? 0.25 : 10.0) {}

void Progress::update(long step, double time, double dt) {
  if (!enabled_) return;
  const double now = watch_.seconds();
  if (now - last_print_ < interval_) return;
  last_print_ = now;
  print(step, time, dt, false);
}

void Progress::finish(long step, double time, double dt) {
  if (!enabled_) return;
  print(step, time, dt, true);
}

void Progress::print(long step, double time, double dt, bool final) {
  const double elapsed = watch_.seconds();
  const double rate =
      elapsed > 0.0 ? static_cast<double>(step - start_step_) * static_cast<double>(points_) / elapsed : 0.0;
  const double fraction = end_time_ > 0.0 ? time / end_time_ : 0.0;
  const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  const std::string line =
      fmt::format("step {:>7}  t {:>10.4g} s ({:5.1f}%)  dt {:9.3g} s  {:9.3g} point-steps/s  {} {:.0f} s", step, time,
                  100.0 * fraction, dt, rate, final ? "wall" : "ETA", final ? elapsed : eta);
  if (terminal_) {
    fmt::print("\r{}{}", line, final ? "\n" : "");
  } else {
    fmt::print("{}\n", line);
  }
  std::fflush(stdout);
}

}  // namespace kessler::app
