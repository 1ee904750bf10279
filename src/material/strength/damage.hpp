#pragma once
// Johnson-Cook cumulative damage (Johnson & Cook, Eng. Fract. Mech. 21, 1985):
//   D += d_eps_p / eps_f,  eps_f = (D1 + D2 exp(D3 sigma*)) (1 + D4 ln rate*) (1 + D5 T*),
// with triaxiality sigma* = -p / sigma_eq, rate* = rate/rate0 (the log term only above 1) and
// T* the homologous temperature clipped to [0, 1]. The point fails when D reaches 1.
namespace kessler::strength {

struct JohnsonCookDamageParameters {
  double D1 = 0.0, D2 = 0.0, D3 = 0.0, D4 = 0.0, D5 = 0.0;
  double rate0 = 1.0;               // 1/s
  double room_temperature = 293.0;  // K
  double melt_temperature = 0.0;    // K
  double min_failure_strain = 0.0;  // lower bound on eps_f (guards D1 + D2 e^(D3 s*) <= 0)
  void check() const;
};

class JohnsonCookDamage {
 public:
  explicit JohnsonCookDamage(const JohnsonCookDamageParameters& p);
  double failureStrain(double triaxiality, double rate, double T) const;
  // Damage increment for a plastic increment at the given state.
  double increment(double d_eps_p, double triaxiality, double rate, double T) const;
  const JohnsonCookDamageParameters& parameters() const { return p_; }

 private:
  JohnsonCookDamageParameters p_;
};

}  // namespace kessler::strength
