// Spall study (docs/validation.md): the spall verification's column at one cell size (mm) and the
// given impact speeds (m/s): where the first spall forms against the plane where the release fronts
// meet, and how much fails. `kessler_spall_study 0.1 200 250 493`. Not a test.
#include "core/error.hpp"
#include "verify/impact_problems.hpp"

#include <fmt/format.h>

#include <cstdlib>

int main(int argc, char** argv) {
  if (argc < 3) {
    fmt::print(stderr, "usage: kessler_spall_study CELL_MM SPEED_M_PER_S...\n");
    return 2;
  }
  const double cell = std::atof(argv[1]) * 1e-3;
  fmt::print("cell {:.3f} mm; acoustic threshold {:.0f} m/s\n", 1e3 * cell, kessler::verify::spallThresholdSpeed());
  for (int i = 2; i < argc; ++i) {
    const double speed = std::atof(argv[i]);
    try {
      const kessler::verify::SpallResult r = kessler::verify::runSpall(speed, cell);
      if (r.failed == 0) {
        fmt::print("{:6.0f} m/s: no spall ({} flyer points failed)\n", speed, r.flyer_failed);
        continue;
      }
      fmt::print(
          "{:6.0f} m/s: first spall at {:.3f} us, {} points at {:.3f} to {:.3f} mm (mean {:.3f}); release fronts meet "
          "at {:.3f} mm, acoustic {:.3f}; {} target and {} flyer points failed in all\n",
          speed, 1e6 * r.first_time, r.first_failed, 1e3 * r.lowest, 1e3 * r.highest, 1e3 * r.first_height,
          1e3 * r.plane, 1e3 * r.acoustic_plane, r.failed, r.flyer_failed);
    } catch (const kessler::NumericalError& e) {
      fmt::print("{:6.0f} m/s: stopped: {}\n", speed, e.what());
    }
  }
  return 0;
}
