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

namespace kessler::app {

struct RunOptions {
  int threads = 0;  // 0: OpenMP's default
  bool progress = true;
  // Continue from config.output.dir/checkpoint.h5 instead of meshing: `config` must be the run
  // folder's resolved deck (only end time, step limit, checks, output and checkpoint intervals
  // may differ).
  bool restart = false;
};

struct RunOutcome {
  std::filesystem::path dir;  // the output folder
  int exit_code = 0;          // 0, or 128 + the signal that stopped the run
};

RunOutcome runSimulation(const io::RunConfig& config, const RunOptions& options);

}  // namespace kessler::app
