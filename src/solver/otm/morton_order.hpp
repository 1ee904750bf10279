#pragma once
// Cache-friendly ordering (docs/performance.md): the points of each body, and the nodes of each
// body, sorted along a Morton (Z-order) space-filling curve, so that a point's neighbour nodes,
// and a node's points, lie close together in memory. Each body's entries stay together (bodyRanges).
// The sort depends on positions only, so every thread count sees the same order. The ids are then
// numbered in that order (numberInOrder), once, when the model is built: a store that holds any
// subset of the points or nodes in id order holds them in the order of the whole, which is what
// makes a distributed run's sums agree bitwise with one process's (docs/parallel.md).
#include "solver/otm/model.hpp"

#include <cstdint>

namespace kessler::otm {

// Morton key of a position quantised to 21 bits per axis within the box [lo, hi].
std::uint64_t mortonKey(const Vec3& x, const Vec3& lo, const Vec3& hi);

// Sorts points and nodes body by body, before the first shape-function solve: the connectivity is
// cleared (to be rebuilt) and the LME warm starts are zero.
void sortForLocality(Model& model);
// Points and nodes numbered 0, 1, ... in store order; the adjacency (by point id) follows.
void numberInOrder(Model& model);

}  // namespace kessler::otm
