#pragma once
// The one place that knows which particle methods exist (the deck's solver.method). Everything
// else drives a method through solver/common/method.hpp.
#include "parallel/communicator.hpp"
#include "solver/common/method.hpp"
#include "solver/common/problem.hpp"

#include <memory>
#include <string>
#include <vector>

namespace kessler {

// The methods this Kessler has, by the name the deck's solver.method gives them.
const std::vector<std::string>& methodNames();

// The problem's method over its bodies, not yet initialised (Method::initialise). Throws for an
// unknown method. With `ranks` of several processes, each runs its part (every rank calls this
// alike; docs/parallel.md).
std::unique_ptr<Method> makeMethod(const Problem& problem, const parallel::Communicator* ranks = nullptr);

// The problem's method for a shared state restored from a checkpoint (its bodies are not meshed
// again); Method::load gives it the rest.
std::unique_ptr<Method> makeMethod(const Problem& problem, ParticleState&& restored,
                                   const parallel::Communicator* ranks = nullptr);

}  // namespace kessler
