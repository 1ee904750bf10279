#pragma once
// Verification problems for the strength models (docs/strength.md): the point-wise log-strain
// radial return driven along deformation paths whose elastic-plastic answers are known.
#include "verify/problem.hpp"

namespace kessler::verify {

Outcome radialReturn();

}  // namespace kessler::verify
