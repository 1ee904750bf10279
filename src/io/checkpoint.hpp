#pragma once
// Checkpoints: the complete state of a run in one HDF5 file (docs/running.md), so that
// `kessler run --restart DIR` continues bitwise as the run would have gone on without stopping.
// The complete state is the shared particle state (every point field, the bodies, the links),
// the method's own state, which it writes and reads itself (Method::save, Method::load; OTM: its
// nodes, the connectivity with its shape functions, since recomputing those from a warm start
// would change the last bits, and its clock), and the run loop's bookkeeping (output schedule,
// history, the outputs the XDMF series lists). Materials are not stored: they are rebuilt from
// the run's resolved deck and matched by name.
//
// The file is written to a temporary name and renamed over the previous checkpoint, so a run
// killed at any moment (SIGKILL included) leaves the previous complete checkpoint in place.
#include "io/summary.hpp"
#include "io/xdmf.hpp"
#include "solver/common/method.hpp"

#include <filesystem>
#include <functional>
#include <memory>
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

// The method for a restored shared state, not yet loaded (the factory, solver/methods.hpp).
using MethodFactory = std::function<std::unique_ptr<Method>(ParticleState&&)>;

struct Restored {
  std::unique_ptr<Method> method;  // loaded: ready to step
  RunLoopState loop;
};

// DIR/checkpoint.h5.
std::filesystem::path checkpointPath(const std::filesystem::path& run_dir);

// Writes `file` atomically (temporary file, then rename).
void writeCheckpoint(const std::filesystem::path& file, const Method& method, const RunLoopState& loop);

// Restores a run from `file`: the shared state (its materials from `materials`, the deck's, in
// any order, matched by name), then the method `make` builds for it, which loads its own part.
// Throws kessler::Error naming the file and what is wrong if the file is not a complete Kessler
// checkpoint or does not fit the deck.
Restored readCheckpoint(const std::filesystem::path& file, const std::vector<MaterialPtr>& materials,
                        const MethodFactory& make);

}  // namespace kessler::io
