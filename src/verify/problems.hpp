#pragma once
// The verification problems, one function each (registered in registry.cpp).
#include "verify/problem.hpp"

#include <fmt/format.h>

namespace kessler::verify {

Outcome lmeConsistency();
Outcome waveSpeed();
Outcome plateWave();
Outcome momentum();
Outcome contactGap();
Outcome energy();
Outcome threadDeterminism();

}  // namespace kessler::verify
