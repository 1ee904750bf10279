// The scalar plastic-increment solve of the radial return over a sweep of hard cases: the published
// laws of docs/materials.md (Liao et al. 2022, Fan et al. 2019, Johnson & Cook 1983) and a few
// synthetic ones, plastic strains from 0 (slope of eps_p^n infinite) to 2, steps from a
// picosecond (rates ~1e10 /s) to an hour (rates ~1e-12 /s), temperatures up to 0.01 K below
// melting, and trial stresses from 1 + 1e-12 to 1000 times the yield stress.
#include "material/strength/radial_return.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace kessler::strength {
namespace {

PowerLawParameters powerLaw(double sigma0, double eps0, double rate0, double n, double m, double l, double Tm,
                            double cap) {
  PowerLawParameters p;
  p.sigma0 = sigma0;
  p.eps0 = eps0;
  p.rate0 = rate0;
  p.n = n;
  p.m = m;
  p.l = l;
  p.melt_temperature = Tm;
  p.rate_factor_cap = cap;
  return p;
}

struct SweepResult {
  int cases = 0, worst_iterations = 0, total_iterations = 0, unconverged = 0;
  double worst_consistency = 0.0;
};

template <typename Law>
void sweep(const Law& law, double T_melt, SweepResult& out) {
  const double three_g = 3.0 * 40e9;
  for (double eps_p : {0.0, 1e-6, 1e-3, 0.1, 2.0}) {
    for (double dt : {0.0, 1e-12, 1e-9, 1e-7, 1e-5, 1e-2, 3.6e3}) {
      for (double T : {293.0, 0.6 * T_melt, T_melt - 0.01}) {
        const double sigma_y0 = law.flowStress(eps_p, 0.0, T, T_melt);
        if (!(sigma_y0 > 0.0)) continue;  // melted: no return to solve
        for (double over : {1e-12, 1e-8, 1e-4, 1e-2, 0.5, 2.0, 30.0, 1000.0}) {
          const double q_trial = sigma_y0 * (1.0 + over);
          const detail::PlasticIncrement inc =
              detail::solvePlasticIncrement(law, q_trial, sigma_y0, three_g, eps_p, dt, T, T_melt);
          const double x = inc.d_eps_p;
          const int iterations = inc.iterations;
          ASSERT_TRUE(std::isfinite(x) && x >= 0.0)
              << "eps_p " << eps_p << " dt " << dt << " T " << T << " over " << over;
          // Consistency of the returned increment, relative to the trial stress (rounding in
          // q_trial - 3 G x is relative to q_trial). A root below 1e-200 (rate exponents m -> 0
          // within a hair of yield) is not chased: x must then be negligible in the stress.
          const double rate = dt > 0.0 ? x / dt : 0.0;
          const double residual = q_trial - three_g * x - law.flowStress(eps_p + x, rate, T, T_melt);
          if (inc.converged) {
            EXPECT_LE(std::abs(residual), 1e-14 * q_trial) << "eps_p " << eps_p << " dt " << dt << " T " << T;
            out.worst_consistency = std::max(out.worst_consistency, std::abs(residual) / q_trial);
          } else {
            EXPECT_LE(three_g * x, 1e-14 * q_trial)
                << "eps_p " << eps_p << " dt " << dt << " T " << T << " over " << over << " x " << x;
            ++out.unconverged;
          }
          ++out.cases;
          out.total_iterations += iterations;
          out.worst_iterations = std::max(out.worst_iterations, iterations);
        }
      }
    }
  }
}

template <typename Law>
void report(const char* label, const Law& law, double T_melt) {
  SweepResult r;
  sweep(law, T_melt, r);
  std::printf("[ newton   ] %-28s %4d cases: mean %.2f, worst %2d iterations; |f|/q_trial <= %.1e; %d roots < 1e-200\n",
              label, r.cases, double(r.total_iterations) / r.cases, r.worst_iterations, r.worst_consistency,
              r.unconverged);
  EXPECT_LE(r.worst_iterations, 30) << label;
}

TEST(StrengthNewton, SweepOfHardCases) {
  report("Al 6061 power law", PowerLaw(powerLaw(270e6, 0.0025, 1.0, 0.148, 0.01389, 1.0, 1200.0, 0.0)), 1200.0);
  report("Cu power law m=1", PowerLaw(powerLaw(120e6, 0.0278, 1.0, 0.45, 1.0, 1.0, 1790.0, 0.0)), 1790.0);
  report("Cu power law m=1 cap 3", PowerLaw(powerLaw(120e6, 0.0278, 1.0, 0.45, 1.0, 1.0, 1790.0, 3.0)), 1790.0);
  report("LY12 power law", PowerLaw(powerLaw(276e6, 5e-4, 1000.0, 0.075, 0.08, 0.5, 925.0, 0.0)), 925.0);
  report("power law m=2 (convex rate)", PowerLaw(powerLaw(100e6, 0.01, 1e3, 0.3, 2.0, 1.0, 1000.0, 0.0)), 1000.0);
  report("Cu JC",
         JohnsonCook({.A = 90e6,
                      .B = 292e6,
                      .n = 0.31,
                      .C = 0.025,
                      .m = 1.09,
                      .rate0 = 1.0,
                      .room_temperature = 293.0,
                      .melt_temperature = 1356.0}),
         1356.0);
  report("4340 JC",
         JohnsonCook({.A = 792e6,
                      .B = 510e6,
                      .n = 0.26,
                      .C = 0.014,
                      .m = 1.03,
                      .rate0 = 1.0,
                      .room_temperature = 293.0,
                      .melt_temperature = 1793.0}),
         1793.0);
  report("JC n=1.5, A=0+",
         JohnsonCook({.A = 1e3,
                      .B = 500e6,
                      .n = 1.5,
                      .C = 0.1,
                      .m = 1.0,
                      .rate0 = 1e-3,
                      .room_temperature = 293.0,
                      .melt_temperature = 1000.0}),
         1000.0);
  report("linear", LinearHardening({.sigma0 = 300e6, .H = 2e9, .melt_temperature = 1e300}), 1e300);
}

}  // namespace
}  // namespace kessler::strength
