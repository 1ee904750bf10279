#pragma once
// Settings of the OTM integrator, filled from the deck (or by a verification problem).
#include "solver/common/settings.hpp"
#include "solver/common/walls.hpp"

#include <vector>

namespace kessler::otm {

// The deck's keys (the common ones and `solver.otm`, solver/common/settings.hpp) and the problem's
// rigid walls.
struct Settings : SolverSettings, OtmOptions {
  std::vector<RigidWall> walls;
};

// OTM's settings for a problem's.
inline Settings settingsFor(const MethodSettings& settings, std::vector<RigidWall> walls = {}) {
  Settings s;
  static_cast<SolverSettings&>(s) = settings.solver;
  static_cast<OtmOptions&>(s) = settings.otm;
  s.walls = std::move(walls);
  return s;
}

}  // namespace kessler::otm
