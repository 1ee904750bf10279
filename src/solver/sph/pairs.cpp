#include "solver/sph/pairs.hpp"

#include "core/transpose.hpp"

#include <algorithm>

namespace kessler::sph {

double Pairs::prepare(std::span<const Vec3> x, std::span<const double> h, LocalIndex count, const MirrorBox& box,
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
    return -1.0;
  }
  offset.assign(n + 1, 0);
  cells_.build(x, count, cell_size, /*enlarge=*/!share.comm);
  return h_max;
}

void Pairs::finish(LocalIndex count) {
  const auto n = static_cast<std::size_t>(count);
  for (std::size_t i = 0; i < n; ++i) offset[i + 1] = offset[i] + count_[i];
  // Thread t's block begins at the pairs of all blocks before it (as listed under schedule(static));
  // one thread's list is the whole (its storage swapped, not copied).
  if (found_.size() == 1) {
    pair.swap(found_[0]);
  } else {
    pair.resize(static_cast<std::size_t>(offset[n]));
    std::vector<std::size_t> start(found_.size() + 1, 0);
    for (std::size_t t = 0; t < found_.size(); ++t) start[t + 1] = start[t] + found_[t].size();
#pragma omp parallel for schedule(static, 1)
    for (std::size_t t = 0; t < found_.size(); ++t)
      std::copy(found_[t].begin(), found_[t].end(), pair.begin() + static_cast<std::ptrdiff_t>(start[t]));
  }
  // The other ends' lists: each particle's pairs listed by lower particles, in their order (a
  // particle's pair with its own image is its own alone).
  transposeRows(
      offset, count, listed_offset, scratch_,
      [&](Index e, LocalIndex i) { return pair[e].other == i ? LocalIndex{-1} : pair[e].other; },
      [&](std::size_t listed) {
        listed_by.resize(listed);
        listed_other.resize(listed);
        listed_mirror.resize(listed);
      },
      [&](std::size_t k, Index e, LocalIndex i) {
        listed_by[k] = static_cast<std::uint32_t>(e);
        listed_other[k] = i;
        listed_mirror[k] = mirrors_.inverse(pair[e].mirror);
      });
  self_images_ = offset[n] - listed_offset[n];
}

}  // namespace kessler::sph
