// eos-*: sweeps of each EOS over log ranges of density and energy (0 and 1 J/kg ... 10 MJ/kg)
// against formulas written out here independently of src/material/eos (Mie-Gruneisen in the
// eta = 1 - rho0/rho form of Meyers 1994, §4; the polynomial; Tillotson as in Melosh 1989,
// appendix II; the ideal gas p = (gamma - 1) rho e). The measured value is the worst error of p,
// dp/de and (where written) c^2, relative to the sum of the magnitudes of the formula's terms;
// the reference is 0. The c^2
// returned by the model is also compared with central differences of its own p(rho, e); that
// inconsistency is in the note and fails the problem above 1e-6.
#include "material/eos/eos.hpp"
#include "material/eos/tabulate.hpp"
#include "verify/eos_problems.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <random>

namespace kessler::verify {

namespace {

constexpr double fd_tolerance = 1e-6;

std::vector<double> logRange(double from, double to, int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(from * std::pow(to / from, i / double(n - 1)));
  return v;
}

std::vector<double> energies() {
  std::vector<double> e = logRange(1.0, 1e7, 71);
  e.insert(e.begin(), 0.0);
  return e;
}

// Worst |c^2 - (dp/drho + p/rho^2 dp/de)| over the sweep, relative to |dp/drho| + |p/rho^2 dp/de|,
// with central differences of the model's own pressure. Floored states and stencils that straddle
// a region boundary (`skip`) are left out.
// Fourth-order central difference: truncation O(h^4), so steps can be large enough that the
// rounding of p (up to ~1e4 rho0 c0^2 near the Mie-Gruneisen limit) stays small.
template <class F>
double centralDifference(const F& f, double x, double h) {
  return (8.0 * (f(x + h) - f(x - h)) - (f(x + 2.0 * h) - f(x - 2.0 * h))) / (12.0 * h);
}

template <class Model>
double fdInconsistency(const Model& eos, double k0, const std::vector<double>& rhos, const std::vector<double>& es,
                       double energy_scale, const std::function<bool(double, double, double, double)>& skip) {
  double worst = 0.0;
  for (double rho : rhos) {
    for (double e : es) {
      const double h = 1e-4 * rho, k = 1e-3 * std::max(std::abs(e), energy_scale);
      if (skip(rho, e, h, k)) continue;
      const eos::State s = eos.evaluate(rho, e);
      if (s.sound_speed2 <= 1.01 * eos::sound_speed2_floor_fraction * k0 / rho) continue;
      const double dp_drho = centralDifference([&](double r) { return eos.evaluate(r, e).pressure; }, rho, h);
      const double dp_de = centralDifference([&](double x) { return eos.evaluate(rho, x).pressure; }, e, k);
      const double term = s.pressure / (rho * rho) * dp_de;
      worst = std::max(worst, std::abs(s.sound_speed2 - (dp_drho + term)) / (std::abs(dp_drho) + std::abs(term)));
    }
  }
  return worst;
}

bool near(double x, double boundary, double step) {
  return std::abs(x - boundary) <= 3.0 * step;
}

Outcome finish(Outcome o, double fd, const std::string& sweep) {
  o.reference = 0.0;
  o.comparison = Comparison::absolute;
  o.note = fmt::format("{}; c^2 vs finite differences {:.2e} (limit {:.0e})", sweep, fd, fd_tolerance);
  o = compare(o);
  if (!(fd <= fd_tolerance)) o.passed = false;
  return o;
}

double relative(double value, double reference, double scale) {
  return std::abs(value - reference) / scale;
}

}  // namespace

Outcome eosMieGruneisen() {
  // Al 6061-T6, Steinberg 1996 (UCRL-MA-106439; the library's constants, docs/materials.md).
  const double rho0 = 2703.0, c0 = 5240.0, s = 1.40, g0 = 1.97, k0 = rho0 * c0 * c0;
  const eos::MieGruneisen model({.density = rho0, .sound_speed = c0, .slope = s, .gamma0 = g0});
  const std::vector<double> rhos = logRange(0.5 * rho0, 0.98 * rho0 * s / (s - 1.0), 81);
  double worst = 0.0;
  for (double rho : rhos) {
    const double eta = 1.0 - rho0 / rho, deta = rho0 / (rho * rho);
    double ph = k0 * (rho / rho0 - 1.0), dph = k0 / (rho0 * deta), eh = 0.0, deh = 0.0;
    if (eta > 0.0) {
      ph = k0 * eta / ((1.0 - s * eta) * (1.0 - s * eta));
      dph = k0 * (1.0 + s * eta) / std::pow(1.0 - s * eta, 3);
      eh = 0.5 * ph * eta / rho0;
      deh = 0.5 * (dph * eta + ph) / rho0;
    }
    for (double e : energies()) {
      const double p = ph + g0 * rho0 * (e - eh);
      const double c2 = std::max((dph - g0 * rho0 * deh) * deta + p * g0 * rho0 / (rho * rho),
                                 eos::sound_speed2_floor_fraction * k0 / rho);
      const eos::State st = model.evaluate(rho, e);
      worst = std::max({worst, relative(st.pressure, p, std::abs(ph) + g0 * rho0 * (e + eh)),
                        relative(st.sound_speed2, c2, std::abs(c2)), relative(st.dp_de, g0 * rho0, g0 * rho0)});
    }
  }
  const double fd = fdInconsistency(model, k0, rhos, energies(), 1e6,
                                    [&](double rho, double, double h, double) { return near(rho, rho0, h); });
  Outcome o;
  o.name = "eos-mie-gruneisen";
  o.quantity = "max relative error of p, c^2, dp/de vs formula";
  o.measured = worst;
  o.tolerance = 1e-12;
  return finish(o, fd,
                fmt::format("Al 6061-T6, {} densities 0.5-3.43 rho0 x {} energies", rhos.size(), energies().size()));
}

Outcome eosPolynomial() {
  const double rho0 = 2785.0, k1 = 74.2e9, k2 = -60.5e9, k3 = 36.5e9, g0 = 1.96;
  const eos::Polynomial model({.density = rho0, .k1 = k1, .k2 = k2, .k3 = k3, .gamma0 = g0});
  const std::vector<double> rhos = logRange(0.5 * rho0, 2.0 * rho0, 81);
  double worst = 0.0;
  for (double rho : rhos) {
    const double mu = rho / rho0 - 1.0;
    const double b = mu > 0.0 ? k2 : 0.0, c = mu > 0.0 ? k3 : 0.0;  // K2, K3 only in compression
    for (double e : energies()) {
      const double energy = rho0 * e;  // E, energy per reference volume
      const double p = ((c * mu + b) * mu + k1) * mu + g0 * energy * (1.0 + mu);
      const double c2 = std::max((k1 + 2.0 * b * mu + 3.0 * c * mu * mu + g0 * energy) / rho0 + p * g0 / rho,
                                 eos::sound_speed2_floor_fraction * k1 / rho);
      const double scale =
          std::abs(k1 * mu) + std::abs(b) * mu * mu + std::abs(c * mu * mu * mu) + g0 * energy * (1.0 + mu);
      const eos::State st = model.evaluate(rho, e);
      worst = std::max({worst, relative(st.pressure, p, scale), relative(st.sound_speed2, c2, std::abs(c2)),
                        relative(st.dp_de, g0 * rho, g0 * rho)});
    }
  }
  const double fd = fdInconsistency(model, k1, rhos, energies(), 1e6,
                                    [&](double rho, double, double h, double) { return near(rho, rho0, h); });
  Outcome o;
  o.name = "eos-polynomial";
  o.quantity = "max relative error of p, c^2, dp/de vs formula";
  o.measured = worst;
  o.tolerance = 1e-12;
  return finish(o, fd,
                fmt::format("K1 74.2, K2 -60.5, K3 36.5 GPa, {} densities 0.5-2 rho0 x {} energies", rhos.size(),
                            energies().size()));
}

Outcome eosTillotson() {
  // Aluminium, the iSALE set after Tillotson 1962 and Melosh 1989, appendix II (docs/materials.md).
  const eos::TillotsonParameters t{.density = 2700.0,
                                   .a = 0.5,
                                   .b = 1.63,
                                   .A = 75.2e9,
                                   .B = 65e9,
                                   .E0 = 5e6,
                                   .alpha = 5.0,
                                   .beta = 5.0,
                                   .E_iv = 3e6,
                                   .E_cv = 13.9e6};
  const eos::Tillotson model(t);
  const std::vector<double> rhos = logRange(0.05 * t.density, 3.0 * t.density, 101);
  std::vector<double> es = energies();
  for (double e : logRange(1.1e7, 3e7, 10)) es.push_back(e);  // into the vapour region above E_cv
  double worst = 0.0;
  for (double rho : rhos) {
    const double eta = rho / t.density, mu = eta - 1.0, z = 1.0 / eta - 1.0;
    for (double e : es) {
      const double w = e / (t.E0 * eta * eta) + 1.0;
      const double pc = (t.a + t.b / w) * rho * e + t.A * mu + t.B * mu * mu;
      const double sc = (t.a + t.b / w) * rho * e + std::abs(t.A * mu) + std::abs(t.B) * mu * mu;
      const double damp = std::exp(-t.alpha * z * z), decay = std::exp(-t.beta * z);
      const double pe = t.a * rho * e + (t.b * rho * e / w + t.A * mu * decay) * damp;
      const double se = t.a * rho * e + (t.b * rho * e / w + std::abs(t.A * mu) * decay) * damp;
      double p = pc, scale = sc;
      if (rho < t.density && e >= t.E_cv) {
        p = pe;
        scale = se;
      } else if (rho < t.density && e > t.E_iv) {
        const double f = (e - t.E_iv) / (t.E_cv - t.E_iv);
        p = f * pe + (1.0 - f) * pc;
        scale = f * se + (1.0 - f) * sc;
      }
      if (scale > 0.0) worst = std::max(worst, relative(model.evaluate(rho, e).pressure, p, scale));
    }
  }
  const double fd = fdInconsistency(model, t.A, rhos, es, 1e3, [&](double rho, double e, double h, double k) {
    return near(rho, t.density, h) || near(e, t.E_iv, k) || near(e, t.E_cv, k);
  });
  Outcome o;
  o.name = "eos-tillotson";
  o.quantity = "max relative error of p vs formula";
  o.measured = worst;
  o.tolerance = 1e-12;
  return finish(o, fd,
                fmt::format("Al (iSALE), {} densities 0.05-3 rho0 x {} energies to 30 MJ/kg", rhos.size(), es.size()));
}

Outcome eosIdealGas() {
  // Noh's gas (Noh 1987, J. Comput. Phys. 72:78), gamma 5/3, over six decades of density: the
  // formula has one term, so each error is relative to the value itself. No floor: at e = 0 p and
  // c^2 must be exactly 0, which the measured value includes (scale 1 there, so any nonzero counts).
  const double rho0 = 1.0, gamma = 5.0 / 3.0;
  const eos::IdealGas model({.density = rho0, .gamma = gamma});
  const std::vector<double> rhos = logRange(1e-3 * rho0, 1e3 * rho0, 81);
  double worst = 0.0;
  for (double rho : rhos) {
    for (double e : energies()) {
      const double p = (gamma - 1.0) * rho * e, c2 = gamma * p / rho, dp_de = (gamma - 1.0) * rho;
      const eos::State st = model.evaluate(rho, e);
      worst = std::max({worst, relative(st.pressure, p, e > 0.0 ? p : 1.0),
                        relative(st.sound_speed2, c2, e > 0.0 ? c2 : 1.0), relative(st.dp_de, dp_de, dp_de)});
    }
  }
  // Energy scale 1 J/kg: the energy stencil of e = 1 J/kg stays above 0, where the law clamps e.
  // K0 = 0 leaves out only e = 0, where c^2 = 0 and the identity's terms vanish.
  const double fd =
      fdInconsistency(model, 0.0, rhos, energies(), 1.0, [](double, double, double, double) { return false; });
  Outcome o;
  o.name = "eos-ideal-gas";
  o.quantity = "max relative error of p, c^2, dp/de vs formula";
  o.measured = worst;
  o.tolerance = 1e-12;
  return finish(o, fd,
                fmt::format("gamma 5/3, {} densities 1e-3-1e3 rho0 x {} energies (e = 0: p = c^2 = 0 exactly)",
                            rhos.size(), energies().size()));
}

Outcome eosTabular() {
  // Al 6061-T6 Mie-Gruneisen tabulated on 100 x 100 (rho 0.5-2 rho0 geometric, T 0-20000 K with
  // e = c_v (T - T0)), written as SESAME, read back and evaluated at random off-grid states.
  const double rho0 = 2703.0, c0 = 5240.0, k0 = rho0 * c0 * c0, cv = 896.0, t0 = 293.0;
  const eos::MieGruneisen analytic({.density = rho0, .sound_speed = c0, .slope = 1.40, .gamma0 = 1.97});
  const eos::TableGrid grid{
      .rho_min = 0.5 * rho0, .rho_max = 2.0 * rho0, .n_rho = 100, .t_min = 0.0, .t_max = 20000.0, .n_t = 100};
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / fmt::format("kessler-verify-eos-{}.ses", ::getpid());
  eos::writeSesame(eos::tabulate(analytic, grid, cv, t0), file);
  const auto table = std::make_shared<const eos::SesameTable>(eos::readSesame(file));
  std::filesystem::remove(file);
  const eos::Tabular model(table);

  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (int n = 0; n < 20000; ++n) {
    const double rho = grid.rho_min * std::pow(grid.rho_max / grid.rho_min, unit(rng));
    const double e = cv * (grid.t_min - t0 + (grid.t_max - grid.t_min) * unit(rng));
    const double p = analytic.evaluate(rho, e).pressure;
    worst = std::max(worst, std::abs(model.evaluate(rho, e).pressure - p) / std::max(std::abs(p), 0.05 * k0));
  }
  // c^2 inside the cells only: the interpolant's derivatives jump on grid lines.
  std::vector<double> rhos, es;
  const std::size_t nr = table->rho.size();
  for (std::size_t i = 0; i + 1 < nr; i += 3)
    rhos.push_back(table->rho[i] + 0.37 * (table->rho[i + 1] - table->rho[i]));
  for (std::size_t j = 0; j + 1 < table->temperature.size(); j += 3)
    es.push_back(table->energy[j * nr] + 0.59 * (table->energy[(j + 1) * nr] - table->energy[j * nr]));
  const double fd = fdInconsistency(model, k0, rhos, es, 1e3, [](double, double, double, double) { return false; });
  Outcome o;
  o.name = "eos-tabular";
  o.quantity = "max |p_table - p| / max(|p|, 0.05 rho0 c0^2)";
  o.measured = worst;
  // Interpolation bound: (drho)^2/8 |p''| across a 1.4% cell at the Hugoniot kink at rho0.
  o.tolerance = 2e-3;
  return finish(o, fd, "Al 6061-T6 MG as SESAME 100 x 100, 20000 off-grid states");
}

}  // namespace kessler::verify
