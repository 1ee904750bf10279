#include "analysis/breakup_model.hpp"

#include "core/error.hpp"

#include <cmath>

namespace kessler::analysis {

double BreakupPrediction::count(double lc) const {
  KESSLER_VERIFY(lc > 0.0, "breakup model: Lc {} m must be positive", lc);
  return breakup_coefficient * std::pow(reference_mass, breakup_mass_exponent) * std::pow(lc, breakup_length_exponent);
}

double BreakupPrediction::lengthForCount(double n) const {
  KESSLER_VERIFY(n > 0.0, "breakup model: a fragment count {} must be positive", n);
  return std::pow(n / (breakup_coefficient * std::pow(reference_mass, breakup_mass_exponent)),
                  1.0 / breakup_length_exponent);
}

BreakupPrediction nasaBreakup(const BreakupEvent& event) {
  if (!(event.projectile_mass > 0.0) || !(event.target_mass > 0.0)) {
    throw InputError(fmt::format("breakup model: projectile mass {} kg and target mass {} kg must be positive",
                                 event.projectile_mass, event.target_mass));
  }
  if (!(event.impact_speed >= 0.0) || !std::isfinite(event.impact_speed)) {
    throw InputError(
        fmt::format("breakup model: impact speed {} m/s must be finite and non-negative", event.impact_speed));
  }
  BreakupPrediction p;
  const double kinetic = 0.5 * event.projectile_mass * event.impact_speed * event.impact_speed;  // J
  p.specific_energy = kinetic / (1000.0 * event.target_mass);                                    // J/g
  p.catastrophic = p.specific_energy >= catastrophic_threshold;
  const double v_km_s = event.impact_speed / 1000.0;
  // Below the threshold only part of the target breaks up; the model's "mass" is then
  // m_p v^2 with v in km/s, a fit that is not a physical mass (Johnson et al. 2001, §2.1).
  p.reference_mass =
      p.catastrophic ? event.projectile_mass + event.target_mass : event.projectile_mass * v_km_s * v_km_s;
  return p;
}

double nasaFragmentArea(double lc) {
  KESSLER_VERIFY(lc >= 0.0, "breakup model: Lc {} m must be non-negative", lc);
  if (lc < 1.67e-3) return 0.540424 * lc * lc;
  return 0.556945 * std::pow(lc, 2.0047077);
}

}  // namespace kessler::analysis
