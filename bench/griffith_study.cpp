// Resolution study of the griffith verification (docs/validation.md): runs verify::runGriffith
// for each a/h given on the command line and prints points, steps, wall time and the failure
// stress against Griffith's. `--thickness N` (points through the thickness, default 2) and
// `--eps X` (erosion radius in h, default 2), `--visibility on|off` (default on; OTM's option) and
// `--method otm|sph|rkpm` (default otm) come first. Not a test: a/h = 8 takes minutes.
#include "verify/fixtures.hpp"
#include "verify/impact_problems.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  kessler::verify::GriffithCase c;
  int i = 1;
  for (; i + 1 < argc; i += 2) {
    const std::string option = argv[i];
    if (option == "--thickness")
      c.thickness_cells = std::atoi(argv[i + 1]);
    else if (option == "--visibility")
      c.crack_visibility = std::string(argv[i + 1]) == "on";
    else if (option == "--eps")
      c.erosion_radius = std::atof(argv[i + 1]);
    else if (option == "--method")
      kessler::verify::useMethod(argv[i + 1]);
    else
      break;
  }
  fmt::print("{:>5} {:>9} {:>5} {:>7} {:>7} {:>8} {:>10} {:>10} {:>7}\n", "a/h", "thickness", "eps", "points", "steps",
             "wall_s", "sigma_MPa", "ref_MPa", "error");
  for (; i < argc; ++i) {
    c.cells_per_half_crack = std::atoi(argv[i]);
    const auto start = std::chrono::steady_clock::now();
    const kessler::verify::GriffithResult r = kessler::verify::runGriffith(c);
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
    fmt::print("{:5} {:9} {:5.2f} {:7} {:7} {:8.1f} {:10.3f} {:10.3f} {:+6.2f}%\n", c.cells_per_half_crack,
               c.thickness_cells, c.erosion_radius, r.points, r.steps, wall.count(), 1e-6 * r.failure_stress,
               1e-6 * r.reference, 100 * (r.failure_stress / r.reference - 1));
    fmt::print("      failed at t = {:.3f} t_ref, first eroded at ({:.3f}, {:.3f}, {:.3f}) mm\n",
               r.failure_time / r.fail_time_reference, 1e3 * r.first_eroded[0], 1e3 * r.first_eroded[1],
               1e3 * r.first_eroded[2]);
    std::fflush(stdout);
  }
  return 0;
}
