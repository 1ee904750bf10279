#pragma once
// Verification problems of the impact materials (whole runs).
#include "core/types.hpp"
#include "solver/common/settings.hpp"
#include "verify/problem.hpp"

#include <fmt/format.h>

#include <vector>

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

struct SpallResult {
  double speed = 0.0;                  // impact speed, m/s
  double cell = 0.0;                   // the column's cell, m
  double plane = 0.0;                  // initial height above the impact face where the release fronts meet, m
  double acoustic_plane = 0.0;         // ... in the acoustic picture (delta), m
  long failed = 0;                     // failed target points at the end
  long first_failed = 0;               // those of the first spall (failed within a cell's crossing time of the first)
  double first_time = 0.0;             // when the first failed, s
  double first_height = 0.0;           // mean initial height of the first spall's points, m
  double lowest = 0.0, highest = 0.0;  // and their extent, m
  long flyer_failed = 0;
  long points = 0, steps = 0;
};

// The impact speed whose shock pressure equals Al 6061-T6's spall strength (acoustic estimate).
double spallThresholdSpeed();
// speed: the flyer's; cell: the column's cell (delta = 2 mm, a whole number of cells).
SpallResult runSpall(double speed, double cell);
Outcome spall();

// One slab of the target at the end of hugoniot-3d, mass-weighted (for the shock study).
struct Slab {
  double z, velocity, density, max_density, pressure, viscous_pressure, energy;  // SI
  double stabilisation_pressure = 0.0;  // mass-weighted mean of the volume stabilisation's pressure, Pa
};

struct Hugoniot3dResult {
  double particle_velocity, shock_speed, pressure, density;  // plateau averages (pressure without viscosity)
  double max_density;                                        // the densest point of the plateau, kg/m^3
  double max_pressure;  // the largest pressure of a plateau point, viscosity included, Pa
  // The plateau's density by the space it fills, not by its points' volumes: rho0 over the
  // least-squares slope of the points' heights z against their initial heights z0.
  double packed_density;
  double reference_velocity, reference_shock_speed, reference_pressure, reference_density, reference_density0;
  long steps, points, plateau_points;
  double energy_change;       // relative change of the total energy over the run
  std::vector<Slab> profile;  // slabs of h/2 along the target at the end
};

struct Shell {
  double radius, density, radial_velocity, energy;  // mass-weighted over the shell
  // The shell's mass over the space it spans (the octant's shell).
  double packed_density;
};

struct NohResult {
  double density = 0.0;  // mass-weighted density of the plateau 0.25 r_s < r < 0.75 r_s
  // The plateau's mass over the space it fills (the shell 0.25 r_s < r < 0.75 r_s of the octant),
  // not over its particles' volumes: where the two differ, the volumes no longer tile the space.
  double packed_density = 0.0;
  double centre_density = 0.0;  // within 0.25 r_s (wall heating)
  double shock_radius = 0.0;    // where the radial velocity crosses -1/2
  double reference_density = 0.0, reference_shock_radius = 0.0;
  double initial_energy = 0.0;  // kinetic, J
  double energy_error = 0.0;    // relative change of the total energy over the run
  long steps = 0, points = 0;
  std::vector<Shell> profile;  // 80 shells out to 2 r_s or r = 0.4, whichever is further, at the end
};

// mesh_size: the Gmsh target edge length of the unit sphere; settings: the solver's (its end_time is
// replaced by end_time, when the problem is measured: the shock is then at end_time / 3).
NohResult runNoh3d(double mesh_size, MethodSettings settings = {}, double end_time = 0.6);
Outcome noh3d();

// Variants of the hugoniot-3d problem for the shock study (bench/shock_study.cpp).
struct Hugoniot3dOptions {
  // One slab whose halves meet at the impact speed (no contact between bodies) instead of a flyer
  // striking a target.
  bool one_body = true;
  // Every point keeps a zero lateral velocity, not only those on the rollers (the exact solution's
  // lateral velocity is zero everywhere).
  bool lateral_lock = false;
  // The planar Noh problem instead of aluminium (Noh 1987): the library's cold ideal gas (gamma 5/3,
  // rho0 1 kg/m^3), the halves meeting at 2 m/s. Behind the shock rho = 4 rho0, up = 1 m/s,
  // Us = 4/3 m/s ahead of the gas, P = 4/3 Pa and e = 1/2 J/kg: the strong-shock Hugoniot is
  // Us = (gamma + 1)/2 up, the linear one with c0 = 0 and s = (gamma + 1)/2.
  bool gas = false;
};

// mesh_size: the Gmsh target edge length, m; settings: the solver's (end_time is set here).
Hugoniot3dResult runHugoniot3d(double mesh_size, MethodSettings settings = {}, Hugoniot3dOptions options = {});
Outcome hugoniot3d();

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

// mesh_size in metres; cfl: the factor on the stable time step (SolverSettings::cfl);
// volume_averaging: OtmOptions::volume_averaging (the verifications keep the default, on).
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
  double erosion_radius = 2.0;   // eps / h (SolverSettings::erosion_radius)
  bool crack_visibility = true;  // OtmOptions::crack_visibility
};
GriffithResult runGriffith(const GriffithCase& c);
Outcome griffith();

}  // namespace kessler::verify
