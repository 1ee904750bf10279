#pragma once
// RKPM as a Method (solver/common/method.hpp): its particles, its integrator and its health checks.
// It runs on one process, each body on its own kernels; bodies meet through the sliding contact
// (docs/theory.md §12).
#include "solver/common/method.hpp"
#include "solver/common/plane_histories.hpp"
#include "solver/common/point_diagnostics.hpp"
#include "solver/common/problem.hpp"
#include "solver/rkpm/integrator.hpp"
#include "solver/rkpm/model.hpp"

#include <vector>

namespace kessler::rkpm {

Settings settingsFor(const Problem& problem);

class RkpmMethod final : public Method {
 public:
  explicit RkpmMethod(Model model, const Settings& settings);
  // A new run of `problem`: its planes' velocity histories are taken up (as OTM's and SPH's).
  RkpmMethod(Model model, const Problem& problem);
  RkpmMethod(const RkpmMethod&) = delete;
  RkpmMethod& operator=(const RkpmMethod&) = delete;

  const char* name() const override { return "rkpm"; }
  void initialise() override { integrator_.initialise(); }
  void step() override;
  void check(double initial_total_energy) override;
  bool finished() const override { return integrator_.finished(); }
  double endTime() const override { return integrator_.settings().solver.end_time; }
  Clock clock() const override { return integrator_.clock(); }
  Energies energies() const override { return integrator_.energies(); }
  const PhaseTimers& timers() const override { return integrator_.timers(); }
  const ParticleState& state() const override { return model_; }
  // The coefficients, as nodes: where the equations of motion carry the particles' kernels.
  NodeCloud nodes() const override;
  std::vector<std::pair<std::string, double>> sizes() const override {
    return {{"mean_neighbours", integrator_.meanNeighbours()}};
  }
  // The kernel updates made and refused, if any.
  std::vector<std::string> notes() const override;
  double stepLength(LocalIndex p) const override { return integrator_.stepLength(p); }
  void save(StateWriter& out) const override;
  void load(const StateReader& in) override;

  const Model& model() const { return model_; }
  const Integrator& integrator() const { return integrator_; }

 private:
  Model model_;
  Integrator integrator_;  // holds a reference to model_
  PointDiagnostics diagnostics_;
  PlaneHistories histories_;
};

}  // namespace kessler::rkpm
