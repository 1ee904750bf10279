#include "verify/problem.hpp"
#include "verify/problems.hpp"

namespace kessler::verify {

const std::vector<Problem>& problems() {
  static const std::vector<Problem> all{
      {"lme-consistency", "LME identities on a distorted point cloud", lmeConsistency},
  };
  return all;
}

}  // namespace kessler::verify
