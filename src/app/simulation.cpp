#include "app/simulation.hpp"

#include "app/progress.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/timer.hpp"
#include "io/deck.hpp"
#include "io/fields_writer.hpp"
#include "io/summary.hpp"
#include "solver/otm/integrator.hpp"
#include "solver/otm/setup.hpp"

#include <omp.h>

#include <cmath>

namespace kessler::app {

namespace {

std::vector<otm::BodySetup> bodySetups(const io::RunConfig& config) {
  std::vector<MaterialPtr> materials;
  for (const io::MaterialConfig& m : config.materials)
    materials.push_back(std::make_shared<NeoHookean>(m.name, m.neo_hookean));
  std::vector<otm::BodySetup> bodies;
  for (const io::BodyConfig& b : config.bodies)
    bodies.push_back({b.name, materials.at(static_cast<std::size_t>(b.material)), b.mesh, b.velocity, b.fixed});
  return bodies;
}

void printSummary(const otm::Integrator& integrator, const io::RunRecord& record, const std::filesystem::path& dir) {
  const otm::Energies& e0 = record.history.front().energies;
  const otm::Energies& e1 = record.history.back().energies;
  const double point_steps = static_cast<double>(integrator.steps()) * integrator.model().points.owned;
  log::info("{} steps to t = {:.4g} s in {:.1f} s wall ({:.3g} us per material-point step, {} threads)",
            integrator.steps(), integrator.time(), record.wall_seconds,
            point_steps > 0 ? 1e6 * record.wall_seconds / point_steps : 0.0, record.threads);
  log::info("energy: kinetic {:.6g} -> {:.6g} J, internal {:.6g} -> {:.6g} J, total {:.6g} -> {:.6g} J",
            e0.kinetic, e1.kinetic, e0.internal, e1.internal, e0.total(), e1.total());
  log::info("momentum: ({:.6g}, {:.6g}, {:.6g}) -> ({:.6g}, {:.6g}, {:.6g}) kg m/s", e0.momentum[0], e0.momentum[1],
            e0.momentum[2], e1.momentum[0], e1.momentum[1], e1.momentum[2]);
  log::info("results in {}/ (points.xdmf and nodes.xdmf open in ParaView; summary.json, history.csv)", dir.string());
}

}  // namespace

std::filesystem::path runSimulation(const io::RunConfig& config, const RunOptions& options) {
  if (options.threads > 0) omp_set_num_threads(options.threads);
  Stopwatch wall;
  const std::filesystem::path dir = config.output.dir;
  std::filesystem::create_directories(dir);
  io::writeResolvedDeck(config, dir / "deck.resolved.yaml");

  io::RunRecord record;
  record.title = config.title;
  record.deck = config.deck_path;
  record.threads = omp_get_max_threads();
  log::info("kessler: {} ({})", config.title.empty() ? "untitled run" : config.title, config.deck_path);

  Stopwatch meshing;
  log::info("meshing {} bodies", config.bodies.size());
  otm::Model model = otm::buildModel(bodySetups(config), config.symmetry_axes);
  record.extra_timings["meshing"] = meshing.seconds();
  log::info("model: {} material points, {} nodes; {} threads", model.points.owned, model.nodes.owned, record.threads);

  otm::Integrator integrator(model, config.solver);
  io::FieldWriter writer(dir);
  double output_seconds = 0.0;
  auto output = [&] {
    Stopwatch watch;
    writer.write(integrator.steps(), integrator.time(), model.nodes, model.points);
    io::writeHistory(dir / "history.csv", record.history);
    ++record.outputs;
    output_seconds += watch.seconds();
  };
  auto remember = [&] {
    record.history.push_back({integrator.steps(), integrator.time(), integrator.lastStep(), integrator.energies()});
  };
  auto finish = [&] {
    record.extra_timings["output"] = output_seconds;
    record.wall_seconds = wall.seconds();
    io::writeSummary(dir / "summary.json", record, integrator);
  };

  Progress progress(config.solver.end_time, model.points.owned, options.progress);
  try {
    integrator.initialise();
    remember();
    output();
    const double every = config.output.every > 0.0 ? config.output.every : config.solver.end_time;
    double next_output = every;
    while (!integrator.finished()) {
      if (config.solver.max_steps > 0 && integrator.steps() >= config.solver.max_steps) break;
      integrator.step();
      progress.update(integrator.steps(), integrator.time(), integrator.lastStep());
      if (integrator.time() >= next_output * (1.0 - 1e-9) || integrator.finished()) {
        remember();
        output();
        while (next_output <= integrator.time() * (1.0 + 1e-9)) next_output += every;
      }
    }
    if (record.history.back().step != integrator.steps()) {
      remember();
      output();
    }
  } catch (const NumericalError& e) {
    // Keep what the run had computed: the state at the failure, for inspection in ParaView.
    progress.finish(integrator.steps(), integrator.time(), integrator.lastStep());
    record.status = "failed";
    record.message = e.what();
    remember();
    output();
    finish();
    throw NumericalError(fmt::format("{}; the last state is in {}", e.what(), dir.string()));
  }
  progress.finish(integrator.steps(), integrator.time(), integrator.lastStep());
  finish();
  printSummary(integrator, record, dir);
  return dir;
}

}  // namespace kessler::app
