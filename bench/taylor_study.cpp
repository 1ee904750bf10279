// Resolution study of the copper Taylor bar (docs/validation.md): runs verify::runTaylorBar at
// each mesh size given in mm on the command line and prints points, steps, wall time, final length
// and footprint radius. Options first: `--cfl X` changes the factor on the time step (default
// 0.3), `--no-volume-averaging` turns solver.otm.volume_averaging off, `--method sph` runs SPH
// (default otm). Not a test: the sizes near the
// 0.8 mm benchmark take minutes.
#include "core/error.hpp"
#include "verify/fixtures.hpp"
#include "verify/impact_problems.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  fmt::print("{:>8} {:>5} {:>7} {:>7} {:>9} {:>11} {:>11}\n", "mesh_mm", "cfl", "points", "steps", "wall_s",
             "length_mm", "radius_mm");
  double cfl = 0.3;
  bool volume_averaging = true;
  int first = 1;
  for (;;) {
    if (argc > first + 1 && std::string(argv[first]) == "--cfl") {
      cfl = std::atof(argv[first + 1]);
      first += 2;
    } else if (argc > first + 1 && std::string(argv[first]) == "--method") {
      kessler::verify::useMethod(argv[first + 1]);
      first += 2;
    } else if (argc > first && std::string(argv[first]) == "--no-volume-averaging") {
      volume_averaging = false;
      first += 1;
    } else {
      break;
    }
  }
  if (!volume_averaging) fmt::print("volume averaging off\n");
  for (int i = first; i < argc; ++i) {
    const double mesh = std::atof(argv[i]) * 1e-3;
    const auto start = std::chrono::steady_clock::now();
    kessler::verify::TaylorBarResult r;
    try {
      r = kessler::verify::runTaylorBar(mesh, cfl, volume_averaging);
    } catch (const kessler::NumericalError& e) {  // a failed size says why, and the study goes on
      fmt::print("{:8.3f} {:5.2f} stopped: {}\n", 1e3 * mesh, cfl, e.what());
      std::fflush(stdout);
      continue;
    }
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
    fmt::print("{:8.3f} {:5.2f} {:7} {:7} {:9.1f} {:11.3f} {:11.3f}\n", 1e3 * mesh, cfl, r.points, r.steps,
               wall.count(), 1e3 * r.length, 1e3 * r.footprint_radius);
    fmt::print(
        "         dt {:.2f} -> {:.2f} ns; limiting point: lambda_min {:.3f}, h0 {:.3f} mm, r {:.2f} mm, z {:.2f} mm; "
        "closest nodes {:.3f} mm apart; outermost point within h of the wall at r {:.3f} mm\n",
        1e9 * r.dt_initial, 1e9 * r.dt_final, r.min_stretch, 1e3 * r.limiting_h0, 1e3 * r.limiting_r,
        1e3 * r.limiting_z, 1e3 * r.min_node_distance, 1e3 * r.point_footprint_radius);
    std::fflush(stdout);
  }
  return 0;
}
