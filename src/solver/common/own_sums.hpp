#pragma once
// Sums, minima and flags over the entries a rank owns, taken over every rank of a distributed run
// (docs/parallel.md): ghosts are someone else's and count there. Without a communicator (one
// process) every entry is own. Sums are exact (core/exact_sum.hpp), so they are the same bits for
// any partition.
#include "core/error.hpp"
#include "core/exact_sum.hpp"
#include "parallel/communicator.hpp"
#include "search/cell_list.hpp"

#include <cstdint>
#include <limits>
#include <span>

namespace kessler {

// Which entries of a store are this rank's own, and the ranks to reduce over (null: one process).
struct Share {
  std::span<const std::uint8_t> ghost;  // per entry, 1 for a ghost; empty: none
  const parallel::Communicator* comm = nullptr;

  bool own(LocalIndex i) const { return ghost.empty() || ghost[static_cast<std::size_t>(i)] == 0; }
  double min(double value) const { return comm ? comm->min(value) : value; }
  double max(double value) const { return comm ? comm->max(value) : value; }
  std::int64_t sum(std::int64_t value) const { return comm ? comm->sum(value) : value; }
  bool any(bool flag) const { return comm ? comm->any(flag) : flag; }
  // Stops every rank when `failed_here` is true on any (the others would wait for it): this rank
  // calls fail(), which throws; the others throw NumericalError(`elsewhere`). One process: fail()
  // if failed_here.
  template <class Fail>
  void stopTogether(bool failed_here, Fail&& fail, const char* elsewhere) const {
    const bool anywhere = any(failed_here);
    if (failed_here) fail();
    if (anywhere) throw NumericalError(elsewhere);
  }
};

// sum over the own entries i < n of term(i) (an Eigen vector of K components), over every rank.
// term is called for ghosts too (what it writes on the way is kept), and their terms left out.
template <int K, typename F>
Eigen::Matrix<double, K, 1> ownSums(const Share& share, LocalIndex n, F&& term) {
  std::array<ExactSum, K> partial = exactPartialSums<K>(n, [&](LocalIndex i) {
    const Eigen::Matrix<double, K, 1> t = term(i);
    return share.own(i) ? t : Eigen::Matrix<double, K, 1>::Zero().eval();
  });
  Eigen::Matrix<double, K, 1> sum;
  for (int k = 0; k < K; ++k) sum[k] = share.comm ? share.comm->sum(partial[k]) : partial[k].value();
  return sum;
}

template <typename F>
double ownSum(const Share& share, LocalIndex n, F&& term) {
  return ownSums<1>(share, n, [&](LocalIndex i) { return Eigen::Matrix<double, 1, 1>(term(i)); })[0];
}

// The cell size a cell list over a set of the whole run would take (CellList::build enlarges
// `cell_size` by the set's extent and count): `x` holds this rank's positions of the set (own and
// ghosts: all within the whole's bounds), `own` how many of them are its own. A rank builds its
// cell list with it as it is (CellList::build, enlarge false).
inline double agreedCellSize(std::span<const Vec3> x, LocalIndex count, std::int64_t own, double cell_size,
                             const Share& share) {
  if (!share.comm) return cell_size;
  CellList::Bounds b = CellList::boundsOf(x, count);
  if (count == 0) {
    b.lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    b.hi = -b.lo;
  }
  share.comm->min(std::span<double>(b.lo.data(), 3));
  share.comm->max(std::span<double>(b.hi.data(), 3));
  return CellList::enlargedSize(b, share.comm->sum(own), cell_size);
}

}  // namespace kessler
