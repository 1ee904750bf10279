#pragma once
// Ideal-gas (gamma-law) equation of state, p = (gamma - 1) rho e, for the gas of the Noh
// implosion (Noh 1987, J. Comput. Phys. 72:78) and other strengthless test problems
// (docs/eos.md). There is no cold curve and no reference modulus: at e = 0 the pressure and the
// sound speed are exactly 0, and c^2 is not floored.
#include "material/eos/state.hpp"

namespace kessler::eos {

struct IdealGasParameters {
  double density = 0.0;  // rho0, kg/m^3: only the body's mass and the reference state
  double gamma = 0.0;    // ratio of specific heats c_p / c_v
  void check() const;    // throws kessler::InputError naming the bad parameter
};

class IdealGas {
 public:
  IdealGas() = default;  // unchecked zero parameters, so configurations can be default-built
  explicit IdealGas(const IdealGasParameters& p);
  State evaluate(double rho, double e) const;
  double referenceDensity() const { return p_.density; }
  const IdealGasParameters& parameters() const { return p_; }

 private:
  IdealGasParameters p_;
};

}  // namespace kessler::eos
