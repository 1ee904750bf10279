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
#include "core/lanes.hpp"
#include "search/cell_list.hpp"
#include "solver/common/mirror.hpp"
#include "solver/common/own_sums.hpp"
#include "solver/sph/kernel.hpp"
#include "solver/sph/model.hpp"

#include <cstdint>
#include <span>
#include <vector>

#include <omp.h>

namespace kessler::sph {

// A pair as its listing particle i sees it: 16 bytes, a quarter of a cache line (every pass over the
// pairs streams them from memory; the particles' positions, a pair's other factor, stay in cache).
struct Pair {
  // The kernel's gradient over the pair's separation: grad_i W(d, h_ij) = slope d, with d = x_i - T x_j
  // at the positions of the search and h_ij = (h_i + h_j) / 2 (CubicSpline::slopeOverDistance).
  double slope;
  LocalIndex other;     // j
  std::uint8_t mirror;  // the image of j (a code of mirrors(); 0: j itself)
  // Which ends take part in the deformation and the stress (Integrator): bit 1 the listing particle i
  // (j counts in its kernel correction and velocity gradient, and i's stress acts over the pair), bit 2
  // the other end j; 0 neither.
  std::uint8_t active;

  Vec3 gradient(const Vec3& d) const { return slope * d; }
};
static_assert(sizeof(Pair) == 16);

struct Pairs {
  std::vector<Index> offset;  // the pairs particle i lists are pair[offset[i] .. offset[i + 1])
  std::vector<Pair> pair;
  // The pairs that list particle j as their other end (not its own image's), in the order of their
  // listing particle: listed_by[listed_offset[j] .. listed_offset[j + 1]), with that particle and the
  // image beside them.
  std::vector<Index> listed_offset;
  std::vector<std::uint32_t> listed_by;  // (the transpose holds at most 2^32 - 1 pairs)
  std::vector<LocalIndex> listed_other;
  std::vector<std::uint8_t> listed_mirror;  // the image of the listing particle as j meets it

  // The pairs of the first `count` positions with smoothing lengths h, and their images across the
  // mirror planes of `box`, each with its kernel gradient and which of its ends take part,
  // takes_part(i, j, mirror, d) (d = x_i - T x_j; Pair::active's bits), formed as the cell list finds
  // it: one pass. With `share` (a distributed run's own particles and ghosts, in id order), the cells
  // are the whole run's, and pairs of two ghosts are left out (no own particle reads them: a ghost's
  // sums are its owner's). Collective then.
  template <class TakesPart>
  void build(std::span<const Vec3> x, std::span<const double> h, LocalIndex count, const MirrorBox& box,
             const Share& share, TakesPart&& takes_part);
  // The images the codes in `mirror` and `listed_mirror` name.
  const Mirrors& mirrors() const { return mirrors_; }
  Index size() const { return static_cast<Index>(pair.size()); }
  // Each particle's pairs counted from both ends (a particle's pair with its own image once).
  Index neighbourCount() const { return 2 * size() - self_images_; }

  // f(j, mirror, d, g, active) for each pair of particle i, at the positions x of the search: the
  // other particle j (whose image across `mirror` i meets), i's separation from that image
  // d = x_i - T x_j and i's kernel gradient g, both in lanes (core/lanes.hpp), and whether i takes
  // part in the pair (Pair::active); those i lists, then those that list i.
  template <class F>
  void forEachOf(LocalIndex i, std::span<const Vec3> x, F&& f) const {
    const lanes::V xi = lanes::load(x[i]);
    // (A pair across no mirror, from either end: d = x_i - x_j and g = slope d, the listing
    // particle's gradient reversed to the bit.)
    for (Index e = offset[i]; e < offset[i + 1]; ++e) {
      const Pair& p = pair[e];
      lanes::V d, g;
      if (p.mirror == 0) {
        d = lanes::minus(xi, lanes::load(x[p.other]));
        g = lanes::times(p.slope, d);
      } else {
        const Vec3 dm = x[i] - mirrors_.point(x[p.other], p.mirror);
        d = lanes::load(dm);
        g = lanes::load(p.gradient(dm));
      }
      f(p.other, p.mirror, d, g, (p.active & 1) != 0);
    }
    for (Index k = listed_offset[i]; k < listed_offset[i + 1]; ++k) {
      const Pair& p = pair[listed_by[k]];
      const LocalIndex j = listed_other[k];
      const std::uint8_t m = listed_mirror[k];
      lanes::V d, g;
      if (m == 0) {
        d = lanes::minus(xi, lanes::load(x[j]));
        g = lanes::times(p.slope, d);
      } else {
        // (The listing particle's gradient as it forms it, reflected.)
        d = lanes::load(Vec3(x[i] - mirrors_.point(x[j], m)));
        g = lanes::load(Vec3(-mirrors_.vector(p.gradient(x[j] - mirrors_.point(x[i], p.mirror)), m)));
      }
      f(j, m, d, g, (p.active & 2) != 0);
    }
  }

 private:
  // build()'s parts before and after the pass over the cell list: the images and the cells, and the
  // whole run's largest smoothing length (negative where there are no positions); the lists joined in
  // particle order and transposed.
  double prepare(std::span<const Vec3> x, std::span<const double> h, LocalIndex count, const MirrorBox& box,
                 const Share& share);
  void finish(LocalIndex count);
  CellList cells_;
  Mirrors mirrors_;
  std::vector<Index> count_;
  std::vector<std::uint32_t> scratch_;    // the transpose's counters
  std::vector<std::vector<Pair>> found_;  // each thread's pairs, in particle order
  Index self_images_ = 0;
};

template <class TakesPart>
void Pairs::build(std::span<const Vec3> x, std::span<const double> h, LocalIndex count, const MirrorBox& box,
                  const Share& share, TakesPart&& takes_part) {
  const double h_max = prepare(x, h, count, box, share);
  if (h_max < 0.0) return;
  const auto n = static_cast<std::size_t>(count);
  // The images a particle near the planes sees: those whose part of space lies within its reach.
  // The image T x_j of j lies within the reach of x_i where j lies within it of T^-1 x_i.
  const auto visit = [&](std::size_t i, auto&& f) {
    const double reach = h[i] + h_max;
    const bool ghost = !share.own(static_cast<LocalIndex>(i));
    mirrors_.near(x[i], reach, [&](std::uint8_t m) {
      // Each pair once, by its lower particle (a particle's own image once).
      const auto first = static_cast<LocalIndex>(m == 0 ? i + 1 : i);
      cells_.forEachWithinFrom(mirrors_.point(x[i], mirrors_.inverse(m)), reach, first, [&](LocalIndex j, double d2) {
        if (ghost && !share.own(j)) return;  // two ghosts: no own particle reads the pair
        const double support = h[i] + h[static_cast<std::size_t>(j)];
        if (d2 < support * support) f(j, m);
      });
    });
  };
  // One pass over the cell list: each thread lists the pairs of a contiguous block of particles in
  // its own buffer, and the blocks are joined in particle order, so the arrays are the same for any
  // thread count.
  count_.assign(n, 0);
#pragma omp parallel
  {
#pragma omp single
    found_.resize(static_cast<std::size_t>(omp_get_num_threads()));
    std::vector<Pair>& mine = found_[static_cast<std::size_t>(omp_get_thread_num())];
    mine.clear();
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t before = mine.size();
      visit(i, [&](LocalIndex j, std::uint8_t m) {
        const Vec3 d = x[i] - mirrors_.point(x[static_cast<std::size_t>(j)], m);
        const double slope = CubicSpline::slopeOverDistance(d.norm(), 0.5 * (h[i] + h[static_cast<std::size_t>(j)]));
        mine.push_back({slope, j, m, static_cast<std::uint8_t>(takes_part(static_cast<LocalIndex>(i), j, m, d))});
      });
      count_[i] = static_cast<Index>(mine.size() - before);
    }
  }
  finish(count);
}

}  // namespace kessler::sph
