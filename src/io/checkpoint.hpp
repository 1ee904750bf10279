#pragma once
// Checkpoints: the complete state of a run in one HDF5 file (docs/running.md), so that
// `kessler run --restart DIR` continues bitwise as the run would have gone on without stopping.
// The complete state is the Model (every node and point field, the bodies, the connectivity
// with its shape functions: recomputing those from a warm start would change the last bits),
// the integrator's own scalars and the run loop's bookkeeping (output schedule, history, the
// outputs the XDMF series lists). Materials are not stored: they are rebuilt from the run's
// resolved deck and matched by name.
//
// The file is written to a temporary name and renamed over the previous checkpoint, so a run
// killed at any moment (SIGKILL included) leaves the previous complete checkpoint in place.
#include "io/summary.hpp"
#include "io/xdmf.hpp"
#include "solver/otm/integrator.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace kessler::io {

// The run loop's own state.
struct RunLoopState {
  double next_output = 0.0;      // simulated time of the next field output
  double next_checkpoint = 0.0;  // simulated time of the next periodic checkpoint
  double wall_seconds = 0.0;     // wall time spent on the run before this checkpoint, all sessions
  long outputs = 0;              // field outputs written
  std::vector<HistoryRow> history;
  std::vector<XdmfGrid> point_grids, node_grids;  // the outputs listed in points.xdmf, nodes.xdmf
};

struct Checkpoint {
  otm::IntegratorState integrator;
  RunLoopState loop;
};

// DIR/checkpoint.h5.
std::filesystem::path checkpointPath(const std::filesystem::path& run_dir);

// Writes `file` atomically (temporary file, then rename).
void writeCheckpoint(const std::filesystem::path& file, const otm::Model& model, const Checkpoint& checkpoint);

// Restores the model from `file`: stores, bodies and connectivity; model.materials come from
// `materials` (the deck's, in any order), matched by name. Throws kessler::Error naming the file
// and what is wrong if the file is not a complete Kessler checkpoint or does not fit the deck.
Checkpoint readCheckpoint(const std::filesystem::path& file, otm::Model& model,
                          const std::vector<MaterialPtr>& materials);

}  // namespace kessler::io
