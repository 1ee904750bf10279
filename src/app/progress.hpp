#pragma once
// The progress line of a run: step, simulated time, dt, material-point steps per second and
// the estimated time left. On a terminal it redraws one line a few times a second; otherwise
// (a log file, CI) it prints a compact line every `interval` seconds.
#include "core/timer.hpp"

namespace kessler::app {

class Progress {
 public:
  Progress(double end_time, long points, bool enabled);
  // Called after every step; prints only when it is time to.
  void update(long step, double time, double dt);
  // Prints the final line (and ends the redrawn line on a terminal).
  void finish(long step, double time, double dt);

 private:
  void print(long step, double time, double dt, bool final);

  double end_time_;
  long points_;
  bool enabled_;
  bool terminal_;
  double interval_;
  Stopwatch watch_;
  double last_print_ = -1e300;
  long start_step_ = 0;
};

}  // namespace kessler::app
