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

// The method, ready to step, and the run loop's state from a checkpoint of a run of this deck
// (io::writeCheckpoint).
std::unique_ptr<Method> restoreMethod(const io::RunConfig& config, const std::filesystem::path& file,
                                      io::RunLoopState& loop);

}  // namespace kessler::app
