#pragma once
// The surface a sliding contact sees of an RKPM lattice body (docs/theory.md §12): triangles whose
// vertices are its boundary particles (those with an element face that no element shares), which lie
// half a spacing inside the body's surface (the contact's gap, solver/common/sliding_contact.hpp).
// Each exposed direction's boundary particles form a sheet; each particle and its neighbours along
// the sheet's two axes (one element up or down where the surface steps, as a sphere's lattice does)
// span two triangles, counter-clockwise seen from outside. Sheets of different directions meet at
// the particles they share, along a body's edges.
#include "core/types.hpp"

#include <array>
#include <vector>

namespace kessler::rkpm {

// `element`: each particle's lattice element (i, j, k), the particles numbered from `first`.
std::vector<std::array<LocalIndex, 3>> latticeSurface(const std::vector<std::array<int, 3>>& element, LocalIndex first);

}  // namespace kessler::rkpm
