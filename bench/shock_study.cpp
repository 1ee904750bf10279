// Shock study (docs/validation.md): the hugoniot-3d problem (or with `--noh`, the noh-3d problem at the
// given mesh sizes of the unit sphere) (symmetric Al 6061-T6 impact at 6.18 km/s on
// unstructured points) at the mesh sizes given in mm, with its plateau measurements and, with
// `--profile`, the target's slab profile at the end. Options first: `--two-bodies` (a flyer onto a target
// instead of one slab whose halves meet), `--no-volume-averaging`,
// `--stabilisation A` (OtmOptions::volume_stabilisation), `--relaxation K` (OtmOptions::volume_relaxation),
// `--contact-distance D`, `--cfl X`, `--method otm|sph|rkpm`, `--lateral-lock` (every point
// held laterally, not only the rollers), `--noh-end T` (the Noh problem's end time, 0.6 by default; the
// shock is then at T/3), `--alpha-min A` and `--alpha-max A` (SPH's viscosity switch's bounds,
// SphOptions::viscosity_min and viscosity_max), `--gas` (the planar Noh problem on the same column:
// Hugoniot3dOptions::gas; pressures then in Pa, not GPa). Not a test.
#include "core/error.hpp"
#include "verify/fixtures.hpp"
#include "verify/impact_problems.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  kessler::MethodSettings settings;
  bool profile = false, noh = false;
  kessler::verify::Hugoniot3dOptions options;
  double noh_end = 0.6;
  int first = 1;
  for (; first < argc; ++first) {
    const std::string option = argv[first];
    if (option == "--profile") {
      profile = true;
    } else if (option == "--noh") {
      noh = true;
    } else if (option == "--gas") {
      options.gas = true;
    } else if (option == "--noh-end" && first + 1 < argc) {
      noh_end = std::atof(argv[++first]);
    } else if (option == "--method" && first + 1 < argc) {
      kessler::verify::useMethod(argv[++first]);
    } else if (option == "--lateral-lock") {
      options.lateral_lock = true;
    } else if (option == "--two-bodies") {
      options.one_body = false;
    } else if (option == "--no-volume-averaging") {
      settings.otm.volume_averaging = false;
    } else if (option == "--stabilisation" && first + 1 < argc) {
      settings.otm.volume_stabilisation = std::atof(argv[++first]);
    } else if (option == "--relaxation" && first + 1 < argc) {
      settings.otm.volume_relaxation = std::atof(argv[++first]);
    } else if (option == "--contact-distance" && first + 1 < argc) {
      settings.otm.contact_distance = std::atof(argv[++first]);
    } else if (option == "--alpha-min" && first + 1 < argc) {
      settings.sph.viscosity_min = std::atof(argv[++first]);
    } else if (option == "--alpha-max" && first + 1 < argc) {
      settings.sph.viscosity_max = std::atof(argv[++first]);
    } else if (option == "--cfl" && first + 1 < argc) {
      settings.solver.cfl = std::atof(argv[++first]);
    } else {
      break;
    }
  }
  for (int i = first; noh && i < argc; ++i) {
    const double mesh = std::atof(argv[i]);
    kessler::verify::NohResult r;
    try {
      r = kessler::verify::runNoh3d(mesh, settings, noh_end);
    } catch (const kessler::NumericalError& e) {
      fmt::print("Noh, mesh {}: stopped: {}\n", mesh, e.what());
      continue;
    }
    fmt::print(
        "Noh, mesh {}: {} points, {} steps; plateau density {:.2f} ({:+.1f}%; {:.2f} over the space it fills), "
        "centre {:.2f}, shock at {:.4f} (vs {:.3f}), energy {:+.2f}%\n",
        mesh, r.points, r.steps, r.density, 100 * (r.density / r.reference_density - 1), r.packed_density,
        r.centre_density, r.shock_radius, r.reference_shock_radius, 100 * r.energy_error);
    if (!profile) continue;
    fmt::print("{:>7} {:>7} {:>7} {:>7} {:>7}\n", "r", "rho", "v_r", "e", "packed");
    for (const kessler::verify::Shell& s : r.profile)
      fmt::print("{:7.4f} {:7.2f} {:7.3f} {:7.3f} {:7.2f}\n", s.radius, s.density, s.radial_velocity, s.energy,
                 s.packed_density);
  }
  for (int i = first; !noh && i < argc; ++i) {
    const double mesh = std::atof(argv[i]) * 1e-3;
    kessler::verify::Hugoniot3dResult r;
    try {
      r = kessler::verify::runHugoniot3d(mesh, settings, options);
    } catch (const kessler::NumericalError& e) {
      fmt::print("{:.3f} mm stopped: {}\n", 1e3 * mesh, e.what());
      continue;
    }
    // Aluminium in GPa, MJ/kg and m/s to the metre per second; the gas in Pa, J/kg and m/s to 1e-4.
    const double rho0 = r.reference_density0, p_unit = options.gas ? 1.0 : 1e-9, e_unit = options.gas ? 1.0 : 1e-6;
    const int digits = options.gas ? 4 : 0;
    const char* pa = options.gas ? "Pa" : "GPa";
    fmt::print(
        "mesh {:.3f} mm: {} points, {} steps; rho {:.4f} rho0 ({:+.2f}%; by the space {:.4f}, {:+.2f}%), "
        "densest {:.4f} ({:+.2f}%), P {:.4g} {} ({:+.2f}%), up {:.{}f} m/s ({:+.2f}%), Us {:.{}f} m/s ({:+.2f}%), "
        "largest plateau pressure {:.4g} {}, energy {:+.3f}%\n",
        1e3 * mesh, r.points, r.steps, r.density / rho0, 100 * (r.density / r.reference_density - 1),
        r.packed_density / rho0, 100 * (r.packed_density / r.reference_density - 1), r.max_density / rho0,
        100 * (r.max_density / r.reference_density - 1), p_unit * r.pressure, pa,
        100 * (r.pressure / r.reference_pressure - 1), r.particle_velocity, digits,
        100 * (r.particle_velocity / r.reference_velocity - 1), r.shock_speed, digits,
        100 * (r.shock_speed / r.reference_shock_speed - 1), p_unit * r.max_pressure, pa, 100 * r.energy_change);
    if (!profile) continue;
    fmt::print("{:>8} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7}\n", "z_mm", "v", "rho", "max",
               options.gas ? "p" : "p_GPa", options.gas ? "q" : "q_GPa", options.gas ? "e" : "e_MJkg",
               options.gas ? "S" : "S_GPa");
    for (const kessler::verify::Slab& s : r.profile)
      if (s.density > 0.0 && std::abs(s.velocity) > 0.01 * r.reference_velocity)
        fmt::print("{:8.2f} {:7.{}f} {:7.4f} {:7.4f} {:7.3f} {:7.3f} {:7.3f} {:7.3f}\n", 1e3 * s.z, s.velocity,
                   options.gas ? 3 : 0, s.density / rho0, s.max_density / rho0, p_unit * s.pressure,
                   p_unit * s.viscous_pressure, e_unit * s.energy, p_unit * s.stabilisation_pressure);
  }
  return 0;
}
