#pragma once
// The one place in the program that knows which particle methods exist (the deck's
// solver.method): it builds a new run's method from the deck, and writes and reads a method's
// checkpoint. Everything else drives a method through solver/common/method.hpp.
#include "io/checkpoint.hpp"
#include "io/config.hpp"
#include "solver/common/method.hpp"

#include <filesystem>
#include <memory>

namespace kessler::app {

// Meshes the deck's bodies and builds its method; not yet initialised (Method::initialise).
std::unique_ptr<Method> buildMethod(const io::RunConfig& config);

// The method and the run loop's state from a checkpoint written by saveMethod() for this deck.
std::unique_ptr<Method> restoreMethod(const io::RunConfig& config, const std::filesystem::path& file,
                                      io::RunLoopState& loop);

// Writes the method's complete state and the run loop's to `file`, atomically.
void saveMethod(const Method& method, const std::filesystem::path& file, const io::RunLoopState& loop);

}  // namespace kessler::app
