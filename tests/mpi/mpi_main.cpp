// The main of the multi-rank tests (tests/mpi): MPI started before GoogleTest, one full report from
// rank 0, and each other rank's failures on lines that name it; a failure on any rank fails the run
// through its exit code. A fatal failure (ASSERT_*) on one rank ends the test there while the others
// go on into its next collective, where they would wait until the test's timeout: it aborts every
// rank at once instead.
#include "parallel/communicator.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace {

// The other ranks report only their failures, each line naming its rank.
class FailurePrinter : public ::testing::EmptyTestEventListener {
 public:
  explicit FailurePrinter(int rank) : rank_(rank) {}
  void OnTestPartResult(const ::testing::TestPartResult& result) override {
    if (result.failed())
      std::fprintf(stderr, "[rank %d] %s:%d: %s\n", rank_, result.file_name() ? result.file_name() : "?",
                   result.line_number(), result.message());
  }

 private:
  int rank_;
};

// Every rank: a fatal failure aborts the run on every rank (after the printers above have reported it).
class FatalAborts : public ::testing::EmptyTestEventListener {
 public:
  void OnTestPartResult(const ::testing::TestPartResult& result) override {
    if (!result.fatally_failed()) return;
    std::fprintf(stderr, "[rank %d] a fatal failure: aborting every rank\n",
                 kessler::parallel::Communicator::world().rank());
    std::fflush(stderr);
    std::fflush(stdout);
    kessler::parallel::Communicator::world().abort(1);
  }
};

}  // namespace

int main(int argc, char** argv) {
  kessler::parallel::Session session(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  // One full report, from rank 0; a failure on any rank fails the run through its exit code.
  const kessler::parallel::Communicator& world = kessler::parallel::Communicator::world();
  if (!world.root()) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
    listeners.Append(new FailurePrinter(world.rank()));
  }
  ::testing::UnitTest::GetInstance()->listeners().Append(new FatalAborts);
  const int failed = RUN_ALL_TESTS();
  return world.any(failed != 0) ? 1 : 0;
}
