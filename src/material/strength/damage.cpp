#include "material/strength/damage.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>

namespace kessler::strength {
namespace {

// Floor on eps_f when the user sets no min_failure_strain: D1 + D2 exp(D3 sigma*) turns negative
// at high triaxiality for sets with D1 < 0 (the commonly cited 6061-T6 set, docs/materials.md),
// and a negative or zero failure strain must mean "fails at once", not a negative or infinite
// damage increment.
constexpr double tiny_failure_strain = 1e-9;

void requireFinite(const char* name, double value) {
  if (!std::isfinite(value)) throw InputError(fmt::format("failure.{} must be finite (got {:g})", name, value));
}

}  // namespace

void JohnsonCookDamageParameters::check() const {
  requireFinite("D1", D1);
  requireFinite("D2", D2);
  requireFinite("D3", D3);
  requireFinite("D4", D4);
  requireFinite("D5", D5);
  if (!(rate0 > 0.0)) throw InputError(fmt::format("failure.rate0 must be positive (got {:g})", rate0));
  if (!(room_temperature > 0.0))
    throw InputError(fmt::format("failure.room_temperature must be positive (got {:g})", room_temperature));
  if (!(melt_temperature > room_temperature))
    throw InputError(fmt::format("failure.melt_temperature must exceed room_temperature {:g} K (got {:g})",
                                 room_temperature, melt_temperature));
  if (!(min_failure_strain >= 0.0 && std::isfinite(min_failure_strain)))
    throw InputError(fmt::format("failure.min_failure_strain must be non-negative (got {:g})", min_failure_strain));
}

JohnsonCookDamage::JohnsonCookDamage(const JohnsonCookDamageParameters& p) : p_(p) {
  p_.check();
}

double JohnsonCookDamage::failureStrain(double triaxiality, double rate, double T) const {
  // Johnson & Cook 1985, eq. 2; the three factors: stress state, strain rate, temperature.
  const double stress_term = p_.D1 + p_.D2 * std::exp(p_.D3 * triaxiality);
  const double rate_star = rate / p_.rate0;
  const double rate_term = rate_star > 1.0 ? 1.0 + p_.D4 * std::log(rate_star) : 1.0;
  const double t_star = T <= p_.room_temperature
                            ? 0.0
                            : std::min((T - p_.room_temperature) / (p_.melt_temperature - p_.room_temperature), 1.0);
  const double thermal_term = 1.0 + p_.D5 * t_star;
  const double eps_f = stress_term * rate_term * thermal_term;
  // std::max returns the floor when eps_f is NaN (from a NaN triaxiality): fail rather than never.
  return std::max(std::max(p_.min_failure_strain, tiny_failure_strain), eps_f);
}

double JohnsonCookDamage::increment(double d_eps_p, double triaxiality, double rate, double T) const {
  if (!(d_eps_p > 0.0)) return 0.0;
  return d_eps_p / failureStrain(triaxiality, rate, T);
}

}  // namespace kessler::strength
