#pragma once
// Verification problems of the impact materials (whole runs).
#include "core/types.hpp"
#include "verify/problem.hpp"

#include <fmt/format.h>

namespace kessler::verify {

struct MieGruneisenRef {
  double rho0, c0, s;
};

struct FlyerPlateResult {
  double particle_velocity, shock_speed, pressure, energy;  // energy: specific internal energy, J/kg
  double reference_velocity, reference_shock_speed, reference_pressure, reference_energy;
  long steps, points;
  long eroded;  // points of the target eroded by eigenerosion: none may erode in a shock
};

FlyerPlateResult runFlyerPlate();
Outcome flyerPlate();

struct TaylorBarResult {
  double length = 0.0;            // final length, m
  double footprint_radius = 0.0;  // radius of the impact face, m
  // For the resolution study: the outermost material point within one mesh size of the wall, m.
  double point_footprint_radius = 0.0;
  long steps = 0, points = 0;
  // The time step at the start and the end, and what limits it at the end (the point of smallest
  // h0 lambda_min / c: its smallest principal stretch and position) against the smallest distance
  // between two nodes, for the resolution study (docs/validation.md).
  double dt_initial = 0.0, dt_final = 0.0;
  double min_stretch = 0.0, limiting_r = 0.0, limiting_z = 0.0, limiting_h0 = 0.0;
  double min_node_distance = 0.0;
};

// mesh_size in metres; cfl: the factor on the stable time step (otm::Settings::cfl);
// volume_averaging: otm::Settings::volume_averaging (the verifications keep the default, on).
TaylorBarResult runTaylorBar(double mesh_size, double cfl = 0.3, bool volume_averaging = true);
Outcome taylorBar();        // 0.8 mm (long)
Outcome taylorBarCoarse();  // 1 mm and 1.6 mm (CI)

}  // namespace kessler::verify

namespace kessler::verify {

struct GriffithResult {
  double failure_stress = 0.0;  // remote stress when the crack first grows, Pa (0: never)
  double reference = 0.0;
  long steps = 0, points = 0;
  double failure_time = 0.0, fail_time_reference = 0.0;  // s: when it failed; when sigma_ref is reached
  Vec3 first_eroded = Vec3::Zero();                      // m: where the crack first grew
};

struct GriffithCase {
  int cells_per_half_crack = 4;  // resolution a/h
  int thickness_cells = 2;       // points through the thickness
  double erosion_radius = 2.0;   // eps / h (otm::Settings::erosion_radius)
  bool crack_visibility = true;  // otm::Settings::crack_visibility
};
GriffithResult runGriffith(const GriffithCase& c);
Outcome griffith();

}  // namespace kessler::verify
