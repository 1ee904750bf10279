#include "app/methods.hpp"

#include "app/run_folder.hpp"
#include "solver/otm/otm_method.hpp"
#include "solver/otm/setup.hpp"

namespace kessler::app {

namespace {

// The bodies to mesh, each with its material from deckMaterials().
std::vector<otm::BodySetup> bodySetups(const io::RunConfig& config) {
  const std::vector<MaterialPtr> materials = deckMaterials(config);
  std::vector<otm::BodySetup> bodies;
  for (const io::BodyConfig& b : config.bodies)
    bodies.push_back({b.name, materials.at(static_cast<std::size_t>(b.material)), b.mesh, b.velocity, b.fixed});
  return bodies;
}

}  // namespace

std::unique_ptr<Method> buildMethod(const io::RunConfig& config) {
  return std::make_unique<otm::OtmMethod>(otm::buildModel(bodySetups(config), config.symmetry_axes),
                                          otm::settingsFor(config.solver, config.otm));
}

std::unique_ptr<Method> restoreMethod(const io::RunConfig& config, const std::filesystem::path& file,
                                      io::RunLoopState& loop) {
  io::Restored restored =
      io::readCheckpoint(file, deckMaterials(config), [&](ParticleState&& state) -> std::unique_ptr<Method> {
        otm::Model model;
        static_cast<ParticleState&>(model) = std::move(state);
        return std::make_unique<otm::OtmMethod>(std::move(model), otm::settingsFor(config.solver, config.otm));
      });
  loop = std::move(restored.loop);
  return std::move(restored.method);
}

}  // namespace kessler::app
