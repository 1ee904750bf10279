#pragma once
// OTM as a Method (solver/common/method.hpp): the model, its integrator and its health checks.
#include "solver/common/method.hpp"
#include "solver/otm/diagnostics.hpp"
#include "solver/otm/integrator.hpp"
#include "solver/otm/model.hpp"
#include "solver/otm/settings.hpp"

namespace kessler::otm {

class OtmMethod final : public Method {
 public:
  OtmMethod(Model model, const Settings& settings)
      : model_(std::move(model)), integrator_(model_, settings), diagnostics_(settings) {}
  OtmMethod(const OtmMethod&) = delete;
  OtmMethod& operator=(const OtmMethod&) = delete;

  const char* name() const override { return "otm"; }
  void initialise() override { integrator_.initialise(); }
  void step() override { integrator_.step(); }
  void check(double initial_total_energy) override;
  bool finished() const override { return integrator_.finished(); }
  double endTime() const override { return integrator_.settings().end_time; }
  Clock clock() const override;
  Energies energies() const override { return integrator_.energies(); }
  const PhaseTimers& timers() const override { return integrator_.timers(); }
  const ParticleState& state() const override { return model_; }
  const NodeStore& nodes() const override { return model_.nodes; }
  std::vector<std::pair<std::string, double>> sizes() const override;
  std::vector<std::string> notes() const override;
  void save(StateWriter& out) const override;
  void load(const StateReader& in) override;

  // OTM's own state, for its checkpoint and its verification problems.
  const Model& model() const { return model_; }
  Integrator& integrator() { return integrator_; }
  const Integrator& integrator() const { return integrator_; }

 private:
  Model model_;
  Integrator integrator_;  // holds a reference to model_
  Diagnostics diagnostics_;
};

}  // namespace kessler::otm
