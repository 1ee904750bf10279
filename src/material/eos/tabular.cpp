// Tabular EOS: P and E are interpolated bilinearly in (rho, T) on the SESAME grid. Along an
// isochore both are then linear in T on each temperature interval, so E(rho, T) = e is inverted
// exactly and p(rho, e) is linear in e between the two bracketing temperatures; c^2 comes from
// the analytic derivatives of this interpolant. Bilinear interpolation keeps E monotone in T
// wherever the grid values are, never overshoots the table, and is exact for a Mie-Gruneisen
// table in tension; its error elsewhere is (drho)^2/8 |d2p/drho2| (docs/eos.md, "Tabular EOS").
#include "material/eos/tabular.hpp"
#include "core/error.hpp"

#include <algorithm>
#include <cmath>

namespace kessler::eos {

namespace {

void validate(const SesameTable& t) {
  const std::size_t nr = t.rho.size(), nt = t.temperature.size();
  auto fail = [](const std::string& what) { throw InputError("tabular EOS: " + what); };
  if (nr < 2 || nt < 2)
    fail(fmt::format("the table needs at least 2 densities and 2 temperatures (has {} x {})", nr, nt));
  if (t.pressure.size() != nr * nt || t.energy.size() != nr * nt)
    fail(fmt::format("{} pressures and {} energies for a {} x {} grid", t.pressure.size(), t.energy.size(), nr, nt));
  if (!(t.density > 0.0)) fail(fmt::format("reference density must be positive (got {})", t.density));
  for (std::size_t i = 0; i < nr; ++i)
    if (!(t.rho[i] >= 0.0 && std::isfinite(t.rho[i]) && (i == 0 || t.rho[i] > t.rho[i - 1])))
      fail(fmt::format("densities must be non-negative and increasing (rho[{}] = {})", i, t.rho[i]));
  for (std::size_t j = 0; j < nt; ++j)
    if (!(t.temperature[j] >= 0.0 && std::isfinite(t.temperature[j]) &&
          (j == 0 || t.temperature[j] > t.temperature[j - 1])))
      fail(fmt::format("temperatures must be non-negative and increasing (T[{}] = {})", j, t.temperature[j]));
  for (std::size_t k = 0; k < nr * nt; ++k)
    if (!std::isfinite(t.pressure[k]) || !std::isfinite(t.energy[k]))
      fail(fmt::format("non-finite pressure or energy at rho = {}, T = {}", t.rho[k % nr], t.temperature[k / nr]));
  for (std::size_t j = 1; j < nt; ++j)
    for (std::size_t i = 0; i < nr; ++i)
      if (!(t.energy[j * nr + i] > t.energy[(j - 1) * nr + i]))
        fail(fmt::format("energy does not increase with temperature at rho = {} kg/m^3 between T = {} K and {} K",
                         t.rho[i], t.temperature[j - 1], t.temperature[j]));
}

// The pressure scale for the c^2 floor: B0 when the table gives one, otherwise the largest
// |P| in the table.
double floorModulus(const SesameTable& t) {
  if (t.bulk_modulus > 0.0) return t.bulk_modulus;
  double largest = 0.0;
  for (double p : t.pressure) largest = std::max(largest, std::abs(p));
  return largest;
}

}  // namespace

Tabular::Tabular() : table_(std::make_shared<const SesameTable>()) {}

Tabular::Tabular(const TabularParameters& p)
    : Tabular(std::make_shared<const SesameTable>(readSesame(p.file, p.material_id))) {
  parameters_ = p;
}

Tabular::Tabular(std::shared_ptr<const SesameTable> table) : table_(std::move(table)) {
  if (!table_) throw InputError("tabular EOS: no table");
  validate(*table_);
  floor_modulus_ = floorModulus(*table_);
}

State Tabular::evaluate(double rho, double e) const {
  const SesameTable& t = *table_;
  const std::size_t nr = t.rho.size(), nt = t.temperature.size();
  if (nr < 2) throw NumericalError("tabular EOS: evaluated without a table (the EOS was default-built)");
  if (!(rho > 0.0 && std::isfinite(rho) && std::isfinite(e)))
    throw NumericalError(fmt::format("tabular EOS: invalid state rho = {} kg/m^3, e = {} J/kg", rho, e));
  auto outside = [&](double e_low, double e_high) {
    return NumericalError(fmt::format(
        "tabular EOS: state rho = {:.6g} kg/m^3, e = {:.6g} J/kg lies outside the table (rho in [{:.6g}, {:.6g}] "
        "kg/m^3; e in [{:.6g}, {:.6g}] J/kg at this density)",
        rho, e, t.rho.front(), t.rho.back(), e_low, e_high));
  };
  if (rho < t.rho.front() || rho > t.rho.back()) {
    const std::size_t edge = rho < t.rho.front() ? 0 : nr - 1;
    throw outside(t.energy[edge], t.energy[(nt - 1) * nr + edge]);
  }
  // Density cell [i, i+1] and the weight u of rho_{i+1}, with du/drho.
  const auto above = std::upper_bound(t.rho.begin(), t.rho.end(), rho);
  const std::size_t i = std::min(static_cast<std::size_t>(above - t.rho.begin()), nr - 1) - 1;
  const double r0 = t.rho[i], r1 = t.rho[i + 1];
  const double du_drho = 1.0 / (r1 - r0);
  const double u = (rho - r0) * du_drho;
  auto along = [&](const std::vector<double>& f, std::size_t j) {
    return f[j * nr + i] + u * (f[j * nr + i + 1] - f[j * nr + i]);
  };
  auto slope = [&](const std::vector<double>& f, std::size_t j) { return f[j * nr + i + 1] - f[j * nr + i]; };

  // Temperature cell [j, j+1] bracketing e on this isochore (E increases with T: validated).
  const double e_low = along(t.energy, 0), e_high = along(t.energy, nt - 1);
  if (!(e >= e_low && e <= e_high)) throw outside(e_low, e_high);
  std::size_t lo = 0, hi = nt - 1;
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    (along(t.energy, mid) <= e ? lo : hi) = mid;
  }
  const std::size_t j = lo;
  const double e0 = along(t.energy, j), e1 = along(t.energy, j + 1);
  const double p0 = along(t.pressure, j), p1 = along(t.pressure, j + 1);
  const double de = e1 - e0, dp = p1 - p0;
  const double v = (e - e0) / de;

  State s;
  s.pressure = p0 + v * dp;
  s.dp_de = dp / de;
  // d/du at fixed e: the bracketing temperature moves as the isochore's energies change.
  const double de0 = slope(t.energy, j), de1 = slope(t.energy, j + 1);
  const double dp0 = slope(t.pressure, j), dp1 = slope(t.pressure, j + 1);
  const double dv_du = -(de0 + v * (de1 - de0)) / de;
  const double dp_drho = (dp0 + v * (dp1 - dp0) + dv_du * dp) * du_drho;
  s.sound_speed2 = floorSoundSpeed2(dp_drho + s.pressure / (rho * rho) * s.dp_de, floor_modulus_, rho);
  return s;
}

}  // namespace kessler::eos
