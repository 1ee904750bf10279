#pragma once
// Exact sums of doubles: every term is added without rounding into a fixed-point accumulator wide
// enough for the whole double range, so the total does not depend on the order of the terms, on
// how they are split among threads, or on how they are split among processes (whose accumulators
// add exactly, limb by limb, in an integer reduction). Only the final conversion rounds, and it is
// a function of the exact sum alone. This is what makes a sum over points the same bitwise for any
// number of threads and of ranks (docs/parallel.md, "Sums that do not depend on the partition").
//
// A finite double is m 2^q with an integer |m| < 2^53 and -1126 <= q <= 971 (frexp scaled by
// 2^53). The accumulator holds sum_i limb_i 2^(32 i - 1126) in signed 64-bit limbs of 32-bit
// digits; a term adds less than 2^33 to any limb, so 2^29 terms fit before the digits need their
// carries propagated, which add() then does. Infinities and NaN are counted apart: the sum is NaN
// when any term is NaN or both infinities occur, else the infinity that occurs.
#include "core/types.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>

namespace kessler {

class ExactSum {
 public:
  static constexpr int limbs = 70;  // 2097 + 53 bits of position, 32 per limb, and room for carries
  // The limbs, then the counts of +infinity, -infinity and NaN terms.
  using State = std::array<std::int64_t, limbs + 3>;

  void add(double value) {
    if (!std::isfinite(value)) {
      ++digits_[std::isnan(value) ? limbs + 2 : value > 0.0 ? limbs : limbs + 1];
      return;
    }
    if (value == 0.0) return;
    int exponent = 0;
    const double fraction = std::frexp(value, &exponent);  // value = fraction 2^exponent, 0.5 <= |fraction| < 1
    const auto m = static_cast<std::int64_t>(std::ldexp(fraction, 53));
    const int position = exponent - 53 + lowest_;  // of m's lowest bit, from the accumulator's
    const int at = position / 32, shift = position % 32;
    const std::uint64_t magnitude = static_cast<std::uint64_t>(m < 0 ? -m : m);
    const std::uint64_t low = (magnitude & mask_) << shift, high = (magnitude >> 32) << shift;
    const std::int64_t sign = m < 0 ? -1 : 1;
    digits_[at] += sign * static_cast<std::int64_t>(low & mask_);
    digits_[at + 1] += sign * static_cast<std::int64_t>((low >> 32) + (high & mask_));
    digits_[at + 2] += sign * static_cast<std::int64_t>(high >> 32);
    if (++pending_ == (1 << 29)) normalise();
  }

  // Adds another accumulator's exact sum (both are normalised first: nothing can overflow).
  void add(const ExactSum& other) {
    normalise();
    ExactSum copy = other;
    copy.normalise();
    for (int i = 0; i < limbs + 3; ++i) digits_[i] += copy.digits_[i];
    pending_ = 1;
    normalise();
  }

  // The digits with their carries propagated (each in [0, 2^32) but the last, which holds the sign)
  // and the counts: what ranks add in an integer reduction (parallel/communicator.hpp) before
  // setState().
  const State& state() {
    normalise();
    return digits_;
  }
  void setState(const State& state) {
    digits_ = state;
    pending_ = 1;
    normalise();
  }

  // The exact sum rounded to a double (within an ulp or two; always the same for the same sum).
  double value() {
    normalise();
    const std::int64_t positive = digits_[limbs], negative = digits_[limbs + 1], nan = digits_[limbs + 2];
    if (nan > 0 || (positive > 0 && negative > 0)) return std::numeric_limits<double>::quiet_NaN();
    if (positive > 0 || negative > 0) return (positive > 0 ? 1.0 : -1.0) * std::numeric_limits<double>::infinity();
    State magnitude = digits_;
    double sign = 1.0;
    if (magnitude[limbs - 1] < 0) {
      sign = -1.0;
      for (int i = 0; i < limbs; ++i) magnitude[i] = -magnitude[i];
      propagate(magnitude);
    }
    int top = limbs - 1;
    while (top >= 0 && magnitude[top] == 0) --top;
    if (top < 0) return 0.0;
    // The three leading digits carry 65 or more bits: more than a double holds. Added from the
    // smallest, so the rounding is a function of those digits alone.
    double sum = 0.0;
    for (int i = std::max(0, top - 2); i <= top; ++i)
      sum += std::ldexp(static_cast<double>(magnitude[i]), 32 * i - lowest_);
    return sign * sum;
  }

 private:
  static constexpr int lowest_ = 1126;  // 2^-1126: the lowest bit of the smallest subnormal's m
  static constexpr std::uint64_t mask_ = 0xffffffffULL;

  static void propagate(State& d) {
    for (int i = 0; i + 1 < limbs; ++i) {
      const std::int64_t carry = d[i] >> 32;  // floor division (C++20: arithmetic shift)
      d[i] -= carry * (std::int64_t{1} << 32);
      d[i + 1] += carry;
    }
  }
  void normalise() {
    if (pending_ == 0) return;
    propagate(digits_);
    pending_ = 0;
  }

  State digits_{};
  long pending_ = 0;  // terms added since the carries were last propagated
};

// sum_{i < n} term(i) of K components (term returns an Eigen vector of size K), each exactly and
// rounded once, over the threads: each adds its share into its own accumulators, and those add
// exactly. The same bits for any thread count and any order.
// The accumulators of exactSums before rounding, for adding across processes.
template <int K, typename F>
std::array<ExactSum, K> exactPartialSums(LocalIndex n, F&& term) {
  std::array<ExactSum, K> total;
#pragma omp parallel
  {
    std::array<ExactSum, K> mine;
#pragma omp for schedule(static) nowait
    for (LocalIndex i = 0; i < n; ++i) {
      const Eigen::Matrix<double, K, 1> t = term(i);
      for (int k = 0; k < K; ++k) mine[k].add(t[k]);
    }
#pragma omp critical(kessler_exact_sum)
    for (int k = 0; k < K; ++k) total[k].add(mine[k]);
  }
  return total;
}

template <int K, typename F>
Eigen::Matrix<double, K, 1> exactSums(LocalIndex n, F&& term) {
  std::array<ExactSum, K> total = exactPartialSums<K>(n, std::forward<F>(term));
  Eigen::Matrix<double, K, 1> sum;
  for (int k = 0; k < K; ++k) sum[k] = total[k].value();
  return sum;
}

template <typename F>
double exactSum(LocalIndex n, F&& term) {
  return exactSums<1>(n, [&](LocalIndex i) { return Eigen::Matrix<double, 1, 1>(term(i)); })[0];
}

}  // namespace kessler
