#include "solver/common/point_diagnostics.hpp"

#include "solver/common/own_sums.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace kessler {
namespace {

constexpr LocalIndex block = 2048;  // points per partial energy sum

bool pointHealthy(const PointStore& s, LocalIndex p) {
  return s.x[p].allFinite() && s.v[p].allFinite() && s.stress[p].allFinite() && std::isfinite(s.energy[p]) &&
         std::isfinite(s.volume[p]) && s.volume[p] > 0.0;
}

// The first unhealthy quantity of point p, named and with its value.
std::string pointProblem(const PointStore& s, LocalIndex p) {
  if (!s.x[p].allFinite()) return fmt::format("non-finite position {}", describeVector(s.x[p]));
  if (!s.v[p].allFinite()) return fmt::format("non-finite velocity v = {} m/s", describeVector(s.v[p]));
  if (!s.stress[p].allFinite()) {
    const Mat3& t = s.stress[p];
    return fmt::format("non-finite stress (diagonal {:.6g}, {:.6g}, {:.6g} Pa)", t(0, 0), t(1, 1), t(2, 2));
  }
  if (!std::isfinite(s.energy[p])) return fmt::format("non-finite specific internal energy e = {} J/kg", s.energy[p]);
  return fmt::format("volume collapsed or non-finite: V = {:.6g} m^3 (initially {:.6g} m^3)", s.volume[p],
                     s.volume0[p]);
}

}  // namespace

std::string describeStep(const StepInfo& at) {
  return fmt::format("step {}, t = {:.6g} s", at.step, at.time);
}

std::string describeVector(const Vec3& v) {
  return fmt::format("({:.6g}, {:.6g}, {:.6g})", v[0], v[1], v[2]);
}

std::string describePoint(const ParticleState& state, const StepInfo& at, LocalIndex p, const std::string& what) {
  const PointStore& s = state.points;
  const auto body = static_cast<std::size_t>(s.body[p]);
  return fmt::format("{}: material point {} of body '{}' at {} m: {}", describeStep(at), s.id[p],
                     body < state.bodies.size() ? state.bodies[body].name : "?", describeVector(s.x[p]), what);
}

void PointDiagnostics::check(const ParticleState& state, const StepInfo& at, double reference_energy,
                             const StepLengthRule& rule, const std::function<bool()>& driven, const Share& share) {
  checkPoints(state, at, share);
  checkTimeStep(state, at, rule);
  checkEnergy(state, at, reference_energy, driven);
}

// The finiteness checks (the lowest failing index) and the total energy (an exact sum), the same
// for any number of threads and, over own points, ranks.
void PointDiagnostics::checkPoints(const ParticleState& state, const StepInfo& at, const Share& share) {
  const PointStore& s = state.points;
  const LocalIndex n = s.owned;
  LocalIndex bad = n;
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (LocalIndex p = 0; p < n; ++p)
    if (share.own(p) && !pointHealthy(s, p)) bad = std::min(bad, p);
  if (bad < n) throw NumericalError(describePoint(state, at, bad, pointProblem(s, bad)));
  // Internal energy by its size: under the compatible energy update a spurious source shows as
  // kinetic energy gained and a point cooled below zero (docs/theory.md §4 step 5).
  energy_ =
      ownSum(share, n, [&](LocalIndex p) { return s.mass[p] * (0.5 * s.v[p].squaredNorm() + std::abs(s.energy[p])); });
}

void PointDiagnostics::checkTimeStep(const ParticleState& state, const StepInfo& at, const StepLengthRule& rule) const {
  const double floor = settings_.min_dt_fraction * at.dt_initial;
  if (settings_.min_dt_fraction <= 0.0 || at.dt_next >= floor || state.points.owned == 0) return;
  // Name the point that sets the step: the smallest l / c, lowest index on a tie.
  const PointStore& s = state.points;
  std::vector<double> ratio(s.owned, std::numeric_limits<double>::infinity());
#pragma omp parallel for schedule(static)
  for (LocalIndex p = 0; p < s.owned; ++p)
    if (!s.debris(p)) ratio[p] = rule.length(p) / s.sound_speed[p];
  const auto limiting = static_cast<LocalIndex>(std::min_element(ratio.begin(), ratio.end()) - ratio.begin());
  throw NumericalError(describePoint(
      state, at, limiting,
      fmt::format("time step collapsed: dt = {:.6g} s is below min_dt_fraction {:.6g} of the initial {:.6g} s "
                  "(this point sets it: length {:.6g} m, {}; sound speed c = {:.6g} m/s, volume V/V0 = {:.6g})",
                  at.dt_next, settings_.min_dt_fraction, at.dt_initial, rule.length(limiting), rule.origin(limiting),
                  s.sound_speed[limiting], s.volume[limiting] / s.volume0[limiting])));
}

void PointDiagnostics::checkEnergy(const ParticleState& state, const StepInfo& at, double reference_energy,
                                   const std::function<bool()>& driven) const {
  if (!(reference_energy > 0.0) || energy_ <= (1.0 + settings_.max_energy_growth) * reference_energy ||
      state.points.owned == 0 || driven())
    return;
  // Name the point with the largest specific energy, where a spurious source usually shows.
  const PointStore& s = state.points;
  double largest = -std::numeric_limits<double>::infinity();
  auto specific = [&](LocalIndex p) { return 0.5 * s.v[p].squaredNorm() + std::abs(s.energy[p]); };
#pragma omp parallel for schedule(static) reduction(max : largest)
  for (LocalIndex p = 0; p < s.owned; ++p) largest = std::max(largest, specific(p));
  LocalIndex hottest = 0;
  while (hottest + 1 < s.owned && specific(hottest) < largest) ++hottest;
  throw NumericalError(describePoint(
      state, at, hottest,
      fmt::format("energy grew without a source: total energy = {:.6g} J exceeds the initial {:.6g} J by {:.3g}% "
                  "(max_energy_growth {:.3g}%); this point has the largest specific energy, {:.6g} J/kg "
                  "(speed {:.6g} m/s, internal {:.6g} J/kg)",
                  energy_, reference_energy, 100.0 * (energy_ / reference_energy - 1.0),
                  100.0 * settings_.max_energy_growth, largest, s.v[hottest].norm(), s.energy[hottest])));
}

}  // namespace kessler
