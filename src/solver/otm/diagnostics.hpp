#pragma once
// OTM's health checks after every step: the shared checks over the material points
// (solver/common/point_diagnostics.hpp) and those of its nodes (a non-finite node position or
// velocity). Inverted points (det dF <= 0) and failed LME solves are caught where they happen,
// inside the integrator step; their messages have the same form.
#include "solver/common/point_diagnostics.hpp"
#include "solver/otm/model.hpp"
#include "solver/otm/settings.hpp"

#include <string>

namespace kessler::otm {

class Diagnostics {
 public:
  explicit Diagnostics(const Settings& settings) : points_(settings) {}

  // `reference_energy`: the total energy the run started with, J. The energy check is skipped
  // when it is not positive, or when a node has a non-zero prescribed velocity (a piston does
  // work that this check does not account).
  // With `share` (a distributed run): the points its own, sums and `driven` over every rank.
  void check(const Model& model, const StepInfo& at, double reference_energy, const Share& share = {});

  // Total energy of the last check(), J.
  double lastEnergy() const { return points_.lastEnergy(); }

 private:
  PointDiagnostics points_;
};

// "step 812, t = 3.21e-06 s: node 17 of body 'plate' at (x, y, z) m: <what>"
std::string describeNode(const Model& model, const StepInfo& at, LocalIndex a, const std::string& what);

}  // namespace kessler::otm
