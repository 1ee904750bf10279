#pragma once
// The end-of-run record: DIR/summary.json (problem size, steps, wall time, energies, momentum,
// per-phase timings, status) and DIR/history.csv (energies and momentum over time).
#include "core/types.hpp"
#include "solver/common/energies.hpp"
#include "solver/common/method.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace kessler::io {

struct HistoryRow {
  long step = 0;
  double time = 0.0;
  double dt = 0.0;
  Energies energies;
};

struct RunRecord {
  std::string title;
  std::string deck;
  std::string status = "completed";  // completed | failed
  std::string message;               // the failure, if any
  int threads = 1;                   // per rank
  int ranks = 1;                     // processes (mpirun)
  double wall_seconds = 0.0;
  long outputs = 0;
  std::map<std::string, double> extra_timings;  // phases outside the integrator (meshing, output)
  std::vector<HistoryRow> history;
  nlohmann::json analysis;  // the impact measurements (docs/analysis.md); null: none
};

// Writes summary.json for the run of `method` (atomically).
void writeSummary(const std::filesystem::path& file, const RunRecord& record, const Method& method);

// Writes the history as CSV (atomically).
void writeHistory(const std::filesystem::path& file, const std::vector<HistoryRow>& history);

}  // namespace kessler::io
