#pragma once
// The surface a sliding contact sees of an RKPM lattice body (docs/theory.md §12): triangles whose
// vertices are its boundary particles (those with an element face that no element shares), which lie
// half a spacing inside the body's surface (the contact's gap, solver/common/sliding_contact.hpp).
// Each exposed direction's boundary particles form a sheet; each particle and its neighbours along
// the sheet's two axes (one element up or down where the surface steps, as a sphere's lattice does)
// span two triangles, counter-clockwise seen from outside. Sheets of different directions meet at
// the particles they share, along a body's edges. The integrator builds it again over the particles
// that are still the body's whenever some leave it as debris: the particles beneath become surface.
#include "core/types.hpp"

#include <array>
#include <span>
#include <vector>

namespace kessler::rkpm {

// The surface of the particles `present` (one body's, in index order; particle p's lattice element
// is element[p]), as triangles of particle indices: per axis and side, the exposed elements in the
// order of their (i, j, k).
std::vector<std::array<LocalIndex, 3>> latticeSurface(std::span<const std::array<int, 3>> element,
                                                      std::span<const LocalIndex> present);

}  // namespace kessler::rkpm
