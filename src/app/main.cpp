// The `kessler` command line: run, check, verify.
#include "app/commands.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "parallel/communicator.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <climits>
#include <exception>
#include <string_view>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

int main(int argc, char** argv) {
#if defined(__GLIBC__)
  // A step and an output free and take again buffers of the same sizes (halo messages, a gathered
  // output's arrays). glibc would hand blocks of over 128 kB back to the system and take them again
  // page by page, and a fresh page costs a fault (about 12 us each on a virtual machine, measured:
  // docs/performance.md). Blocks up to 32 MB come from the heap instead, and freed memory stays
  // there for the next: the peak is the same, the faults are not paid again.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, INT_MAX);
#endif
  // MPI starts only under mpirun (parallel/communicator.hpp); a plain run never touches it.
  kessler::parallel::Session session(argc, argv);
  const kessler::parallel::Communicator& world = kessler::parallel::Communicator::world();
  const bool distributed = world.size() > 1;
  if (distributed) {
    // Under mpirun the ranks run one problem together (docs/parallel.md): `run` and `bench` do so.
    const char* command = nullptr;
    for (int i = 1; i < argc && !command; ++i)
      if (argv[i][0] != '-') command = argv[i];
    if (!command || (std::string_view(command) != "run" && std::string_view(command) != "bench")) {
      if (world.root())
        fmt::print(stderr,
                   "kessler: error: started on {} ranks; only `kessler run` and `kessler bench` run across ranks "
                   "(docs/parallel.md), so run `{}` without mpirun\n",
                   world.size(), command ? command : "kessler");
      return 1;
    }
    // Rank 0 speaks for the run.
    if (!world.root()) kessler::log::setLevel(kessler::log::Level::quiet);
  }
  CLI::App app{"Kessler: hypervelocity impact simulation with the Optimal Transportation Meshfree method"};
  app.require_subcommand(1);
  kessler::app::addCommands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // (Every rank parses the same command line: rank 0 says what is wrong.)
    return world.root() ? app.exit(e) : e.get_exit_code();
  } catch (const kessler::NumericalError& e) {
    // One handler at the top: a one-line message, non-zero exit, never a stack trace. Every rank of
    // a distributed run stops a failing step together: rank 0 reports it.
    if (world.root()) fmt::print(stderr, "kessler: error: {}\n", e.what());
    return 1;
  } catch (const kessler::InputError& e) {
    // (Every rank reads the same input.)
    if (world.root()) fmt::print(stderr, "kessler: error: {}\n", e.what());
    return 1;
  } catch (const kessler::Error& e) {
    if (!distributed) {
      fmt::print(stderr, "kessler: error: {}\n", e.what());
      return 1;
    }
    // The other ranks may not have seen it, and would wait for this one: end them all.
    fmt::print(stderr, "kessler: error (rank {}): {}\n", world.rank(), e.what());
    world.abort(1);
  } catch (const std::exception& e) {
    fmt::print(stderr, "kessler: internal error{}: {}\n", distributed ? fmt::format(" (rank {})", world.rank()) : "",
               e.what());
    if (distributed) world.abort(2);
    return 2;
  }
  return kessler::app::exitCode();
}
