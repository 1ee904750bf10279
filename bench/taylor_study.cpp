// Resolution study of the copper Taylor bar (docs/validation.md): runs verify::runTaylorBar at
// each mesh size given in mm on the command line (`--cfl X` first changes the factor on the time
// step, default 0.3) and prints points, steps, wall time, final length and footprint radius. Not a
// test: the sizes near the 0.8 mm benchmark take minutes.
#include "core/error.hpp"
#include "verify/impact_problems.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  fmt::print("{:>8} {:>5} {:>7} {:>7} {:>9} {:>11} {:>11}\n", "mesh_mm", "cfl", "points", "steps", "wall_s",
             "length_mm", "radius_mm");
  double cfl = 0.3;
  int first = 1;
  if (argc > 2 && std::string(argv[1]) == "--cfl") {
    cfl = std::atof(argv[2]);
    first = 3;
  }
  for (int i = first; i < argc; ++i) {
    const double mesh = std::atof(argv[i]) * 1e-3;
    const auto start = std::chrono::steady_clock::now();
    kessler::verify::TaylorBarResult r;
    try {
      r = kessler::verify::runTaylorBar(mesh, cfl);
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
