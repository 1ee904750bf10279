// Exact sums (core/exact_sum.hpp): the total is the exact sum rounded once, whatever the order of
// the terms and however they are split, and it survives cancellation and overflow that a running
// double sum does not.
#include "../../wide_terms.hpp"
#include "core/exact_sum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace kessler {
namespace {

double sumOf(const std::vector<double>& terms) {
  ExactSum sum;
  for (double t : terms) sum.add(t);
  return sum.value();
}

TEST(ExactSum, KeepsWhatARunningSumLosesToCancellation) {
  // A running double sum gives 0 (1 is lost against 1e16) and then overflows for the second case.
  EXPECT_EQ(sumOf({1e16, 1.0, -1e16}), 1.0);
  EXPECT_EQ(sumOf({DBL_MAX, DBL_MAX, -DBL_MAX}), DBL_MAX);
  EXPECT_EQ(sumOf({DBL_MAX, -DBL_MAX, DBL_MIN}), DBL_MIN);
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(sumOf({tiny, tiny, tiny}), 3 * tiny);
  EXPECT_EQ(sumOf({1.0, tiny, -1.0}), tiny);
  EXPECT_EQ(sumOf({-2.5, 0.5}), -2.0);
  EXPECT_EQ(sumOf({}), 0.0);
}

// Terms k 2^-20 with integer k: their exact sum is an integer sum, known without rounding.
TEST(ExactSum, EqualsTheExactSumRoundedOnceInAnyOrder) {
  std::mt19937_64 random(7);
  std::uniform_int_distribution<std::int64_t> k(-(std::int64_t{1} << 40), std::int64_t{1} << 40);
  std::vector<double> terms;
  std::int64_t exact = 0;
  for (int i = 0; i < 5000; ++i) {
    const std::int64_t n = k(random);
    exact += n;
    terms.push_back(std::ldexp(static_cast<double>(n), -20));
  }
  const double expected = std::ldexp(static_cast<double>(exact), -20);
  EXPECT_EQ(sumOf(terms), expected);
  for (int shuffle = 0; shuffle < 5; ++shuffle) {
    std::shuffle(terms.begin(), terms.end(), random);
    EXPECT_EQ(sumOf(terms), expected);
  }
}

// Terms over 600 orders of magnitude, both signs: the result's bits do not depend on the order, on
// splitting the terms into accumulators that are then added, or on the thread count.
TEST(ExactSum, TheSameBitsForAnyOrderAndAnySplit) {
  std::vector<double> terms = testing::wideRangeTerms(20000, 11);
  std::mt19937_64 random(11);  // for the shuffles
  const double reference = sumOf(terms);
  ASSERT_TRUE(std::isfinite(reference));
  for (int shuffle = 0; shuffle < 3; ++shuffle) {
    std::shuffle(terms.begin(), terms.end(), random);
    EXPECT_EQ(sumOf(terms), reference);
    ExactSum first, second;
    for (std::size_t i = 0; i < terms.size(); ++i) (i % 3 == 0 ? first : second).add(terms[i]);
    first.add(second);
    EXPECT_EQ(first.value(), reference);
    EXPECT_EQ(exactSum(static_cast<LocalIndex>(terms.size()), [&](LocalIndex i) { return terms[i]; }), reference);
  }
  // The same terms added in the state an integer reduction would carry (digits and counts summed
  // element-wise) give the same bits.
  ExactSum a, b;
  for (std::size_t i = 0; i < terms.size(); ++i) (i < 7000 ? a : b).add(terms[i]);
  ExactSum::State state = a.state();
  const ExactSum::State& other = b.state();
  for (std::size_t i = 0; i < state.size(); ++i) state[i] += other[i];
  ExactSum merged;
  merged.setState(state);
  EXPECT_EQ(merged.value(), reference);
}

TEST(ExactSum, InfinitiesAndNanAsIEEEWouldGiveInAnyOrder) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(sumOf({1.0, inf, 2.0}), inf);
  EXPECT_EQ(sumOf({-inf, 1.0}), -inf);
  EXPECT_TRUE(std::isnan(sumOf({inf, 1.0, -inf})));
  EXPECT_TRUE(std::isnan(sumOf({1.0, std::nan(""), 2.0})));
}

TEST(ExactSum, SumsVectorsComponentByComponent) {
  // The third component: a running sum overflows to infinity after the first 500 terms.
  const Eigen::Vector3d sum = exactSums<3>(
      1000, [](LocalIndex i) { return Eigen::Vector3d(1e20, static_cast<double>(i), i < 500 ? 1e308 : -1e308); });
  EXPECT_EQ(sum[0], 1e23);
  EXPECT_EQ(sum[1], 999.0 * 1000.0 / 2.0);
  EXPECT_EQ(sum[2], 0.0);
}

}  // namespace
}  // namespace kessler
