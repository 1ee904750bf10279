#pragma once
// Verification problems for the strength models (docs/strength.md): the point-wise log-strain
// radial return driven along deformation paths whose elastic-plastic answers are known, and the
// heating of the impact material along such a path.
#include "verify/problem.hpp"

namespace kessler::verify {

Outcome radialReturn();
Outcome adiabaticHeating();

}  // namespace kessler::verify
