// `kessler run DECK [--out DIR] [--threads N] [--set key=value ...]`, `kessler run --restart DIR`
// and `kessler check DECK`.
#include "app/commands.hpp"
#include "app/simulation.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "geometry/shape.hpp"
#include "io/deck.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <memory>

namespace kessler::app {

namespace {

struct RunArguments {
  std::string deck;
  std::string out;
  int threads = 0;
  std::vector<std::string> sets;
  bool quiet = false;
  std::string restart;
};

void runDeck(const RunArguments& args) {
  if (args.quiet) log::setLevel(log::Level::quiet);
  if (args.restart.empty() == args.deck.empty())
    throw InputError("kessler run needs a deck, or --restart DIR to continue a run (not both)");
  const bool restart = !args.restart.empty();
  if (restart && !args.out.empty()) throw InputError("--restart DIR continues the run in DIR: --out does not apply");
  io::RunConfig config = restart ? restartConfig(args.restart, args.sets) : io::parseDeck(args.deck, args.sets);
  if (!args.out.empty()) config.output.dir = args.out;
  const RunOutcome outcome =
      runSimulation(config, RunOptions{.threads = args.threads, .progress = !args.quiet, .restart = restart});
  setExitCode(outcome.exit_code);
}

void checkDeck(const RunArguments& args) {
  const io::RunConfig config = io::parseDeck(args.deck, args.sets);
  fmt::print("{}: ok — {} material(s), {} body(ies), end time {:.4g} s\n", args.deck, config.materials.size(),
             config.bodies.size(), config.solver.end_time);
  for (const io::BodyConfig& b : config.bodies)
    fmt::print("  {:<16} {:<8} mesh size {:.4g} m, volume {:.4g} m^3, material {}\n", b.name,
               geometry::kindName(b.mesh.shape), b.mesh.mesh_size, geometry::volume(b.mesh.shape),
               config.materials[static_cast<std::size_t>(b.material)].name);
  fmt::print("  estimated memory {:.3g} MB\n", io::estimateMemoryBytes(config) / 1e6);
}

}  // namespace

void addRunCommands(CLI::App& app) {
  auto args = std::make_shared<RunArguments>();
  CLI::App* run = app.add_subcommand("run", "Run a deck");
  run->add_option("deck", args->deck, "YAML deck")->check(CLI::ExistingFile);
  run->add_option("--out", args->out, "Output folder (default: the deck's output.dir)");
  run->add_option("--threads", args->threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);
  run->add_option("--set", args->sets, "Override a deck value, e.g. --set solver.end_time='5 us'");
  run->add_flag("--quiet", args->quiet, "Print only errors");
  run->add_option("--restart", args->restart,
                  "Continue the run in this folder from its checkpoint (docs/running.md); --set may change "
                  "solver.end_time, solver.max_steps, output.every and checkpoint intervals");
  run->callback([args] { runDeck(*args); });

  auto check_args = std::make_shared<RunArguments>();
  CLI::App* check = app.add_subcommand("check", "Validate a deck without running it");
  check->add_option("deck", check_args->deck, "YAML deck")->required()->check(CLI::ExistingFile);
  check->add_option("--set", check_args->sets, "Override a deck value");
  check->callback([check_args] { checkDeck(*check_args); });
}

}  // namespace kessler::app
