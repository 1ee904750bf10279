#include "material/strength/yield.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace kessler::strength {
namespace {

// The slopes n B eps_p^(n-1) (Johnson-Cook, n < 1) and m/rate0 (rate/rate0)^(m-1) (power law,
// m < 1) are infinite at 0. They are evaluated no lower than these floors, which keeps them
// finite (below ~1e200 B) for every state; the radial-return Newton works with slope * x, which
// tends to 0 there, and its bracket copes with the underestimate below the floor.
constexpr double eps_p_floor = 1e-200;
constexpr double relative_rate_floor = 1e-200;

void requirePositive(const char* name, double value) {
  if (!(value > 0.0)) throw InputError(fmt::format("strength.{} must be positive (got {:g})", name, value));
}

void requireNonNegative(const char* name, double value) {
  if (!(value >= 0.0)) throw InputError(fmt::format("strength.{} must be non-negative (got {:g})", name, value));
}

void requireMeltAboveRoom(double melt, double room) {
  requirePositive("room_temperature", room);
  if (!(melt > room))
    throw InputError(
        fmt::format("strength.melt_temperature must exceed room_temperature {:g} K (got {:g})", room, melt));
}

// Homologous temperature (T - T0)/(Tm - T0) clipped to [0, 1]; the caller has handled T >= Tm.
double homologous(double T, double T_room, double T_melt) {
  if (T <= T_room) return 0.0;
  return std::clamp((T - T_room) / (T_melt - T_room), 0.0, 1.0);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Power law (Liao et al. 2022, eq. 5; Fan et al. 2019, eq. 3)

void PowerLawParameters::check() const {
  requirePositive("sigma0", sigma0);
  requirePositive("eps0", eps0);
  requirePositive("rate0", rate0);
  requireNonNegative("n", n);
  requireNonNegative("m", m);
  requireNonNegative("l", l);
  requireMeltAboveRoom(melt_temperature, room_temperature);
  requireNonNegative("melt_a", melt_a);
  if (!std::isfinite(melt_gamma0))
    throw InputError(fmt::format("strength.melt_gamma0 must be finite (got {:g})", melt_gamma0));
  if (!(rate_factor_cap == 0.0 || rate_factor_cap > 1.0))
    throw InputError(fmt::format("strength.rate_factor_cap must be 0 (no cap) or above 1 (got {:g})", rate_factor_cap));
}

PowerLaw::PowerLaw(const PowerLawParameters& p) : p_(p) {
  p_.check();
}

double PowerLaw::flowStress(double eps_p, double rate, double T, double T_melt) const {
  if (T >= T_melt) return 0.0;
  const double hardening_factor = std::pow(1.0 + std::max(eps_p, 0.0) / p_.eps0, p_.n);
  double rate_factor = 1.0 + std::pow(std::max(rate, 0.0) / p_.rate0, p_.m);
  if (p_.rate_factor_cap > 1.0) rate_factor = std::min(rate_factor, p_.rate_factor_cap);
  const double thermal_factor = std::pow(1.0 - homologous(T, p_.room_temperature, T_melt), p_.l);
  return p_.sigma0 * hardening_factor * rate_factor * thermal_factor;
}

double PowerLaw::hardening(double eps_p, double rate, double T, double T_melt, double dt) const {
  if (T >= T_melt) return 0.0;
  const double base = 1.0 + std::max(eps_p, 0.0) / p_.eps0;
  const double hardening_factor = std::pow(base, p_.n);
  const double d_hardening = p_.n / p_.eps0 * std::pow(base, p_.n - 1.0);
  const double x = std::max(rate, 0.0) / p_.rate0;
  double rate_factor = 1.0 + std::pow(x, p_.m);
  // d/d(delta eps_p) of the rate factor through rate = delta eps_p / dt; zero when capped.
  double d_rate = 0.0;
  if (p_.rate_factor_cap > 1.0 && rate_factor >= p_.rate_factor_cap) {
    rate_factor = p_.rate_factor_cap;
  } else if (dt > 0.0 && p_.m > 0.0) {
    d_rate = p_.m * std::pow(std::max(x, relative_rate_floor), p_.m - 1.0) / (p_.rate0 * dt);
  }
  const double thermal_factor = std::pow(1.0 - homologous(T, p_.room_temperature, T_melt), p_.l);
  return p_.sigma0 * thermal_factor * (d_hardening * rate_factor + hardening_factor * d_rate);
}

double PowerLaw::meltingTemperature(double J) const {
  if (!(p_.melt_a > 0.0)) return p_.melt_temperature;
  // Fan et al. 2019, eq. 4 (a Lindemann law with Gamma/rho constant): Tm rises under compression.
  const double a = p_.melt_a;
  return p_.melt_temperature * std::exp(2.0 * a * (1.0 - J)) * std::pow(J, 2.0 * (1.0 / 3.0 + a - p_.melt_gamma0));
}

// ---------------------------------------------------------------------------------------------
// Johnson-Cook (Johnson & Cook 1983, eq. 1)

void JohnsonCookParameters::check() const {
  requireNonNegative("A", A);
  requireNonNegative("B", B);
  requireNonNegative("n", n);
  requireNonNegative("C", C);
  requirePositive("m", m);
  requirePositive("rate0", rate0);
  requireMeltAboveRoom(melt_temperature, room_temperature);
}

JohnsonCook::JohnsonCook(const JohnsonCookParameters& p) : p_(p) {
  p_.check();
}

double JohnsonCook::flowStress(double eps_p, double rate, double T, double T_melt) const {
  if (T >= T_melt) return 0.0;
  const double hardening_factor = p_.A + p_.B * std::pow(std::max(eps_p, 0.0), p_.n);
  const double rate_factor = rate > p_.rate0 ? 1.0 + p_.C * std::log(rate / p_.rate0) : 1.0;
  const double thermal_factor = 1.0 - std::pow(homologous(T, p_.room_temperature, T_melt), p_.m);
  return hardening_factor * rate_factor * thermal_factor;
}

double JohnsonCook::hardening(double eps_p, double rate, double T, double T_melt, double dt) const {
  if (T >= T_melt) return 0.0;
  const double e = std::max(eps_p, 0.0);
  const double hardening_factor = p_.A + p_.B * std::pow(e, p_.n);
  const double d_hardening = p_.n > 0.0 ? p_.B * p_.n * std::pow(std::max(e, eps_p_floor), p_.n - 1.0) : 0.0;
  const bool rate_active = rate > p_.rate0;
  const double rate_factor = rate_active ? 1.0 + p_.C * std::log(rate / p_.rate0) : 1.0;
  // d/d(delta eps_p) of C ln(rate/rate0) with rate = delta eps_p/dt is C/(rate dt).
  const double d_rate = rate_active && dt > 0.0 ? p_.C / (rate * dt) : 0.0;
  const double thermal_factor = 1.0 - std::pow(homologous(T, p_.room_temperature, T_melt), p_.m);
  return thermal_factor * (d_hardening * rate_factor + hardening_factor * d_rate);
}

double JohnsonCook::meltingTemperature(double /*J*/) const {
  return p_.melt_temperature;
}

// ---------------------------------------------------------------------------------------------
// Linear hardening

void LinearHardeningParameters::check() const {
  requirePositive("sigma0", sigma0);
  requireNonNegative("H", H);
  requirePositive("melt_temperature", melt_temperature);
}

LinearHardening::LinearHardening(const LinearHardeningParameters& p) : p_(p) {
  p_.check();
}

double LinearHardening::flowStress(double eps_p, double /*rate*/, double T, double T_melt) const {
  return T >= T_melt ? 0.0 : p_.sigma0 + p_.H * std::max(eps_p, 0.0);
}

double LinearHardening::hardening(double /*eps_p*/, double /*rate*/, double T, double T_melt, double /*dt*/) const {
  return T >= T_melt ? 0.0 : p_.H;
}

double LinearHardening::meltingTemperature(double /*J*/) const {
  return p_.melt_temperature;
}

// ---------------------------------------------------------------------------------------------

const char* modelName(const Yield& yield) {
  return std::visit(
      [](const auto& law) -> const char* {
        using Law = std::decay_t<decltype(law)>;
        if constexpr (std::is_same_v<Law, NoStrength>) return "none";
        if constexpr (std::is_same_v<Law, LinearHardening>) return "linear-hardening";
        if constexpr (std::is_same_v<Law, PowerLaw>) return "power-law";
        if constexpr (std::is_same_v<Law, JohnsonCook>) return "johnson-cook";
      },
      yield);
}

}  // namespace kessler::strength
