#pragma once
// A whole run from a parsed deck: build the model, integrate to the end time, write fields at
// the output times, the summary and the history. A numerical failure writes the last state
// and a summary that says what failed before the error propagates.
#include "io/config.hpp"

#include <filesystem>

namespace kessler::app {

struct RunOptions {
  int threads = 0;  // 0: OpenMP's default
  bool progress = true;
};

// Returns the output folder.
std::filesystem::path runSimulation(const io::RunConfig& config, const RunOptions& options);

}  // namespace kessler::app
