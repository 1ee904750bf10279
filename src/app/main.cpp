// The `kessler` command line: run, check, verify.
#include "app/commands.hpp"
#include "core/error.hpp"
#include "parallel/communicator.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <exception>

int main(int argc, char** argv) {
  // MPI starts only under mpirun (parallel/communicator.hpp); a plain run never touches it.
  kessler::parallel::Session session(argc, argv);
  const kessler::parallel::Communicator& world = kessler::parallel::Communicator::world();
  if (world.size() > 1) {
    // The processes are up (docs/parallel.md), but no command steps a problem across them yet:
    // refuse rather than run the same problem once per rank.
    if (world.root())
      fmt::print(stderr,
                 "kessler: error: started on {} ranks, but this version runs a problem on one process only "
                 "(distributed stepping is not built yet: docs/parallel.md); run it without mpirun\n",
                 world.size());
    return 1;
  }
  CLI::App app{"Kessler: hypervelocity impact simulation with the Optimal Transportation Meshfree method"};
  app.require_subcommand(1);
  kessler::app::addCommands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const kessler::Error& e) {
    // One handler at the top: a one-line message, non-zero exit, never a stack trace.
    fmt::print(stderr, "kessler: error: {}\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "kessler: internal error: {}\n", e.what());
    return 2;
  }
  return kessler::app::exitCode();
}
