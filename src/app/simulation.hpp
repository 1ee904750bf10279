#pragma once
// A whole run from a parsed deck (docs/running.md): build the model (or restore it from the
// run folder's checkpoint), integrate to the end time, write fields at the output times,
// checkpoints on their schedule, the summary and the history.
//   - A numerical failure writes the current state as the last output and a summary marked
//     "failed" before the NumericalError propagates; the last checkpoint stays as it was.
//   - SIGINT/SIGTERM write a final checkpoint and a summary marked "interrupted"; the outcome
//     carries the exit code 128 + signal (130, 143).
//   - solver.max_steps writes a checkpoint, then the state reached; the summary says "stopped".
#include "io/config.hpp"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace kessler::app {

// Where a run stands, for a caller that shows its progress (the Python module's bar).
struct ProgressReport {
  long step = 0;
  double time = 0.0;      // s
  double end_time = 0.0;  // s
  double dt = 0.0;        // s, the last step
};

struct RunOptions {
  int threads = 0;  // 0: OpenMP's default
  bool progress = true;
  // Continue from config.output.dir/checkpoint.h5 instead of meshing: `config` must be the run
  // folder's resolved deck (only end time, step limit, checks, output and checkpoint intervals
  // may differ).
  bool restart = false;
  // Called on the root process after a step, at most every `report_interval` seconds of wall
  // time, and once after the last step. Returning false stops the run as a SIGINT does: a
  // checkpoint, a summary marked "interrupted", exit code 130 and `stopped_by_caller`.
  std::function<bool(const ProgressReport&)> on_progress;
  double report_interval = 0.2;  // s
};

struct RunOutcome {
  std::filesystem::path dir;  // the output folder
  int exit_code = 0;          // 0, or 128 + the signal that stopped the run
  bool stopped_by_caller = false;
};

RunOutcome runSimulation(const io::RunConfig& config, const RunOptions& options);

// What a restart may change (`--set` on `kessler run --restart`): when and how long to run, and the
// checks. Everything else is the model of the checkpoint.
const std::vector<std::string>& restartKeys();

// The run folder's resolved deck with the allowed overrides, to continue the run in that folder.
// Throws InputError for a folder that is not a run folder or an override that is not allowed.
io::RunConfig restartConfig(const std::filesystem::path& dir, const std::vector<std::string>& overrides);

}  // namespace kessler::app
