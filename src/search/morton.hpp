#pragma once
// Cache-friendly ordering (docs/performance.md): entries sorted along a Morton (Z-order)
// space-filling curve, so that neighbours in space lie close together in memory. Each body's
// entries stay together (bodyRanges); the sort depends on positions only, so every thread count
// sees the same order.
#include "particles/store.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace kessler {

// Morton key of a position quantised to 21 bits per axis within the box [lo, hi].
std::uint64_t mortonKey(const Vec3& x, const Vec3& lo, const Vec3& hi);

// The permutation (for permute(): order[k] is the entry that goes to place k) that sorts each
// body's entries, grouped by body as bodyRanges requires, by their Morton keys in [lo, hi], ties
// by index.
std::vector<LocalIndex> mortonOrder(std::span<const Vec3> x, std::span<const std::int32_t> body, std::size_t bodies,
                                    const Vec3& lo, const Vec3& hi);

}  // namespace kessler
