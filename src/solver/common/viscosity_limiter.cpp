#include "solver/common/viscosity_limiter.hpp"

#include <algorithm>

namespace kessler {

double christensenLimiter(double mean_ratio, double min_ratio) {
  return std::clamp(std::min(mean_ratio, 2.0 * min_ratio), 0.0, 1.0);
}

}  // namespace kessler
