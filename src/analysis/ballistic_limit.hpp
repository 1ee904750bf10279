#pragma once
// Engineering ballistic-limit equations that shielding engineers compare simulations with
// (docs/analysis.md §8): Christiansen's Whipple-shield ballistic limit (Int. J. Impact Eng. 14,
// 1993; NASA TP-2003-210788) and the JSC Cour-Palais single-wall penetration equation (Int. J.
// Impact Eng. 5, 1987). The equations are empirical fits in cm, g/cm^3, km/s and ksi; the
// interface is SI and the conversion happens inside.

#include <string_view>

namespace kessler::analysis {

// A two-wall (Whipple) shield, SI.
struct WhippleShield {
  double bumper_thickness = 0.0;   // m
  double bumper_density = 0.0;     // kg/m^3
  double wall_thickness = 0.0;     // m
  double wall_yield_stress = 0.0;  // Pa, the rear wall's yield stress (the fit's sigma)
  double spacing = 0.0;            // m, bumper to rear wall
};

// The projectile, SI; obliquity is measured from the plate normal.
struct Projectile {
  double diameter = 0.0;   // m (ignored by whippleBallisticLimit)
  double density = 0.0;    // kg/m^3
  double speed = 0.0;      // m/s
  double obliquity = 0.0;  // rad
};

// Christiansen's three regimes of normal speed Vn = V cos(theta): the projectile stays whole
// (Vn <= 3 km/s), fragments (3-7 km/s), melts or vaporises (>= 7 km/s).
enum class ChristiansenRegime { ballistic, shatter, hypervelocity };
std::string_view regimeName(ChristiansenRegime regime);

struct BallisticLimit {
  double critical_diameter = 0.0;  // m: a larger projectile perforates the rear wall
  ChristiansenRegime regime = ChristiansenRegime::ballistic;
  double normal_speed = 0.0;         // m/s, with the obliquity clamped at 65 degrees
  double effective_obliquity = 0.0;  // rad, min(theta, 65 degrees)
};

// Throws kessler::InputError for non-positive thicknesses, densities, spacing, yield stress or
// speed, or an obliquity outside [0, 90) degrees.
BallisticLimit whippleBallisticLimit(const WhippleShield& shield, const Projectile& projectile);

// The regime equations on their own, in the fit's units (cm, g/cm^3, km/s, ksi; theta in
// rad), so that their continuity at Vn = 3 and 7 km/s can be checked.
struct ChristiansenUnits {
  double t_b = 0.0, rho_b = 0.0, t_w = 0.0, sigma_ksi = 0.0, spacing = 0.0, rho_p = 0.0;
};
double christiansenBallistic(const ChristiansenUnits& u, double v_km_s, double theta);
double christiansenShatter(const ChristiansenUnits& u, double v_km_s, double theta);
double christiansenHypervelocity(const ChristiansenUnits& u, double v_km_s, double theta);

// A single aluminium-like wall, SI.
struct SingleWall {
  double thickness = 0.0;         // m
  double density = 0.0;           // kg/m^3
  double brinell_hardness = 0.0;  // BHN (e.g. 95 for Al 6061-T6)
  double sound_speed = 0.0;       // m/s, the target's speed of sound C_t
};

enum class WallDamage { none, incipient_spall, detached_spall, perforation };
std::string_view damageName(WallDamage damage);

struct Penetration {
  double depth = 0.0;  // m, P of the Cour-Palais equation
  WallDamage damage = WallDamage::none;
  double perforation_diameter = 0.0;  // m, the projectile diameter at which t = 1.8 P
};

// P = 5.24 d^(19/18) BHN^-0.25 (rho_p/rho_t)^0.5 (V cos(theta)/C_t)^(2/3) (cm, km/s);
// perforation when t < 1.8 P, detached spall when t < 2.2 P, incipient spall when t < 3 P.
Penetration courPalaisPenetration(const SingleWall& wall, const Projectile& projectile);

}  // namespace kessler::analysis
