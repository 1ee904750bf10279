#include "verify/problem.hpp"

#include <cmath>

namespace kessler::verify {

Outcome compare(Outcome o) {
  const double diff = std::abs(o.measured - o.reference);
  o.error = o.comparison == Comparison::relative ? diff / std::abs(o.reference) : diff;
  o.passed = std::isfinite(o.measured) && o.error <= o.tolerance;
  return o;
}

}  // namespace kessler::verify
