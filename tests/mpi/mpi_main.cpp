// The main of the multi-rank tests (tests/mpi): MPI started before GoogleTest, one full report from
// rank 0, and each other rank's failures on lines that name it; a failure on any rank fails the run
// through its exit code.
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
  const int failed = RUN_ALL_TESTS();
  return world.any(failed != 0) ? 1 : 0;
}
