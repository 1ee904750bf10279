#pragma once
// The NASA standard breakup model (Johnson, Krisko, Liou & Anz-Meador, "NASA's new breakup
// model of EVOLVE 4.0", Adv. Space Res. 28(9), 2001): the cumulative number of fragments of a
// collision larger than a characteristic length Lc, and the average cross-section area of a
// fragment of that size. Interface in SI; the model's own units (J/g, km/s) stay inside.

namespace kessler::analysis {

// The collision, in SI: the smaller (projectile) and larger (target) masses and the relative
// speed.
struct BreakupEvent {
  double projectile_mass = 0.0;  // kg
  double target_mass = 0.0;      // kg
  double impact_speed = 0.0;     // m/s
};

struct BreakupPrediction {
  double specific_energy = 0.0;  // J/g, projectile kinetic energy per gram of target
  bool catastrophic = false;     // specific_energy >= 40 J/g
  double reference_mass = 0.0;   // M (kg): m_p + m_t if catastrophic, else m_p v^2 (v in km/s)

  // N(>Lc) = 0.1 M^0.75 Lc^-1.71 with Lc in m, M in kg (Johnson et al. 2001).
  double count(double lc) const;
  // Inverse: the Lc above which the model predicts `n` fragments.
  double lengthForCount(double n) const;
};

inline constexpr double catastrophic_threshold = 40.0;  // J/g (Johnson et al. 2001)
inline constexpr double breakup_coefficient = 0.1;
inline constexpr double breakup_mass_exponent = 0.75;
inline constexpr double breakup_length_exponent = -1.71;

// Throws kessler::InputError for non-positive masses or a negative speed.
BreakupPrediction nasaBreakup(const BreakupEvent& event);

// Average cross-section area (m^2) of a fragment of characteristic length lc (m):
// 0.540424 Lc^2 below Lc = 1.67 mm, 0.556945 Lc^2.0047077 above (Johnson et al. 2001).
double nasaFragmentArea(double lc);

}  // namespace kessler::analysis
