#pragma once
// Settings of the OTM integrator, filled from the deck (or by a verification problem).
#include "solver/common/settings.hpp"
#include "solver/common/walls.hpp"

#include <vector>

namespace kessler::otm {

// The deck's keys (the common ones and `solver.otm`, solver/common/settings.hpp) and what only
// the verification problems set.
struct Settings : SolverSettings, OtmOptions {
  // The volume averaging's stabilisation: a pressure -alpha rho c^2 d on the volume strain d that
  // the averaging took away (PointStore::volume_defect), alpha times the point's longitudinal
  // modulus, added to each point's own stress in the forces. With alpha = 1 the nodes feel each
  // point's whole volumetric stiffness (the averaged pressure on what the average keeps, the
  // stabilisation on what it takes away), so the averaged update has no zero-energy mode (the
  // crushed axis of a plastic Taylor bar) and no soft one, while the state the material sees
  // (density, pressure, heating) stays the patch average (docs/theory.md §4).
  double volume_stabilisation = 1.0;
  // The defect of an intact point relaxes with the time constant of this many wave transits of its
  // spacing, tau = k h / c (0: never), the energy it stored becomes heat, and the stored energy
  // follows the stiffness (docs/theory.md §4).
  double volume_relaxation = 10.0;
  std::vector<RigidWall> walls;
  // Eigenerosion (Pandolfi & Ortiz 2012; docs/theory.md §8): radius of the ball B_eps as a
  // multiple of the point spacing h.
  double erosion_radius = 2.0;
};

// OTM's settings for a deck's solver section.
inline Settings settingsFor(const SolverSettings& common, const OtmOptions& own) {
  Settings s;
  static_cast<SolverSettings&>(s) = common;
  static_cast<OtmOptions&>(s) = own;
  return s;
}

}  // namespace kessler::otm
