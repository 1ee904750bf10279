#pragma once
// The verification problems, one function each (registered in registry.cpp).
#include "verify/problem.hpp"

namespace kessler::verify {

Outcome lmeConsistency();

}  // namespace kessler::verify
