#pragma once
// Verification problems for the equations of state (docs/eos.md): each sweeps one model over a
// wide range of density and energy against an independent evaluation of its formula, and checks
// c^2 against finite differences of the model's own p(rho, e).
#include "verify/problem.hpp"

namespace kessler::verify {

Outcome eosMieGruneisen();
Outcome eosPolynomial();
Outcome eosTillotson();
Outcome eosTabular();
Outcome eosIdealGas();

}  // namespace kessler::verify
