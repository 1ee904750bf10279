// The point store's helpers for a store that holds any subset of a run's points in any order:
// where each id sits (IdIndex), each body's range (bodyRanges) and its points (forEachPointOf).
#include "core/error.hpp"
#include "particles/store.hpp"
#include "particles/store_fields.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstring>
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

// What moving points between processes sends: every array of the chosen entries, through the one
// field list, arrives bit for bit behind the receiver's entries.
TEST(PackFields, CarriesEveryArrayOfTheChosenEntries) {
  PointStore from;
  from.resize(4);
  long k = 0;
  PointStore::fields(from, [&](const char*, auto& values, const auto&) {
    for (auto& v : values) {
      std::vector<unsigned char> bytes(sizeof(v));
      for (auto& b : bytes) b = static_cast<unsigned char>(++k * 37);
      std::memcpy(static_cast<void*>(&v), bytes.data(), sizeof(v));
    }
  });
  std::vector<std::byte> buffer;
  const std::vector<LocalIndex> which{3, 1};
  packFields(from, which, buffer);
  PointStore to;
  to.resize(2);
  EXPECT_EQ(unpackFields(to, buffer, 0, which.size()), buffer.size());
  EXPECT_EQ(to.size(), 4);
  EXPECT_EQ(to.owned, 2);  // the caller decides what the new entries are
  int arrays = 0;
  // Compare array by array: received entries 2 and 3 are the sender's 3 and 1.
  std::vector<std::vector<unsigned char>> sent, received;
  PointStore::fields(from, [&](const char*, const auto& values, const auto&) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    const std::size_t size = sizeof(values[0]);
    std::vector<unsigned char> chosen;
    for (const LocalIndex i : which) chosen.insert(chosen.end(), bytes + i * size, bytes + (i + 1) * size);
    sent.push_back(chosen);
  });
  PointStore::fields(to, [&](const char*, const auto& values, const auto&) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    const std::size_t size = sizeof(values[0]);
    received.emplace_back(bytes + 2 * size, bytes + 4 * size);
    ++arrays;
  });
  EXPECT_EQ(arrays, PointStore::field_count);
  EXPECT_EQ(received, sent);
  EXPECT_THROW(unpackFields(to, std::span<const std::byte>(buffer).first(buffer.size() - 1), 0, 2), Error);
}

}  // namespace
}  // namespace kessler
