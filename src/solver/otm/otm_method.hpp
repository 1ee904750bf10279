#pragma once
// OTM as a Method (solver/common/method.hpp): the model, its integrator and its health checks.
#include "solver/common/method.hpp"
#include "solver/common/plane_histories.hpp"
#include "solver/common/problem.hpp"
#include "solver/otm/diagnostics.hpp"
#include "solver/otm/distribution.hpp"
#include "solver/otm/integrator.hpp"
#include "solver/otm/model.hpp"
#include "solver/otm/settings.hpp"

#include <memory>
#include <optional>

namespace kessler::otm {

class OtmMethod final : public Method {
 public:
  // With `ranks` of more than one process, this rank runs its part of the model (which every rank
  // built alike; docs/parallel.md).
  OtmMethod(Model model, const Settings& settings, const parallel::Communicator* ranks = nullptr);
  // For a problem's model (buildModel): its settings, walls and velocity histories.
  OtmMethod(Model model, const Problem& problem, const parallel::Communicator* ranks = nullptr);
  OtmMethod(const OtmMethod&) = delete;
  OtmMethod& operator=(const OtmMethod&) = delete;

  const char* name() const override { return "otm"; }
  void initialise() override;
  void step() override;
  void check(double initial_total_energy) override;
  bool finished() const override { return integrator_.finished(); }
  double endTime() const override { return integrator_.settings().end_time; }
  Clock clock() const override;
  Energies energies() const override { return integrator_.energies(); }
  const PhaseTimers& timers() const override { return report_ ? report_->timers : integrator_.timers(); }
  const ParticleState& state() const override { return model_; }
  NodeCloud nodes() const override { return model_.nodes.cloud(); }
  std::vector<std::pair<std::string, double>> sizes() const override;
  std::vector<std::string> notes() const override;
  double stepLength(LocalIndex p) const override { return otm::stepLength(model_, p); }
  double addedPressure(LocalIndex p) const override;
  void save(StateWriter& out) const override;
  void load(const StateReader& in) override;
  bool distributed() const override { return distribution_ != nullptr; }
  std::unique_ptr<Method> gathered(bool for_checkpoint) const override;

  // OTM's own state, for its checkpoint and its verification problems.
  const Model& model() const { return model_; }
  Integrator& integrator() { return integrator_; }
  const Integrator& integrator() const { return integrator_; }

 private:
  // A plane whose nodes' prescribed velocity follows a history (PlaneConstraint::history).
  // The histories' nodes in the store's current order (after the Morton sort or a restart).
  void locateHistories();

  // The sizes and notes of the whole run (collective in a distributed run).
  std::vector<std::pair<std::string, double>> rankSizes() const;
  std::vector<std::string> tornNotes(LocalIndex torn, double mass) const;

  Model model_;
  std::unique_ptr<Distribution> distribution_;  // a distributed run's; before the integrator, which holds it
  Integrator integrator_;                       // holds a reference to model_
  Diagnostics diagnostics_;
  PlaneHistories histories_;
  std::optional<GatheredReport> report_;  // a gathered method's
};

}  // namespace kessler::otm
