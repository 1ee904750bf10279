#pragma once
// A run's method from its deck, new or from a checkpoint: the deck becomes a Problem
// (solver/common/problem.hpp) and the solver's factory (solver/methods.hpp) builds the method.
#include "io/checkpoint.hpp"
#include "io/config.hpp"
#include "parallel/communicator.hpp"
#include "solver/common/method.hpp"
#include "solver/common/problem.hpp"

#include <filesystem>
#include <memory>

namespace kessler::app {

// The deck as a problem: its bodies (with their materials from deckMaterials()), symmetry planes and
// settings.
Problem deckProblem(const io::RunConfig& config);

// Meshes the deck's bodies and builds its method; not yet initialised (Method::initialise).
// With `ranks` of several processes (mpirun), each builds the whole model and keeps its part.
std::unique_ptr<Method> buildMethod(const io::RunConfig& config, const parallel::Communicator* ranks = nullptr);

// A run restored from a checkpoint: the method, ready to step, the run loop's state, and the
// material points of the whole run.
struct RestoredRun {
  std::unique_ptr<Method> method;
  io::RunLoopState loop;
  long points = 0;
};

// From a checkpoint of a run of this deck (io::writeCheckpoint), written by one process or by any
// number of ranks. With `ranks` of several processes, each reads the whole checkpoint and keeps its
// part.
RestoredRun restoreMethod(const io::RunConfig& config, const std::filesystem::path& file,
                          const parallel::Communicator* ranks = nullptr);

}  // namespace kessler::app
