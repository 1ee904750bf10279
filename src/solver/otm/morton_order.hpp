#pragma once
// Cache-friendly ordering (docs/performance.md): the points of each body, and the nodes of each
// body, sorted along a Morton (Z-order) space-filling curve (search/morton.hpp), so that a point's
// neighbour nodes, and a node's points, lie close together in memory. The ids are then numbered in
// that order (numberInOrder), once, when the model is built: a store that holds any subset of the
// points or nodes in id order holds them in the order of the whole, which is what makes a
// distributed run's sums agree bitwise with one process's (docs/parallel.md).
#include "search/morton.hpp"
#include "solver/otm/model.hpp"

namespace kessler::otm {

// Sorts points and nodes body by body, before the first shape-function solve: the connectivity is
// cleared (to be rebuilt) and the LME warm starts are zero.
void sortForLocality(Model& model);
// Points and nodes numbered 0, 1, ... in store order; the adjacency (by point id) follows.
void numberInOrder(Model& model);

}  // namespace kessler::otm
