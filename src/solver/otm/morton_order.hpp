#pragma once
// Cache-friendly ordering (docs/performance.md): the points of each body, and the nodes of each
// body, sorted along a Morton (Z-order) space-filling curve, so that a point's neighbour nodes,
// and a node's points, lie close together in memory. Each body's entries stay together (bodyRanges); the
// mesh adjacency, by point id, needs no renumbering. The sort depends on positions only, so every
// thread count sees the same order.
#include "solver/otm/model.hpp"

#include <cstdint>

namespace kessler::otm {

// Morton key of a position quantised to 21 bits per axis within the box [lo, hi].
std::uint64_t mortonKey(const Vec3& x, const Vec3& lo, const Vec3& hi);

// Sorts points and nodes body by body, before the first shape-function solve: the connectivity is
// cleared (to be rebuilt) and the LME warm starts are zero.
void sortForLocality(Model& model);

}  // namespace kessler::otm
