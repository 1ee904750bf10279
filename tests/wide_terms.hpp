#pragma once
// Test terms for exact sums (core/exact_sum.hpp): n doubles of both signs over 600 orders of
// magnitude, m 2^e with m uniform in (-1, 1) and e in [-300, 300], the same for a given seed.
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace kessler::testing {

inline std::vector<double> wideRangeTerms(std::size_t n, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-300, 300);
  std::vector<double> terms(n);
  for (double& t : terms) t = std::ldexp(mantissa(random), exponent(random));
  return terms;
}

}  // namespace kessler::testing
