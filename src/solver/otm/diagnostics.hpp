#pragma once
// Health checks the run loop calls after every step (docs/running.md, "When a run fails"). A
// numerical failure must stop the run with a diagnosis, never go on computing garbage:
//   - a non-finite node position or velocity; a non-finite point position, velocity, stress or
//     specific energy; a collapsed or non-finite point volume;
//   - the time step collapsing below Settings::min_dt_fraction of the initial step;
//   - the total (kinetic + internal) energy exceeding (1 + Settings::max_energy_growth) times the
//     reference energy (the initial total energy), each point's internal energy counted by its size
//     (a spurious source that the compatible energy update balances cools a point below zero).
// Inverted points (det dF <= 0) and failed LME solves are caught where they happen, inside the
// integrator step; their messages have the same form. Each failure throws NumericalError:
//   step 812, t = 3.21e-06 s: material point 4711 of body 'plate' at (1, 2, 3) m: <quantity> = <value>
//
// The checks are O(N) passes with OpenMP reductions that give the same answer (the lowest failing
// index, block sums in a fixed order) for any thread count, and allocate nothing after the first
// call.
#include "solver/otm/model.hpp"
#include "solver/otm/settings.hpp"

#include <vector>

namespace kessler::otm {

struct StepInfo {
  long step = 0;            // steps taken
  double time = 0.0;        // s
  double dt_next = 0.0;     // the step about to be taken
  double dt_initial = 0.0;  // the first step of the run
};

class Diagnostics {
 public:
  explicit Diagnostics(const Settings& settings) : settings_(settings) {}

  // `reference_energy`: the total energy the run started with, J. The energy check is skipped
  // when it is not positive, or when a node has a non-zero prescribed velocity (a piston does
  // work that this check does not account).
  void check(const Model& model, const StepInfo& at, double reference_energy);

  // Total energy of the last check(), J.
  double lastEnergy() const { return energy_; }

 private:
  void checkNodes(const Model& model, const StepInfo& at) const;
  void checkPoints(const Model& model, const StepInfo& at);
  void checkTimeStep(const Model& model, const StepInfo& at) const;
  void checkEnergy(const Model& model, const StepInfo& at, double reference_energy) const;

  Settings settings_;
  std::vector<double> block_energy_;  // per fixed block of points, summed in order
  double energy_ = 0.0;
};

// "step 812, t = 3.21e-06 s: material point 4711 of body 'plate' at (x, y, z) m: <what>"
std::string describePoint(const Model& model, const StepInfo& at, LocalIndex p, const std::string& what);
std::string describeNode(const Model& model, const StepInfo& at, LocalIndex a, const std::string& what);

}  // namespace kessler::otm
