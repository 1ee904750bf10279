#pragma once
// Body of radialReturnWith (declared in radial_return.hpp). The kinematics, which do not depend
// on the yield law, are compiled once in radial_return.cpp; only the scalar return (the law's
// flow stress and slope inside the Newton iteration) is a template, so that a loop over points
// resolved by one std::visit calls the law without any dispatch.
#include "core/types.hpp"
#include "material/strength/radial_return.hpp"

#include <cmath>
#include <limits>

namespace kessler::strength::detail {

// The trial state of a step in the principal frame of b_e^trial = dF b_e dF^T.
struct TrialState {
  Mat3 be_trial;            // symmetrised
  Mat3 directions;          // columns: principal directions n_i
  Vec3 deviator;            // dev eps_e in the principal frame, eps_i = 1/2 ln lambda_i
  double volumetric = 0.0;  // tr eps_e = ln J
  double J = 1.0;           // sqrt(det b_e^trial): the total volume ratio (plastic flow is isochoric)
  double q_trial = 0.0;     // Kirchhoff equivalent stress sqrt(3/2) |2 G dev eps_e|
};

TrialState trialState(const Mat3& dF, const Mat3& be, double shear_modulus);

// Completes a step whose deviatoric log strain is scaled by `scale` in [0, 1] (1: elastic,
// 0: the deviator is wiped out): writes b_e = sum exp(2 eps_i) n_i (x) n_i and the Cauchy
// deviator s = 2 G scale dev eps_e / J. An elastic step (scale == 1) keeps b_e^trial exactly.
void finishReturn(const TrialState& trial, double shear_modulus, double scale, Mat3& be, ReturnResult& result);

// The plastic increment of a step, the flow stress there, and how the solve went.
struct PlasticIncrement {
  double d_eps_p = 0.0;
  double flow_stress = 0.0;  // sigma_y(eps_p + d_eps_p, d_eps_p/dt)
  int iterations = 0;        // Newton/bisection iterations after the first evaluation at x_max
  bool converged = false;    // |residual| <= 1e-14 q_trial
};

// Solves q_trial - 3 G x = sigma_y(eps_p + x, x/dt, T, T_melt) for the plastic increment x.
// With a non-decreasing flow stress the residual f(x) is strictly decreasing, positive at 0
// (the caller has found q_trial > sigma_y0 = sigma_y(eps_p, 0)) and non-positive at the
// perfectly plastic estimate x_max = (q_trial - sigma_y0) / 3G, so [0, x_max] brackets a unique
// root. The root may lie many decades below x_max: with the published Al 6061 rate exponent
// m = 0.0139 a step 1% over yield has x ~ 1e-144 dt, where Newton in x and bisection are hopeless
// and the slopes of eps_p^n and rate^m are nearly infinite. So the iteration runs in y = ln x and
// takes the smaller (less overshooting) of two Newton steps, each exact for one limit:
//   - on f(e^y): exact where f is linear in x (the elastic term dominates, near x_max);
//   - on H(y) = ln(sigma_y(e^y) - sigma_y0) - ln(3 G (x_max - e^y)), which vanishes with f and is
//     linear in y where the hardening is a power of x (x^m, eps_p^n at 0, linear in eps_p).
// Iterates are kept inside the bracket, by bisection (geometric when the bracket spans decades)
// where both steps leave it, which happens at kinks (the rate cap, the Johnson-Cook rate
// threshold). The sweep in tests/unit/material/test_strength_newton.cpp records the iteration
// counts (a mean of 2-4, at most ~25 with the root on a kink).
template <typename Law>
PlasticIncrement solvePlasticIncrement(const Law& law, double q_trial, double sigma_y0, double three_g, double eps_p,
                                       double dt, double T, double T_melt) {
  constexpr int max_iterations = 100;
  // Still above yield at a plastic increment this small, the root (from a rate exponent m -> 0
  // within a hair of yield) is below anything that changes the stress q_trial - 3 G x in double.
  constexpr double negligible_increment = 1e-200;
  const double tolerance = 1e-14 * q_trial;
  PlasticIncrement out;
  const auto rate = [dt](double x) { return dt > 0.0 ? x / dt : 0.0; };
  const auto residual = [&](double x) {
    out.flow_stress = law.flowStress(eps_p + x, rate(x), T, T_melt);
    return q_trial - three_g * x - out.flow_stress;
  };
  const double x_max = (q_trial - sigma_y0) / three_g;
  double lo = 0.0;
  double hi = x_max;
  double x = x_max;
  double f = residual(x);
  while (std::abs(f) > tolerance && out.iterations < max_iterations) {
    ++out.iterations;
    if (f > 0.0) {
      lo = x;
    } else {
      hi = x;
    }
    const double hardening = law.hardening(eps_p + x, rate(x), T, T_melt, dt);
    double next = x * std::exp(f / ((three_g + hardening) * x));  // Newton on f(e^y)
    const double excess = out.flow_stress - sigma_y0;
    const double room = x_max - x;
    if (excess > 0.0 && room > 0.0) {  // Newton on H(y)
      const double dH_dy = x * (hardening / excess + 1.0 / room);
      const double candidate = x * std::exp(-std::log(excess / (three_g * room)) / dH_dy);
      if (candidate > lo && (candidate < next || !(next < hi))) next = candidate;
    }
    if (!(next > lo && next < hi)) next = lo > 0.0 && hi > 4.0 * lo ? std::sqrt(lo * hi) : 0.5 * (lo + hi);
    const double step = std::abs(next - x);
    x = next;
    f = residual(x);
    if (step <= 4.0 * std::numeric_limits<double>::epsilon() * x || (f < 0.0 && x < negligible_increment)) break;
  }
  out.d_eps_p = x;
  out.converged = std::abs(f) <= tolerance;
  return out;
}

}  // namespace kessler::strength::detail

namespace kessler::strength {

template <typename Law>
ReturnResult radialReturnWith(const Law& law, const ReturnInput& in, Mat3& be, double& eps_p) {
  const double G = in.shear_modulus;
  const detail::TrialState trial = detail::trialState(in.dF, be, G);
  ReturnResult result;
  // Melted (or no shear stiffness): no deviator, and b_e forgets its shape (keeps its volume).
  if (in.temperature >= in.melt_temperature || !(G > 0.0)) {
    detail::finishReturn(trial, G, 0.0, be, result);
    return result;
  }
  // The yield check uses the flow stress at rate 0, the lowest it can be: any q_trial above it
  // gives a positive increment whose rate d_eps_p/dt enters the yield condition itself
  // (consistency viscoplasticity, Wang, Sluys & de Borst, IJNME 40, 1997).
  const double sigma_y0 = law.flowStress(eps_p, 0.0, in.temperature, in.melt_temperature);
  if (!(trial.q_trial > sigma_y0)) {
    detail::finishReturn(trial, G, 1.0, be, result);
    result.flow_stress = sigma_y0;
    return result;
  }
  const detail::PlasticIncrement inc = detail::solvePlasticIncrement(law, trial.q_trial, sigma_y0, 3.0 * G, eps_p,
                                                                     in.dt, in.temperature, in.melt_temperature);
  // Radial return in principal log strains (Simo 1992; Simo & Hughes 1998, §9.2): the deviator
  // keeps its direction and shrinks to q_trial - 3 G d_eps_p = sigma_y. Scaling by
  // sigma_y / q_trial puts it exactly on the yield surface of the returned eps_p even when
  // sigma_y << q_trial (near melting), where the residual, accurate to 1e-14 q_trial, is not small
  // relative to sigma_y. An unconverged solve (a root below 1e-200) keeps the elastic relation
  // q_trial - 3 G d_eps_p instead, which then differs from q_trial by less than one rounding.
  const double q = inc.converged ? inc.flow_stress : trial.q_trial - 3.0 * G * inc.d_eps_p;
  detail::finishReturn(trial, G, q / trial.q_trial, be, result);
  eps_p += inc.d_eps_p;
  result.plastic_increment = inc.d_eps_p;
  result.flow_stress = q;
  // Kirchhoff plastic power tau : d^p dt = sigma_y d_eps_p per reference volume; / J per current.
  result.plastic_work = q * inc.d_eps_p / trial.J;
  return result;
}

}  // namespace kessler::strength
