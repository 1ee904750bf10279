#include "solver/sph/pairs.hpp"

#include "core/transpose.hpp"

#include <algorithm>

#include <omp.h>

namespace kessler::sph {

void Pairs::build(std::span<const Vec3> x, std::span<const double> h, LocalIndex count, const MirrorBox& box,
                  const Share& share) {
  const auto n = static_cast<std::size_t>(count);
  // The whole run's largest smoothing length and cell size (a distributed run's ranks agree on
  // them, so that each particle meets its candidates in the one process's order).
  double h_max = 0.0;
  std::int64_t own = 0;
  for (std::size_t i = 0; i < n; ++i) {
    h_max = std::max(h_max, h[i]);
    own += share.own(static_cast<LocalIndex>(i)) ? 1 : 0;
  }
  h_max = share.max(h_max);
  // The images a particle's search reaches (h_i + h_max), enough for twice as far when they are made
  // anew: the codes name the same images in the same order, however far the table reaches.
  if (mirrors_.box().lo != box.lo || mirrors_.box().hi != box.hi || (box.any() && mirrors_.reach() < 2.0 * h_max))
    mirrors_ = Mirrors(box, 4.0 * h_max);
  const double cell_size = agreedCellSize(x, count, own, 2.0 * h_max, share);
  if (n == 0) {
    *this = Pairs{};
    offset.assign(1, 0);
    listed_offset.assign(1, 0);
    return;
  }
  offset.assign(n + 1, 0);
  cells_.build(x, count, cell_size, /*enlarge=*/!share.comm);
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
    std::vector<Found>& mine = found_[static_cast<std::size_t>(omp_get_thread_num())];
    mine.clear();
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t before = mine.size();
      visit(i, [&](LocalIndex j, std::uint8_t m) { mine.push_back({j, m}); });
      count_[i] = static_cast<Index>(mine.size() - before);
    }
  }
  for (std::size_t i = 0; i < n; ++i) offset[i + 1] = offset[i] + count_[i];
  const auto total = static_cast<std::size_t>(offset[n]);
  other.resize(total);
  mirror.resize(total);
  active.resize(total);
  gradient.resize(total);
  // Thread t's block begins at the pairs of all blocks before it (as listed under schedule(static)).
  std::vector<std::size_t> start(found_.size() + 1, 0);
  for (std::size_t t = 0; t < found_.size(); ++t) start[t + 1] = start[t] + found_[t].size();
#pragma omp parallel for schedule(static, 1)
  for (std::size_t t = 0; t < found_.size(); ++t)
    for (std::size_t k = 0; k < found_[t].size(); ++k) {
      other[start[t] + k] = found_[t][k].j;
      mirror[start[t] + k] = found_[t][k].mirror;
    }
  // The other ends' lists: each particle's pairs listed by lower particles, in their order (a
  // particle's pair with its own image is its own alone).
  transposeRows(
      offset, count, listed_offset, scratch_,
      [&](Index e, LocalIndex i) { return other[e] == i ? LocalIndex{-1} : other[e]; },
      [&](std::size_t listed) {
        listed_by.resize(listed);
        listed_other.resize(listed);
        listed_mirror.resize(listed);
      },
      [&](std::size_t k, Index e, LocalIndex i) {
        listed_by[k] = static_cast<std::uint32_t>(e);
        listed_other[k] = i;
        listed_mirror[k] = mirrors_.inverse(mirror[e]);
      });
  self_images_ = offset[n] - listed_offset[n];
}

}  // namespace kessler::sph
