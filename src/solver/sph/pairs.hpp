#pragma once
// SPH's neighbour pairs (docs/theory.md §10): the particles i, j within the support h_i + h_j (the
// mean smoothing length's 2h), and the images of particles across the problem's mirror planes (its
// symmetry planes, a mirrored copy of the model that the run leaves out, and its rollers). Built anew
// at every step's positions from a cell list.
//
// Each pair is listed once, by its lower particle i (j > i, or j >= i for an image: a particle near
// a plane meets its own image), with i's view of it: the kernel's gradient at
// d = x_i - T x_j (T the pair's image, x -> R x + t with R a reflection, solver/common/mirror.hpp).
// j sees the same pair as the image of i by the inverse of T, at d_j = -R d, with the gradient
// -R grad_i W: what is computed once per pair reaches both ends, j's share reflected. Each particle gathers its pairs'
// shares in a fixed order (those it lists, then those that list it, in the order of their listing particle), the same
// for any thread count.
#include "search/cell_list.hpp"
#include "solver/common/mirror.hpp"
#include "solver/common/own_sums.hpp"
#include "solver/sph/kernel.hpp"
#include "solver/sph/model.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace kessler::sph {

struct Pairs {
  std::vector<Index> offset;         // the pairs particle i lists are [offset[i], offset[i + 1])
  std::vector<LocalIndex> other;     // j
  std::vector<std::uint8_t> mirror;  // the image of j (a code of mirrors(); 0: j itself)
  std::vector<std::uint8_t> active;  // takes part in the deformation and the stress (Integrator)
  std::vector<Vec3> gradient;        // grad_i W(x_i - x_j', h_ij), h_ij = (h_i + h_j) / 2
  // The pairs that list particle j as their other end (not its own image's), in the order of their
  // listing particle: listed_by[listed_offset[j] .. listed_offset[j + 1]), with that particle and the
  // image beside them.
  std::vector<Index> listed_offset;
  std::vector<std::uint32_t> listed_by;  // (the transpose holds at most 2^32 - 1 pairs)
  std::vector<LocalIndex> listed_other;
  std::vector<std::uint8_t> listed_mirror;  // the image of the listing particle as j meets it

  // The pairs of the first `count` positions with smoothing lengths h, and their images across the
  // mirror planes of `box` (their kernels and activity by weigh()). With `share` (a distributed run's
  // own particles and ghosts, in id order), the cells are the whole run's, and pairs of two ghosts are
  // left out (no own particle reads them: a ghost's sums are its owner's). Collective then.
  void build(std::span<const Vec3> x, std::span<const double> h, LocalIndex count, const MirrorBox& box,
             const Share& share = {});
  // Each pair's kernel gradient at the positions x it was built with, and its activity,
  // takes_part(i, j, mirror, d) with d = x_i - T x_j: one pass over the pairs.
  template <class TakesPart>
  void weigh(std::span<const Vec3> x, std::span<const double> h, TakesPart&& takes_part);
  // The images the codes in `mirror` and `listed_mirror` name.
  const Mirrors& mirrors() const { return mirrors_; }
  Index size() const { return static_cast<Index>(other.size()); }
  // Each particle's pairs counted from both ends (a particle's pair with its own image once).
  Index neighbourCount() const { return 2 * size() - self_images_; }

  // f(j, mirror, g, active) for each pair of particle i: the other particle j (whose image across
  // `mirror` i meets), i's kernel gradient g and whether the pair is active; those i lists, then
  // those that list i.
  template <class F>
  void forEachOf(LocalIndex i, F&& f) const {
    for (Index e = offset[i]; e < offset[i + 1]; ++e) f(other[e], mirror[e], gradient[e], active[e] != 0);
    for (Index k = listed_offset[i]; k < listed_offset[i + 1]; ++k) {
      const Index e = listed_by[k];
      f(listed_other[k], listed_mirror[k], Vec3(-mirrors_.vector(gradient[e], listed_mirror[k])), active[e] != 0);
    }
  }

 private:
  struct Found {
    LocalIndex j;
    std::uint8_t mirror;
  };
  CellList cells_;
  Mirrors mirrors_;
  std::vector<Index> count_;
  std::vector<std::uint32_t> scratch_;     // the transpose's counters
  std::vector<std::vector<Found>> found_;  // each thread's pairs, in particle order
  Index self_images_ = 0;
};

template <class TakesPart>
void Pairs::weigh(std::span<const Vec3> x, std::span<const double> h, TakesPart&& takes_part) {
  const auto n = static_cast<LocalIndex>(offset.size()) - 1;
#pragma omp parallel for schedule(static)
  for (LocalIndex i = 0; i < n; ++i)
    for (Index e = offset[i]; e < offset[i + 1]; ++e) {
      const LocalIndex j = other[e];
      const Vec3 d = x[i] - mirrors_.point(x[j], mirror[e]);
      gradient[e] = CubicSpline::slopeOverDistance(d.norm(), 0.5 * (h[i] + h[j])) * d;
      active[e] = takes_part(i, j, mirror[e], d);
    }
}

}  // namespace kessler::sph
