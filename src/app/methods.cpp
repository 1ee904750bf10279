#include "app/methods.hpp"

#include "app/run_folder.hpp"
#include "core/error.hpp"
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

const otm::OtmMethod& asOtm(const Method& method) {
  const auto* otm = dynamic_cast<const otm::OtmMethod*>(&method);
  KESSLER_VERIFY(otm != nullptr, "checkpoint: no writer for the method '{}'", method.name());
  return *otm;
}

}  // namespace

std::unique_ptr<Method> buildMethod(const io::RunConfig& config) {
  return std::make_unique<otm::OtmMethod>(otm::buildModel(bodySetups(config), config.symmetry_axes), config.solver);
}

std::unique_ptr<Method> restoreMethod(const io::RunConfig& config, const std::filesystem::path& file,
                                      io::RunLoopState& loop) {
  otm::Model model;
  const io::Checkpoint c = io::readCheckpoint(file, model, deckMaterials(config));
  auto method = std::make_unique<otm::OtmMethod>(std::move(model), config.solver);
  method->integrator().restore(c.integrator);
  loop = c.loop;
  return method;
}

void saveMethod(const Method& method, const std::filesystem::path& file, const io::RunLoopState& loop) {
  const otm::OtmMethod& otm = asOtm(method);
  io::Checkpoint c;
  c.integrator = otm.integrator().state();
  c.loop = loop;
  io::writeCheckpoint(file, otm.model(), c);
}

}  // namespace kessler::app
