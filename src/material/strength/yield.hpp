#pragma once
// Flow-stress laws for J2 plasticity (docs/strength.md; the published parameter sets and their
// sources are in docs/materials.md). Each is a small value type with
//   double flowStress(eps_p, eps_p_rate, T, T_melt) -> sigma_y (Pa), 0 at or above melting
//   double hardening(eps_p, eps_p_rate, T, T_melt, dt) -> d sigma_y / d(delta eps_p), for the
//     Newton iteration of the radial return with eps_p_rate = delta eps_p / dt
// and the melting temperature law `meltingTemperature(J)`.
#include <variant>

namespace kessler::strength {

// sigma_y = sigma0 (1 + eps_p/eps_p0)^n [1 + (rate/rate0)^m] (1 - (T - T0)/(Tm - T0))^l
// (Liao et al. 2022; Fan et al. 2019 call the thermal exponent q).
// Melting point: constant `melt_temperature`, or, when `melt_a` is set (> 0), compression
// dependent Tm(J) = Tm0 exp[2a(1 - J)] J^(2(1/3 + a - Gamma0)) (Fan et al. 2019).
// `rate_factor_cap` (> 1, default unlimited) caps the rate factor [1 + (rate/rate0)^m]: the
// published copper set (m = 1, rate0 = 1/s) otherwise multiplies the flow stress by ~1e6 at
// impact strain rates (Liao et al. 2022, Table 2, taken literally; docs/strength.md).
struct PowerLawParameters {
  double sigma0 = 0.0;              // Pa
  double eps0 = 0.0;                // reference plastic strain
  double rate0 = 1.0;               // 1/s
  double n = 0.0;                   // hardening exponent
  double m = 0.0;                   // rate exponent
  double l = 1.0;                   // thermal-softening exponent
  double room_temperature = 293.0;  // T0, K
  double melt_temperature = 0.0;    // Tm0, K
  double melt_a = 0.0;              // a of Tm(J); 0: Tm does not depend on compression
  double melt_gamma0 = 0.0;         // Gamma0 of Tm(J)
  double rate_factor_cap = 0.0;     // 0: no cap
  void check() const;
};

class PowerLaw {
 public:
  explicit PowerLaw(const PowerLawParameters& p);
  double flowStress(double eps_p, double rate, double T, double T_melt) const;
  double hardening(double eps_p, double rate, double T, double T_melt, double dt) const;
  double meltingTemperature(double J) const;
  const PowerLawParameters& parameters() const { return p_; }

 private:
  PowerLawParameters p_;
};

// Johnson-Cook: sigma_y = (A + B eps_p^n)(1 + C ln(rate/rate0))(1 - T*^m),
// T* = (T - T_room)/(Tm - T_room) clipped to [0, 1]; the rate term is 1 below rate0.
struct JohnsonCookParameters {
  double A = 0.0, B = 0.0, n = 0.0, C = 0.0, m = 1.0;
  double rate0 = 1.0;               // 1/s
  double room_temperature = 293.0;  // K
  double melt_temperature = 0.0;    // K
  void check() const;
};

class JohnsonCook {
 public:
  explicit JohnsonCook(const JohnsonCookParameters& p);
  double flowStress(double eps_p, double rate, double T, double T_melt) const;
  double hardening(double eps_p, double rate, double T, double T_melt, double dt) const;
  double meltingTemperature(double J) const;
  const JohnsonCookParameters& parameters() const { return p_; }

 private:
  JohnsonCookParameters p_;
};

// Linear isotropic hardening sigma_y = sigma0 + H eps_p (rate and temperature independent),
// for benchmarks such as the Taylor bar (docs/validation.md).
struct LinearHardeningParameters {
  double sigma0 = 0.0;              // Pa
  double H = 0.0;                   // Pa
  double melt_temperature = 1e300;  // K
  void check() const;
};

class LinearHardening {
 public:
  explicit LinearHardening(const LinearHardeningParameters& p);
  double flowStress(double eps_p, double rate, double T, double T_melt) const;
  double hardening(double eps_p, double rate, double T, double T_melt, double dt) const;
  double meltingTemperature(double J) const;
  const LinearHardeningParameters& parameters() const { return p_; }

 private:
  LinearHardeningParameters p_;
};

// No strength (a fluid, or a target whose strength is negligible).
struct NoStrength {
  double flowStress(double, double, double, double) const { return 0.0; }
  double hardening(double, double, double, double, double) const { return 0.0; }
  double meltingTemperature(double) const { return 1e300; }
};

using Yield = std::variant<NoStrength, LinearHardening, PowerLaw, JohnsonCook>;

const char* modelName(const Yield& yield);

}  // namespace kessler::strength
