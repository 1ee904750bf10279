// radial-return: the log-strain radial return (Simo 1992) driven point by point, without a mesh,
// along three coaxial paths whose answers are written out here independently of the update:
//   (a) uniaxial strain dF = diag(1, 1, e^de), linear hardening, compression to eps_zz = -8%,
//       then reversal to +4% (elastic unloading, reverse yield): closed form per segment;
//   (b) pure shear dF = Q diag(e^dg, e^-dg, 1) Q^T in axes Q, Al 6061-T6 power law (Liao et al.
//       2022), rate independent (dt = 0): the hardening curve sigma = sigma_y(eps_eq - sigma/3G),
//       solved by bisection;
//   (c) the same path at a constant equivalent strain rate of 1e4 /s with 4340 steel Johnson-Cook
//       at 600 K: each step's backward-Euler condition 3G (eps_eq - p) = sigma_y(p, (p - p_old)/dt)
//       solved by bisection (the time-discrete answer: the update is backward Euler in the rate).
// For a coaxial path the log-strain return is exact: the deviatoric log strain is x N with the
// equivalent strain x and a fixed direction N (|N| = sqrt(3/2)), and the Kirchhoff deviator is
// tau' = (2/3) Sigma N with Sigma = 3 G (x - p). The measured value is the largest difference of
// any component of the Cauchy deviator s = tau'/J from that answer, over every step of the three
// paths, relative to the initial yield stress of the path; the reference is 0.
#include "material/strength/radial_return.hpp"
#include "verify/strength_problems.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace kessler::verify {
namespace {

constexpr double G = 26e9;  // Pa

// Root of an increasing function on [lo, hi] by bisection (independent of the production solver).
double bisect(const std::function<double(double)>& g, double lo, double hi) {
  for (int i = 0; i < 200 && hi - lo > 0.0; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (g(mid) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

struct PathResult {
  double worst = 0.0;  // relative to the yield stress
  int steps = 0;
};

// Drives one point through the increments dF[k] and compares s after each with the expected
// (2/3) Sigma_k Q N Q^T / J_k.
template <typename Law>
PathResult drive(const Law& law, const std::vector<Mat3>& increments, double dt, double T, double T_melt,
                 const Mat3& direction, const std::vector<double>& sigma, const std::vector<double>& J, double yield) {
  PathResult r;
  Mat3 be = Mat3::Identity();
  double eps_p = 0.0;
  strength::ReturnInput in;
  in.dt = dt;
  in.shear_modulus = G;
  in.temperature = T;
  in.melt_temperature = T_melt;
  for (std::size_t k = 0; k < increments.size(); ++k) {
    in.dF = increments[k];
    const strength::ReturnResult out = strength::radialReturnWith(law, in, be, eps_p);
    const Mat3 expected = (2.0 / 3.0) * sigma[k] * direction / J[k];
    r.worst = std::max(r.worst, (out.deviatoric_stress - expected).cwiseAbs().maxCoeff() / yield);
    ++r.steps;
  }
  return r;
}

// (a) Uniaxial strain with linear hardening sigma_y = sigma0 + H eps_p. Signed equivalent strain
// x = (2/3) eps_zz, N = diag(-1/2, -1/2, 1). Loading from the virgin state (x decreasing):
// elastic until 3G|x| = sigma0, then sigma_y = (sigma0 + H |x|)/(1 + H/3G). Reversal at x_t with
// p_t = x_t + sigma_y,t/3G, eps_p,t = -p_t: elastic until Sigma = +sigma_y,t, then
// sigma_y = (sigma0 + H eps_p,t + H (x - p_t))/(1 + H/3G).
PathResult uniaxialStrain() {
  const double sigma0 = 300e6, H = 2e9;
  const strength::LinearHardening law({.sigma0 = sigma0, .H = H, .melt_temperature = 1e300});
  const int n_load = 200, n_reverse = 150;
  const double d_load = -0.08 / n_load, d_reverse = 0.12 / n_reverse;
  const double k = 1.0 + H / (3.0 * G);
  std::vector<Mat3> increments;
  std::vector<double> sigma, J;
  double eps_zz = 0.0;
  for (int i = 0; i < n_load + n_reverse; ++i) {
    const double d = i < n_load ? d_load : d_reverse;
    increments.push_back(Vec3(1.0, 1.0, std::exp(d)).asDiagonal());
    eps_zz += d;
    J.push_back(std::exp(eps_zz));
    const double x = 2.0 / 3.0 * eps_zz;
    if (i < n_load) {
      sigma.push_back(3.0 * G * std::abs(x) <= sigma0 ? 3.0 * G * x : -(sigma0 + H * std::abs(x)) / k);
    } else {
      const double x_t = 2.0 / 3.0 * (n_load * d_load);
      const double sigma_t = (sigma0 + H * std::abs(x_t)) / k;
      const double p_t = x_t + sigma_t / (3.0 * G);
      const double elastic = -sigma_t + 3.0 * G * (x - x_t);
      sigma.push_back(elastic <= sigma_t ? elastic : (sigma0 - H * p_t + H * (x - p_t)) / k);
    }
  }
  const Mat3 N = Vec3(-0.5, -0.5, 1.0).asDiagonal();
  return drive(law, increments, 0.0, 293.0, 1e300, N, sigma, J, sigma0);
}

// Pure-shear increments in the axes Q and the direction N = sqrt(3)/2 Q diag(1, -1, 0) Q^T;
// the equivalent strain after k steps of dg is x_k = (2/sqrt 3) k dg.
struct ShearPath {
  std::vector<Mat3> increments;
  std::vector<double> x;
  Mat3 direction;
};

ShearPath pureShear(int steps, double gamma) {
  ShearPath path;
  const Mat3 Q = Eigen::AngleAxisd(0.7, Vec3(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  const double dg = gamma / steps;
  const Mat3 dF = Q * Vec3(std::exp(dg), std::exp(-dg), 1.0).asDiagonal() * Q.transpose();
  for (int k = 1; k <= steps; ++k) {
    path.increments.push_back(dF);
    path.x.push_back(2.0 / std::sqrt(3.0) * k * dg);
  }
  path.direction = std::sqrt(3.0) / 2.0 * Q * Vec3(1.0, -1.0, 0.0).asDiagonal() * Q.transpose();
  return path;
}

// (b) Rate-independent power law: Sigma = sigma_y(x - Sigma/3G) on the hardening curve.
PathResult shearPowerLaw() {
  strength::PowerLawParameters p;
  p.sigma0 = 270e6;
  p.eps0 = 0.0025;
  p.n = 0.148;
  p.m = 0.01389;
  p.melt_temperature = 1200.0;
  const strength::PowerLaw law(p);
  const auto flow = [&](double eps_p) { return p.sigma0 * std::pow(1.0 + eps_p / p.eps0, p.n); };
  const ShearPath path = pureShear(200, 0.3);
  std::vector<double> sigma, J(path.x.size(), 1.0);
  for (double x : path.x) {
    if (3.0 * G * x <= flow(0.0)) {
      sigma.push_back(3.0 * G * x);
    } else {
      sigma.push_back(bisect([&](double s) { return s - flow(x - s / (3.0 * G)); }, 0.0, 3.0 * G * x));
    }
  }
  return drive(law, path.increments, 0.0, 293.0, p.melt_temperature, path.direction, sigma, J, p.sigma0);
}

// (c) Johnson-Cook at a constant equivalent strain rate: per step, the plastic strain p solves
// 3G (x - p) = (A + B p^n)(1 + C ln max(1, (p - p_old)/dt))(1 - T*^m).
PathResult shearJohnsonCook() {
  const strength::JohnsonCookParameters p{.A = 792e6,
                                          .B = 510e6,
                                          .n = 0.26,
                                          .C = 0.014,
                                          .m = 1.03,
                                          .rate0 = 1.0,
                                          .room_temperature = 293.0,
                                          .melt_temperature = 1793.0};
  const strength::JohnsonCook law(p);
  const double T = 600.0;
  const double thermal = 1.0 - std::pow((T - 293.0) / (1793.0 - 293.0), p.m);
  const ShearPath path = pureShear(200, 0.3);
  const double dt = (path.x[1] - path.x[0]) / 1e4;
  const auto flow = [&](double eps_p, double rate) {
    return (p.A + p.B * std::pow(eps_p, p.n)) * (1.0 + p.C * std::log(std::max(1.0, rate))) * thermal;
  };
  std::vector<double> sigma, J(path.x.size(), 1.0);
  double p_old = 0.0;
  for (double x : path.x) {
    if (3.0 * G * (x - p_old) > flow(p_old, 0.0)) {
      const auto g = [&](double pp) { return flow(pp, (pp - p_old) / dt) - 3.0 * G * (x - pp); };
      p_old = bisect(g, p_old, x);
    }
    sigma.push_back(3.0 * G * (x - p_old));
  }
  return drive(law, path.increments, dt, T, p.melt_temperature, path.direction, sigma, J, p.A * thermal);
}

}  // namespace

Outcome radialReturn() {
  const PathResult a = uniaxialStrain();
  const PathResult b = shearPowerLaw();
  const PathResult c = shearJohnsonCook();
  Outcome o;
  o.name = "radial-return";
  o.quantity = "max |s - s_exact| / sigma_y0 over all steps (dimensionless)";
  o.measured = std::max({a.worst, b.worst, c.worst});
  o.reference = 0.0;
  o.tolerance = 1e-8;
  o.comparison = Comparison::absolute;
  o.note = fmt::format(
      "uniaxial strain, linear hardening, -8% then +4%: {} steps, {:.1e}; pure shear to 0.35, Al 6061 power law, "
      "dt 0: {} steps, {:.1e}; pure shear at 1e4/s, 4340 JC at 600 K: {} steps, {:.1e}",
      a.steps, a.worst, b.steps, b.worst, c.steps, c.worst);
  return compare(o);
}

}  // namespace kessler::verify
