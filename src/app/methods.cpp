#include "app/methods.hpp"

#include "app/run_folder.hpp"
#include "solver/methods.hpp"

namespace kessler::app {

Problem deckProblem(const io::RunConfig& config) {
  const std::vector<MaterialPtr> materials = deckMaterials(config);
  Problem problem;
  for (const io::BodyConfig& b : config.bodies) {
    BodySetup body;
    body.name = b.name;
    body.material = materials.at(static_cast<std::size_t>(b.material));
    body.mesh = b.mesh;
    body.velocity = b.velocity;
    body.fixed = b.fixed;
    problem.bodies.push_back(std::move(body));
  }
  problem.method = config.method;
  problem.symmetry_axes = config.symmetry_axes;
  problem.settings = MethodSettings{config.solver, config.otm, {}};
  return problem;
}

std::unique_ptr<Method> buildMethod(const io::RunConfig& config, const parallel::Communicator* ranks) {
  return makeMethod(deckProblem(config), ranks);
}

RestoredRun restoreMethod(const io::RunConfig& config, const std::filesystem::path& file,
                          const parallel::Communicator* ranks) {
  Problem problem = deckProblem(config);
  problem.bodies.clear();  // restored, not meshed
  RestoredRun run;
  io::Restored restored =
      io::readCheckpoint(file, deckMaterials(config), [&](ParticleState&& state) -> std::unique_ptr<Method> {
        run.points = state.points.owned;  // the whole run's, before a distributed method keeps its part
        return makeMethod(problem, std::move(state), ranks);
      });
  run.loop = std::move(restored.loop);
  run.method = std::move(restored.method);
  return run;
}

}  // namespace kessler::app
