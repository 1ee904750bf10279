#pragma once
// Tabulation of an equation of state on a (rho, T) grid as a SESAME table 301, the writer behind
// `kessler eos-table` (docs/eos.md). Analytic models have no temperature, so the table uses the
// caloric mapping e(rho, T) = c_v (T - T0) at every density: P(rho_i, T_j) is the model's
// pressure at (rho_i, c_v (T_j - T0)). The table therefore covers the same energy range
// [c_v (T_min - T0), c_v (T_max - T0)] at every density, and along each isochore the table is
// exact wherever the model is linear in e (Mie-Gruneisen, polynomial).
#include "material/eos/eos.hpp"

namespace kessler::eos {

struct TableGrid {
  double rho_min = 0.0;  // kg/m^3; densities are spaced geometrically from rho_min to rho_max
  double rho_max = 0.0;
  int n_rho = 100;
  double t_min = 0.0;  // K; temperatures are spaced evenly from t_min to t_max
  double t_max = 0.0;
  int n_t = 100;
  void check() const;  // throws kessler::InputError naming the bad entry
};

// Throws kessler::InputError for a bad grid, specific heat or T0, or an ideal-gas EOS (not
// tabulated, docs/eos.md), and the model's kessler::NumericalError for a grid point it cannot
// evaluate (e.g. beyond the Mie-Gruneisen compression limit).
SesameTable tabulate(const Eos& eos, const TableGrid& grid, double specific_heat, double temperature0,
                     int material_id = 1);

}  // namespace kessler::eos
