#include "verify/eos_problems.hpp"
#include "verify/impact_problems.hpp"
#include "verify/problem.hpp"
#include "verify/problems.hpp"
#include "verify/strength_problems.hpp"

namespace kessler::verify {

const std::vector<Check>& problems() {
  static const std::vector<Check> all{
      {"lme-consistency", "LME identities on a distorted point cloud", lmeConsistency},
      {"wave-speed", "longitudinal wave speed in a bar under uniaxial strain", waveSpeed},
      {"plate-wave", "extensional wave in a plate with free faces", plateWave},
      {"momentum", "linear momentum conserved through a collision of two bodies", momentum},
      {"contact-gap", "bodies separated by a gap do not interact until they touch", contactGap},
      {"energy", "energy drift of a freely vibrating elastic bar over 5 periods", energy},
      {"thread-determinism", "1 and 2 threads give bitwise identical fields", threadDeterminism},
      {"eos-mie-gruneisen", "Mie-Gruneisen EOS swept against its formula; c^2 against finite differences",
       eosMieGruneisen},
      {"eos-polynomial", "polynomial EOS swept against its formula; c^2 against finite differences", eosPolynomial},
      {"eos-tillotson", "Tillotson EOS swept against its formula; c^2 against finite differences", eosTillotson},
      {"eos-tabular", "SESAME table of a Mie-Gruneisen EOS against the analytic EOS", eosTabular},
      {"eos-ideal-gas", "ideal-gas EOS swept against its formula, exactly 0 at e = 0; c^2 against finite differences",
       eosIdealGas},
      {"radial-return", "log-strain radial return along uniaxial-strain and pure-shear paths against analytic answers",
       radialReturn},
      {"adiabatic-heating", "temperature rise of plastic work in isochoric shear against the closed form",
       adiabaticHeating},
      {"flyer-plate", "symmetric Al 6061-T6 plate impact at 2 km/s against the Hugoniot", flyerPlate},
      {"spall",
       "symmetric Al 6061-T6 plate impact, flyer delta on target 2 delta: spall plane above the threshold, none below",
       spall},
      {"hugoniot-3d", "symmetric Al 6061-T6 plate impact at 6.18 km/s on unstructured points against the Hugoniot",
       hugoniot3d},
      {"noh-3d", "spherical Noh problem (ideal gas): post-shock density at two resolutions", noh3d},
      {"taylor-bar", "copper Taylor bar: final length and footprint radius", taylorBar},
      {"taylor-bar-coarse", "copper Taylor bar at 1 mm (CI): length and radius, length converging", taylorBarCoarse},
      {"griffith", "centre-cracked plate fails at Griffith's stress (eigenerosion)", griffith},
  };
  return all;
}

}  // namespace kessler::verify
