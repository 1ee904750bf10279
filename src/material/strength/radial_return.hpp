#pragma once
// Finite-strain J2 plasticity with logarithmic elastic strain and radial return (Simo,
// CMAME 99, 1992; Simo & Hughes "Computational Inelasticity" 1998, §9.2; Eterovic & Bathe 1990).
// The elastic left Cauchy-Green tensor b_e is pushed forward with the step's dF, its
// logarithmic strain eps_e = 1/2 ln b_e^trial is split into volume (handled by the EOS) and
// deviator, the deviatoric Kirchhoff stress tau' = 2 G dev(eps_e) is returned radially onto the
// yield surface, solving  q_trial - 3 G d_eps_p = sigma_y(eps_p + d_eps_p, d_eps_p/dt, T)  by
// Newton's method, and b_e is rebuilt from the returned strain with the same eigenvectors. The
// update is objective: a pure rotation in dF rotates b_e and the stress exactly.
#include "core/types.hpp"
#include "material/strength/yield.hpp"

namespace kessler::strength {

struct ReturnInput {
  Mat3 dF;              // deformation-gradient increment of the step
  double dt = 0.0;      // s (0: no rate effects, e.g. at initialisation)
  double shear_modulus = 0.0;  // G, Pa
  double temperature = 0.0;    // K
  double melt_temperature = 0.0;  // K, from Yield::meltingTemperature(J)
};

struct ReturnResult {
  Mat3 deviatoric_stress;     // Cauchy deviator s = tau' / J, Pa
  double plastic_increment = 0.0;  // d eps_p over the step
  double plastic_work = 0.0;  // per unit current volume over the step, J/m^3 (sigma_y d_eps_p / J)
  double flow_stress = 0.0;   // sigma_y at the end of the step, Pa
};

// Updates `be` (elastic left Cauchy-Green tensor) and `eps_p` (equivalent plastic strain) of
// one point. At or above melting the deviator is zero and b_e relaxes to its volumetric part.
ReturnResult radialReturn(const Yield& yield, const ReturnInput& in, Mat3& be, double& eps_p);

// The same, with the yield law already resolved (call inside loops after one std::visit).
template <typename Law>
ReturnResult radialReturnWith(const Law& law, const ReturnInput& in, Mat3& be, double& eps_p);

}  // namespace kessler::strength

#include "material/strength/radial_return_impl.hpp"
