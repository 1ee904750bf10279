#include "verify/problem.hpp"
#include "verify/problems.hpp"

namespace kessler::verify {

const std::vector<Problem>& problems() {
  static const std::vector<Problem> all{
      {"lme-consistency", "LME identities on a distorted point cloud", lmeConsistency},
      {"wave-speed", "longitudinal wave speed in a bar under uniaxial strain", waveSpeed},
      {"momentum", "linear momentum conserved through a collision of two bodies", momentum},
      {"energy", "energy drift of a freely vibrating elastic bar over 5 periods", energy},
      {"thread-determinism", "1 and 2 threads give bitwise identical fields", threadDeterminism},
  };
  return all;
}

}  // namespace kessler::verify
