#pragma once
// Health checks over the material points, which every method calls after each step (docs/running.md,
// "When a run fails"). A numerical failure must stop the run with a diagnosis, never go on
// computing garbage:
//   - a non-finite point position, velocity, stress or specific energy; a collapsed or non-finite
//     point volume;
//   - the time step collapsing below SolverSettings::min_dt_fraction of the initial step;
//   - the total (kinetic + internal) energy exceeding (1 + SolverSettings::max_energy_growth) times
//     the reference energy (the initial total energy), each point's internal energy counted by its
//     size (a spurious source that the compatible energy update balances cools a point below zero).
// A method adds the checks of its own discretisation (OTM: its nodes, solver/otm/diagnostics.hpp).
// Each failure throws NumericalError:
//   step 812, t = 3.21e-06 s: material point 4711 of body 'plate' at (1, 2, 3) m: <quantity> = <value>
//
// The checks are O(N) passes with OpenMP reductions that give the same answer (the lowest failing
// index, exact sums) for any thread count, and allocate nothing.
#include "solver/common/own_sums.hpp"
#include "solver/common/particle_state.hpp"
#include "solver/common/settings.hpp"

#include <functional>
#include <string>
#include <vector>

namespace kessler {

struct StepInfo {
  long step = 0;            // steps taken
  double time = 0.0;        // s
  double dt_next = 0.0;     // the step about to be taken
  double dt_initial = 0.0;  // the first step of the run
};

// How a method's stable step measures a point: it is cfl times the smallest length(p) / c_p over
// the points that are not debris. origin(p) says how that length came about, for the message that
// names the point which collapsed the step.
struct StepLengthRule {
  std::function<double(LocalIndex)> length;
  std::function<std::string(LocalIndex)> origin;
};

class PointDiagnostics {
 public:
  explicit PointDiagnostics(const SolverSettings& settings) : settings_(settings) {}

  // `reference_energy`: the total energy the run started with, J. The energy check is skipped when
  // it is not positive, or when driven() says a prescribed non-zero velocity does work that this
  // check does not account (asked only when the energy has grown beyond its limit).
  // With `share` (a distributed run), the points checked and the energy summed are the rank's own,
  // over every rank.
  void check(const ParticleState& state, const StepInfo& at, double reference_energy, const StepLengthRule& rule,
             const std::function<bool()>& driven, const Share& share = {});

  // Total energy of the last check(), J.
  double lastEnergy() const { return energy_; }

 private:
  void checkPoints(const ParticleState& state, const StepInfo& at, const Share& share);
  void checkTimeStep(const ParticleState& state, const StepInfo& at, const StepLengthRule& rule) const;
  void checkEnergy(const ParticleState& state, const StepInfo& at, double reference_energy,
                   const std::function<bool()>& driven) const;

  SolverSettings settings_;
  double energy_ = 0.0;
};

// "step 812, t = 3.21e-06 s"
std::string describeStep(const StepInfo& at);
// "(x, y, z)" with 6 significant digits
std::string describeVector(const Vec3& v);
// "step 812, t = 3.21e-06 s: material point 4711 of body 'plate' at (x, y, z) m: <what>"
std::string describePoint(const ParticleState& state, const StepInfo& at, LocalIndex p, const std::string& what);

}  // namespace kessler
