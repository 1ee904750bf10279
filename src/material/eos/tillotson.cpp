// Tillotson EOS (Tillotson 1962, GA-3216; in the form of Melosh 1989, "Impact Cratering",
// appendix II, as used by iSALE). eta = rho/rho0, mu = eta - 1,
// omega = 1 + e/(E0 eta^2), x = 1/eta - 1:
//   compressed (rho >= rho0, or cold expanded e <= E_iv):
//     p_c = (a + b/omega) rho e + A mu + B mu^2
//   expanded (rho < rho0, e >= E_cv):
//     p_e = a rho e + [b rho e/omega + A mu exp(-beta x)] exp(-alpha x^2)
//   partial vaporisation (rho < rho0, E_iv < e < E_cv), linear in e:
//     p = [(e - E_iv) p_e + (E_cv - e) p_c] / (E_cv - E_iv)
// No tension cut-off is applied here: spall and erosion are the failure models' business.
#include "material/eos/tillotson.hpp"

#include "core/error.hpp"

#include <cmath>

namespace kessler::eos {

namespace {

void require(bool ok, const char* name, const char* what, double value) {
  if (!ok) throw InputError(fmt::format("eos.{} must be {} (got {})", name, what, value));
}

// Pressure and its partial derivatives at one (rho, e) on one branch.
struct Branch {
  double p = 0.0, dp_drho = 0.0, dp_de = 0.0;
};

}  // namespace

void TillotsonParameters::check() const {
  require(std::isfinite(density) && density > 0.0, "density", "positive", density);
  require(std::isfinite(a) && a >= 0.0, "a", "non-negative", a);
  require(std::isfinite(b) && b >= 0.0, "b", "non-negative", b);
  require(std::isfinite(A) && A > 0.0, "A", "positive", A);
  require(std::isfinite(B), "B", "finite", B);
  require(std::isfinite(E0) && E0 > 0.0, "E0", "positive", E0);
  require(std::isfinite(alpha) && alpha >= 0.0, "alpha", "non-negative", alpha);
  require(std::isfinite(beta) && beta >= 0.0, "beta", "non-negative", beta);
  require(std::isfinite(E_iv) && E_iv >= 0.0, "E_iv", "non-negative", E_iv);
  require(std::isfinite(E_cv) && E_cv > E_iv, "E_cv", fmt::format("greater than E_iv = {}", E_iv).c_str(), E_cv);
}

Tillotson::Tillotson(const TillotsonParameters& p) : p_(p) {
  p_.check();
}

State Tillotson::evaluate(double rho, double e) const {
  if (!(rho > 0.0 && std::isfinite(rho) && std::isfinite(e)))
    throw NumericalError(fmt::format("tillotson EOS: invalid state rho = {} kg/m^3, e = {} J/kg", rho, e));
  const double rho0 = p_.density;
  const double eta = rho / rho0;
  const double mu = eta - 1.0;
  const double omega = 1.0 + e / (p_.E0 * eta * eta);
  // omega <= 0 needs e <= -E0 eta^2, an energy far below any state the fit describes.
  if (!(omega > 0.0))
    throw NumericalError(
        fmt::format("tillotson EOS: energy e = {:.6g} J/kg at rho = {:.6g} kg/m^3 is below -E0 (rho/rho0)^2, where "
                    "omega = 1 + e/(E0 eta^2) vanishes",
                    e, rho));
  const double domega_de = 1.0 / (p_.E0 * eta * eta);
  const double domega_drho = -2.0 * e / (p_.E0 * eta * eta * eta * rho0);
  // Derivatives of the shared term q = b rho e / omega.
  const double q = p_.b * rho * e / omega;
  const double dq_de = p_.b * rho * (1.0 / omega - e * domega_de / (omega * omega));
  const double dq_drho = p_.b * e * (1.0 / omega - rho * domega_drho / (omega * omega));

  auto compressed = [&] {
    Branch c;
    c.p = p_.a * rho * e + q + p_.A * mu + p_.B * mu * mu;
    c.dp_de = p_.a * rho + dq_de;
    c.dp_drho = p_.a * e + dq_drho + (p_.A + 2.0 * p_.B * mu) / rho0;
    return c;
  };
  auto expanded = [&] {
    const double x = 1.0 / eta - 1.0;
    const double dx_drho = -rho0 / (rho * rho);
    const double eb = std::exp(-p_.beta * x);
    const double ea = std::exp(-p_.alpha * x * x);
    const double inner = q + p_.A * mu * eb;
    const double dinner_drho = dq_drho + p_.A * eb * (1.0 / rho0 - p_.beta * mu * dx_drho);
    Branch v;
    v.p = p_.a * rho * e + inner * ea;
    v.dp_de = p_.a * rho + dq_de * ea;
    v.dp_drho = p_.a * e + dinner_drho * ea - 2.0 * p_.alpha * x * dx_drho * inner * ea;
    return v;
  };

  Branch r;
  if (rho >= rho0 || e <= p_.E_iv) {
    r = compressed();
  } else if (e >= p_.E_cv) {
    r = expanded();
  } else {
    const Branch c = compressed();
    const Branch v = expanded();
    const double width = p_.E_cv - p_.E_iv;
    const double w = (e - p_.E_iv) / width;
    r.p = w * v.p + (1.0 - w) * c.p;
    r.dp_drho = w * v.dp_drho + (1.0 - w) * c.dp_drho;
    r.dp_de = w * v.dp_de + (1.0 - w) * c.dp_de + (v.p - c.p) / width;
  }
  State s;
  s.pressure = r.p;
  s.dp_de = r.dp_de;
  s.sound_speed2 = floorSoundSpeed2(r.dp_drho + r.p / (rho * rho) * r.dp_de, p_.A, rho);
  return s;
}

}  // namespace kessler::eos
