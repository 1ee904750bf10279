#pragma once
// SPH's neighbour pairs (docs/theory.md §10): for each particle i, the particles j within the
// support h_i + h_j (the mean smoothing length's 2h), and the images of particles across the
// problem's symmetry planes (a mirrored copy of the model that the run leaves out). Built anew at
// every step's positions from a cell list; the order of each particle's pairs is the cell list's,
// the same for any thread count.
#include "search/cell_list.hpp"
#include "solver/sph/model.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace kessler::sph {

// x reflected across the symmetry planes normal to the axes whose bits `mirror` sets.
inline Vec3 reflect(Vec3 x, std::uint8_t mirror) {
  for (int a = 0; a < 3; ++a)
    if (mirror & (1u << a)) x[a] = -x[a];
  return x;
}
// A tensor of the image (R T R with R the reflection).
inline Mat3 reflect(Mat3 t, std::uint8_t mirror) {
  for (int a = 0; a < 3; ++a)
    if (mirror & (1u << a)) {
      t.row(a) *= -1.0;
      t.col(a) *= -1.0;
    }
  return t;
}

struct Pairs {
  std::vector<Index> offset;         // particle i's pairs are [offset[i], offset[i + 1])
  std::vector<LocalIndex> other;     // j
  std::vector<std::uint8_t> mirror;  // the image of j across these planes (0: j itself)
  std::vector<std::uint8_t> active;  // takes part in the deformation and the stress (Integrator)
  std::vector<Vec3> gradient;        // grad_i W(x_i - x_j', h_ij), h_ij = (h_i + h_j) / 2
  std::vector<double> kernel;        // W(|x_i - x_j'|, h_ij)

  // The pairs of the first `count` positions with smoothing lengths h, and their images across the
  // planes normal to `symmetry_axes` (particles at x[a] >= 0).
  void build(std::span<const Vec3> x, std::span<const double> h, LocalIndex count,
             const std::vector<int>& symmetry_axes);
  Index size() const { return static_cast<Index>(other.size()); }

 private:
  struct Found {
    LocalIndex j;
    std::uint8_t mirror;
  };
  CellList cells_;
  std::vector<Index> count_;
  std::vector<std::vector<Found>> found_;  // each thread's pairs, in particle order
};

}  // namespace kessler::sph
