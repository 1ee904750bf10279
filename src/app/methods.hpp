#pragma once
// The one place in the program that knows which particle methods exist (the deck's
// solver.method): it builds a run's method from the deck, new or from a checkpoint. Everything
// else drives a method through solver/common/method.hpp.
#include "io/checkpoint.hpp"
#include "io/config.hpp"
#include "solver/common/method.hpp"

#include <filesystem>
#include <memory>

namespace kessler::app {

// Meshes the deck's bodies and builds its method; not yet initialised (Method::initialise).
std::unique_ptr<Method> buildMethod(const io::RunConfig& config);

// The method, ready to step, and the run loop's state from a checkpoint of a run of this deck
// (io::writeCheckpoint).
std::unique_ptr<Method> restoreMethod(const io::RunConfig& config, const std::filesystem::path& file,
                                      io::RunLoopState& loop);

}  // namespace kessler::app
