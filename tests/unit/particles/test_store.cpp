// The point store's helpers for a store that holds any subset of a run's points in any order:
// where each id sits (IdIndex), each body's range (bodyRanges) and its points (forEachPointOf).
#include "core/error.hpp"
#include "particles/store.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace kessler {
namespace {

TEST(IdIndex, FindsCompactIdsInAnyOrder) {
  const std::vector<Index> ids{4, 0, 3, 1};
  const IdIndex index(ids);
  EXPECT_EQ(index.find(4), 0);
  EXPECT_EQ(index.find(0), 1);
  EXPECT_EQ(index.find(3), 2);
  EXPECT_EQ(index.find(1), 3);
  EXPECT_EQ(index.find(2), -1);
  EXPECT_EQ(index.find(5), -1);
  EXPECT_EQ(index.find(-1), -1);
}

// A few points of a large run (or a damaged file): no table sized by the largest id.
TEST(IdIndex, FindsSparseIdsWithoutATableById) {
  const std::vector<Index> ids{7'000'000'000'000, 12, 99'999'999'999};
  const IdIndex index(ids);
  EXPECT_EQ(index.find(7'000'000'000'000), 0);
  EXPECT_EQ(index.find(12), 1);
  EXPECT_EQ(index.find(99'999'999'999), 2);
  EXPECT_EQ(index.find(13), -1);
}

TEST(IdIndex, RefusesRepeatedOrNegativeIds) {
  EXPECT_THROW(IdIndex(std::vector<Index>{1, 2, 1}), Error);
  EXPECT_THROW(IdIndex(std::vector<Index>{5'000'000'000'000, 3, 5'000'000'000'000}), Error);
  EXPECT_THROW(IdIndex(std::vector<Index>{0, -2}), Error);
}

TEST(BodyRanges, GivesEachBodysRangeAndRefusesABodyInTwoPieces) {
  const std::vector<std::int32_t> body{1, 1, 0, 0, 0};
  const std::vector<IndexRange> ranges = bodyRanges(body, 5, 3);
  ASSERT_EQ(ranges.size(), 3u);
  EXPECT_EQ(ranges[0].begin, 2);
  EXPECT_EQ(ranges[0].end, 5);
  EXPECT_EQ(ranges[1].begin, 0);
  EXPECT_EQ(ranges[1].end, 2);
  EXPECT_EQ(ranges[2].begin, ranges[2].end);  // no entries
  EXPECT_THROW(bodyRanges(std::vector<std::int32_t>{0, 1, 0}, 3, 2), Error);
  EXPECT_THROW(bodyRanges(std::vector<std::int32_t>{0, 2}, 2, 2), Error);
}

TEST(ForEachPointOf, VisitsTheOwnedPointsOfOneBodyInStoreOrder) {
  PointStore points;
  points.resize(5);
  points.body = {0, 1, 0, 1, 0};
  points.owned = 4;  // the last is a ghost
  std::vector<LocalIndex> seen;
  forEachPointOf(points, 0, [&](LocalIndex p) { seen.push_back(p); });
  EXPECT_EQ(seen, (std::vector<LocalIndex>{0, 2}));
}

}  // namespace
}  // namespace kessler
