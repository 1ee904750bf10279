#include "parallel/communicator.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <climits>
#include <cstdlib>

#if KESSLER_HAVE_MPI
#include <mpi.h>
#endif

namespace kessler::parallel {

bool launched() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMIX_RANK") != nullptr;
}

#if KESSLER_HAVE_MPI

namespace {

MPI_Comm world_comm = MPI_COMM_WORLD;

bool running() {
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  return initialised && !finalised;
}

MPI_Comm comm(const void* handle) {
  return *static_cast<const MPI_Comm*>(handle);
}

void check(int status, const char* what) {
  if (status == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(status, text, &length);
  throw Error(fmt::format("MPI {} failed: {}", what, std::string(text, static_cast<std::size_t>(length))));
}

int count(std::size_t bytes) {
  KESSLER_VERIFY(bytes <= static_cast<std::size_t>(INT_MAX), "an MPI message of {} bytes is over MPI's 2 GiB limit",
                 bytes);
  return static_cast<int>(bytes);
}

}  // namespace

Session::Session(int& argc, char**& argv) {
  if (!launched() || running()) return;
  int provided = 0;
  check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "initialisation");
  initialised_ = true;
  // Errors come back as codes (check() turns them into a kessler::Error) rather than aborting.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
}

Session::~Session() {
  if (initialised_ && running()) MPI_Finalize();
}

const Communicator& Communicator::world() {
  static const Communicator world = [] {
    if (!running()) return Communicator(nullptr, 0, 1);
    int rank = 0, size = 1;
    MPI_Comm_rank(world_comm, &rank);
    MPI_Comm_size(world_comm, &size);
    return Communicator(&world_comm, rank, size);
  }();
  return world;
}

void Communicator::sum(std::span<std::int64_t> values) const {
  if (!handle_ || values.empty()) return;
  check(MPI_Allreduce(MPI_IN_PLACE, values.data(), count(values.size()), MPI_INT64_T, MPI_SUM, comm(handle_)), "sum");
}

void Communicator::min(std::span<double> values) const {
  if (!handle_ || values.empty()) return;
  check(MPI_Allreduce(MPI_IN_PLACE, values.data(), count(values.size()), MPI_DOUBLE, MPI_MIN, comm(handle_)),
        "minimum");
}

void Communicator::max(std::span<double> values) const {
  if (!handle_ || values.empty()) return;
  check(MPI_Allreduce(MPI_IN_PLACE, values.data(), count(values.size()), MPI_DOUBLE, MPI_MAX, comm(handle_)),
        "maximum");
}

std::vector<std::vector<std::byte>> Communicator::exchange(const std::vector<std::vector<std::byte>>& outgoing) const {
  KESSLER_VERIFY(outgoing.size() == static_cast<std::size_t>(size_), "an exchange with {} buffers among {} ranks",
                 outgoing.size(), size_);
  if (!handle_) return outgoing;
  std::vector<int> send_counts(static_cast<std::size_t>(size_)), receive_counts(send_counts.size());
  std::vector<int> send_offsets(send_counts.size()), receive_offsets(send_counts.size());
  std::vector<std::byte> send;
  for (int r = 0; r < size_; ++r) {
    const auto& buffer = outgoing[static_cast<std::size_t>(r)];
    send_offsets[r] = count(send.size());
    send_counts[r] = count(buffer.size());
    send.insert(send.end(), buffer.begin(), buffer.end());
  }
  check(MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, comm(handle_)),
        "exchange of sizes");
  std::size_t total = 0;
  for (int r = 0; r < size_; ++r) {
    receive_offsets[r] = count(total);
    total += static_cast<std::size_t>(receive_counts[r]);
  }
  std::vector<std::byte> received(std::max<std::size_t>(total, 1));
  check(MPI_Alltoallv(send.data(), send_counts.data(), send_offsets.data(), MPI_BYTE, received.data(),
                      receive_counts.data(), receive_offsets.data(), MPI_BYTE, comm(handle_)),
        "exchange");
  std::vector<std::vector<std::byte>> incoming(static_cast<std::size_t>(size_));
  for (int r = 0; r < size_; ++r)
    incoming[r].assign(received.begin() + receive_offsets[r],
                       received.begin() + receive_offsets[r] + receive_counts[r]);
  return incoming;
}

void Communicator::exchangeWith(std::span<const int> to, const std::vector<std::vector<std::byte>>& outgoing,
                                std::span<const int> from, std::vector<std::vector<std::byte>>& incoming) const {
  if (!handle_) {
    KESSLER_VERIFY(to.empty() && from.empty(), "messages between ranks in one process");
    return;
  }
  constexpr int tag = 7;
  std::vector<MPI_Request> requests;
  requests.reserve(to.size() + from.size());
  for (const int s : from) {
    auto& buffer = incoming[static_cast<std::size_t>(s)];
    requests.emplace_back();
    check(MPI_Irecv(buffer.data(), count(buffer.size()), MPI_BYTE, s, tag, comm(handle_), &requests.back()), "receive");
  }
  for (const int r : to) {
    const auto& buffer = outgoing[static_cast<std::size_t>(r)];
    requests.emplace_back();
    check(MPI_Isend(buffer.data(), count(buffer.size()), MPI_BYTE, r, tag, comm(handle_), &requests.back()), "send");
  }
  check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE), "wait for messages");
}

std::vector<std::vector<std::byte>> Communicator::allGather(std::span<const std::byte> mine) const {
  if (!handle_) return {std::vector<std::byte>(mine.begin(), mine.end())};
  std::vector<int> counts(static_cast<std::size_t>(size_)), offsets(counts.size());
  const int own = count(mine.size());
  check(MPI_Allgather(&own, 1, MPI_INT, counts.data(), 1, MPI_INT, comm(handle_)), "gathering of sizes");
  std::size_t total = 0;
  for (int r = 0; r < size_; ++r) {
    offsets[r] = count(total);
    total += static_cast<std::size_t>(counts[r]);
  }
  std::vector<std::byte> all(std::max<std::size_t>(total, 1));
  check(MPI_Allgatherv(mine.data(), own, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, comm(handle_)),
        "gathering");
  std::vector<std::vector<std::byte>> each(static_cast<std::size_t>(size_));
  for (int r = 0; r < size_; ++r) each[r].assign(all.begin() + offsets[r], all.begin() + offsets[r] + counts[r]);
  return each;
}

std::vector<std::vector<std::byte>> Communicator::gather(std::vector<std::byte> mine) const {
  if (!handle_) return {std::move(mine)};
  std::vector<int> counts(static_cast<std::size_t>(size_));
  const int own = count(mine.size());
  check(MPI_Gather(&own, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm(handle_)), "gathering of sizes");
  constexpr int tag = 8;
  if (!root()) {
    check(MPI_Send(mine.data(), own, MPI_BYTE, 0, tag, comm(handle_)), "sending to rank 0");
    return {};
  }
  std::vector<std::vector<std::byte>> each(static_cast<std::size_t>(size_));
  std::vector<MPI_Request> requests;
  for (int r = 1; r < size_; ++r) {
    auto& buffer = each[static_cast<std::size_t>(r)];
    buffer.resize(static_cast<std::size_t>(counts[static_cast<std::size_t>(r)]));
    requests.emplace_back();
    check(MPI_Irecv(buffer.data(), counts[static_cast<std::size_t>(r)], MPI_BYTE, r, tag, comm(handle_),
                    &requests.back()),
          "receiving on rank 0");
  }
  each[0] = std::move(mine);
  check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE), "gathering to rank 0");
  return each;
}

void Communicator::abort(int code) const {
  if (handle_) MPI_Abort(comm(handle_), code);
  std::exit(code);
}

#else  // one process: every collective is the identity

Session::Session(int&, char**&) {}
Session::~Session() = default;

const Communicator& Communicator::world() {
  static const Communicator world(nullptr, 0, 1);
  return world;
}

void Communicator::sum(std::span<std::int64_t>) const {}
void Communicator::min(std::span<double>) const {}
void Communicator::max(std::span<double>) const {}

std::vector<std::vector<std::byte>> Communicator::exchange(const std::vector<std::vector<std::byte>>& outgoing) const {
  KESSLER_VERIFY(outgoing.size() == 1, "an exchange with {} buffers in one process", outgoing.size());
  return outgoing;
}

void Communicator::exchangeWith(std::span<const int> to, const std::vector<std::vector<std::byte>>&,
                                std::span<const int> from, std::vector<std::vector<std::byte>>&) const {
  KESSLER_VERIFY(to.empty() && from.empty(), "messages between ranks in one process");
}

std::vector<std::vector<std::byte>> Communicator::allGather(std::span<const std::byte> mine) const {
  return {std::vector<std::byte>(mine.begin(), mine.end())};
}

std::vector<std::vector<std::byte>> Communicator::gather(std::vector<std::byte> mine) const {
  return {std::move(mine)};
}

void Communicator::abort(int code) const {
  std::exit(code);
}

#endif

double Communicator::min(double value) const {
  min(std::span<double>(&value, 1));
  return value;
}

double Communicator::max(double value) const {
  max(std::span<double>(&value, 1));
  return value;
}

std::int64_t Communicator::sum(std::int64_t value) const {
  sum(std::span<std::int64_t>(&value, 1));
  return value;
}

bool Communicator::any(bool flag) const {
  return sum(std::int64_t{flag ? 1 : 0}) > 0;
}

double Communicator::sum(ExactSum& partial) const {
  if (size_ > 1) {
    ExactSum::State state = partial.state();
    sum(std::span<std::int64_t>(state));
    partial.setState(state);
  }
  return partial.value();
}

}  // namespace kessler::parallel
