#pragma once
// SPH as a Method (solver/common/method.hpp): its particles, its integrator and its health checks.
#include "solver/common/method.hpp"
#include "solver/common/plane_histories.hpp"
#include "solver/common/point_diagnostics.hpp"
#include "solver/common/problem.hpp"
#include "solver/sph/integrator.hpp"
#include "solver/sph/model.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace kessler::sph {

// SPH's settings for a problem.
Settings settingsFor(const Problem& problem);

class SphMethod final : public Method {
 public:
  // With `ranks` of more than one process, this rank runs its part of the model (which every rank
  // built alike; docs/parallel.md, "SPH across ranks").
  SphMethod(Model model, const Settings& settings, const parallel::Communicator* ranks = nullptr);
  // A new run of `problem`: its planes' velocity histories are taken up (a restored run, built
  // from its settings alone, does not take them up, as OTM's).
  SphMethod(Model model, const Problem& problem, const parallel::Communicator* ranks = nullptr);
  SphMethod(const SphMethod&) = delete;
  SphMethod& operator=(const SphMethod&) = delete;

  const char* name() const override { return "sph"; }
  void initialise() override;
  void step() override;
  void check(double initial_total_energy) override;
  bool finished() const override { return integrator_.finished(); }
  double endTime() const override { return integrator_.settings().solver.end_time; }
  Clock clock() const override { return integrator_.clock(); }
  Energies energies() const override { return integrator_.energies(); }
  const PhaseTimers& timers() const override { return report_ ? report_->timers : integrator_.timers(); }
  const ParticleState& state() const override { return model_; }
  // The reconstructed elements' nodes (solver/sph/reconstruction.hpp).
  NodeCloud nodes() const override { return integrator_.nodes(); }
  std::vector<std::pair<std::string, double>> sizes() const override;
  std::vector<std::string> notes() const override;
  double stepLength(LocalIndex p) const override { return integrator_.smoothingLength(p); }
  void save(StateWriter& out) const override;
  void load(const StateReader& in) override;
  bool distributed() const override { return distribution_ != nullptr; }
  std::unique_ptr<Method> gathered(bool for_checkpoint) const override;

  const Model& model() const { return model_; }
  const Integrator& integrator() const { return integrator_; }

 private:
  // The histories' particles in the store's current order (a distributed run's move between ranks).
  void locateHistories();

  Model model_;
  std::unique_ptr<Distribution> distribution_;  // a distributed run's; before the integrator, which holds it
  Integrator integrator_;                       // holds a reference to model_
  PointDiagnostics diagnostics_;
  PlaneHistories histories_;
  long located_ = -1;                     // the distribution's layout the histories were located in
  std::optional<GatheredReport> report_;  // a gathered method's
};

}  // namespace kessler::sph
