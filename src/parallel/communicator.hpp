#pragma once
// The processes of a run (docs/parallel.md). A program started by `mpirun` (Open MPI) initialises
// MPI through a Session and its world communicator spans the ranks; started any other way, or
// built without MPI (KESSLER_MPI=OFF), it is one process and every collective below is the
// identity. Nothing here includes mpi.h: the layers above see no MPI type.
#include "core/exact_sum.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace kessler::parallel {

// True when this process was started by an MPI launcher (Open MPI's mpirun sets
// OMPI_COMM_WORLD_SIZE, PMIx launchers PMIX_RANK): only then does a Session initialise MPI, so
// that a plain `kessler run` never starts MPI's runtime.
bool launched();

// Initialises MPI (thread level funnelled: OpenMP threads never call MPI) when the process was
// launched by mpirun and finalises it when destroyed. One per program, in main().
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

 private:
  [[maybe_unused]] bool initialised_ = false;  // by this Session (unused without MPI)
};

class Communicator {
 public:
  // All the ranks of the run (one process when MPI is not running).
  static const Communicator& world();

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }

  // Element-wise sums, minima and maxima over the ranks, in place. Integer sums are exact, so
  // their result does not depend on the ranks' order.
  void sum(std::span<std::int64_t> values) const;
  void min(std::span<double> values) const;
  void max(std::span<double> values) const;
  double min(double value) const;
  double max(double value) const;
  std::int64_t sum(std::int64_t value) const;
  // True on every rank when `flag` is true on any.
  bool any(bool flag) const;
  // The exact sum over the ranks of each rank's accumulator (which then holds it), rounded once:
  // the same bits for any number of ranks and any split of the terms among them.
  double sum(ExactSum& partial) const;

  // Every rank sends outgoing[r] to rank r and receives, in the result's [s], what rank s sent it.
  // outgoing.size() must be size().
  std::vector<std::vector<std::byte>> exchange(const std::vector<std::vector<std::byte>>& outgoing) const;
  // Messages between neighbours only, no collective: sends outgoing[r] to each rank r in `to`, and
  // receives into incoming[s], already sized to the bytes expected, from each rank s in `from`
  // (both buffer lists are indexed by rank). What each pair sends must be agreed beforehand.
  void exchangeWith(std::span<const int> to, const std::vector<std::vector<std::byte>>& outgoing,
                    std::span<const int> from, std::vector<std::vector<std::byte>>& incoming) const;
  // Every rank's `mine`, in rank order, on every rank.
  std::vector<std::vector<std::byte>> allGather(std::span<const std::byte> mine) const;
  // Every rank's `mine`, in rank order, on rank 0 (its own moved, the others' received straight into
  // their buffers: a gathered run's output is the largest message); nothing elsewhere.
  std::vector<std::vector<std::byte>> gather(std::vector<std::byte> mine) const;
  // Ends every rank of the run with `code` (an error that the ranks did not all see: waiting for
  // the others would hang).
  [[noreturn]] void abort(int code) const;

  // The MPI communicator (an MPI_Comm) for libraries that take one (Zoltan); null without MPI.
  const void* handle() const { return handle_; }

 private:
  Communicator(const void* handle, int rank, int size) : handle_(handle), rank_(rank), size_(size) {}
  const void* handle_;
  int rank_, size_;
};

}  // namespace kessler::parallel
