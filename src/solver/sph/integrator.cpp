#include "solver/sph/integrator.hpp"

#include "core/error.hpp"
#include "solver/common/body_laws.hpp"
#include "solver/common/stable_step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <omp.h>

namespace kessler::sph {

namespace {

// A particle's work in a step, in pairs: its pairs' kernel, force and deformation terms go by the
// pair, its material update, erosion and time step by the particle (about as much as 9 pairs).
constexpr double pairs_per_particle = 9.0;

constexpr const char* elsewhere = "stopped: a particle of another rank failed (that rank reports it)";

}  // namespace

Integrator::Integrator(Model& model, const Settings& settings, Distribution* distribution)
    : model_(model),
      settings_(settings),
      distribution_(distribution),
      reconstruction_(model),
      elements_(settings.sph.element_share, settings.sph.element_min_quality),
      erosion_(settings.solver.erosion_radius),
      release_(settings.solver.erosion_radius) {
  KESSLER_VERIFY(settings.solver.cfl > 0.0 && settings.solver.cfl <= 1.0, "cfl must lie in (0, 1], got {}",
                 settings.solver.cfl);
  KESSLER_VERIFY(settings.solver.end_time > 0.0, "end_time must be positive, got {}", settings.solver.end_time);
  KESSLER_VERIFY(model.constrained.size() == model.points.x.size() &&
                     model.prescribed_v.size() == model.points.x.size() &&
                     model.viscosity.size() == model.points.x.size(),
                 "{} constraints and {} viscosities for {} particles", model.constrained.size(), model.viscosity.size(),
                 model.points.x.size());
  KESSLER_VERIFY(settings.sph.element_share >= 0.0 && settings.sph.element_share <= 1.0,
                 "element_share must lie in [0, 1], got {}", settings.sph.element_share);
  KESSLER_VERIFY(settings.sph.viscosity_min >= 0.0 && settings.sph.viscosity_min <= settings.sph.viscosity_max,
                 "viscosity coefficients: need 0 <= min {} <= max {}", settings.sph.viscosity_min,
                 settings.sph.viscosity_max);
}

void Integrator::initialise() {
  PointStore& points = model_.points;
  body_points_ = bodyRanges(points.body, points.owned, model_.bodies.size());
  for (std::size_t b = 0; b < model_.bodies.size(); ++b)
    model_.materials[model_.bodies[b].material]->initialise(points, body_points_[b].begin, body_points_[b].end);
  {
    ScopedPhase phase(timers_, "constitutive");
    updateMaterials(0.0);
  }
  volume_rate_.assign(static_cast<std::size_t>(points.owned), 0.0);
  if (distribution_) split();
  search();
  reconstruction_.rebuild(model_);
  forces();
  volume_rate_.assign(static_cast<std::size_t>(points.owned), 0.0);
  clock_.dt_next = clock_.dt_initial = stableStep();
}

void Integrator::restore(const Clock& clock, LocalIndex distorted, double stored) {
  body_points_ = bodyRanges(model_.points.body, model_.points.owned, model_.bodies.size());
  clock_ = clock;
  distorted_ = distorted;
  stored_ = stored;
  reconstruction_ = Reconstruction(model_);  // the restored elements
  elements_.renumbered();
  volume_rate_.assign(static_cast<std::size_t>(model_.points.owned), 0.0);
  if (distribution_) split();
  search();
  reconstruction_.rebuild(model_);
  forces();
}

void Integrator::adopt(const Clock& clock, LocalIndex distorted, double stored) {
  body_points_ = bodyRanges(model_.points.body, model_.points.owned, model_.bodies.size());
  clock_ = clock;
  distorted_ = distorted;
  stored_ = stored;
  reconstruction_.rebuild(model_);
}

// Every rank holds the whole model (built or restored alike); each keeps its part, with the reach of
// every particle's lattice neighbours measured while it holds them all.
void Integrator::split() {
  lattice_reach_ = latticeReach(true);
  distribution_->split(model_, {volume_rate_, lattice_reach_});
}

// The reach of each particle's lattice neighbours (its own element's), or with the elements' share
// of the deviator, of four rings of them: an own particle's force reads the nodes two rings away,
// whose hexahedra's nodes are placed by particles two rings further (ElementGradient).
std::vector<double> Integrator::latticeReach(bool whole) const {
  const Share own = whole ? Share{} : share();
  std::vector<double> reach = reconstruction_.latticeReach(model_, own);
  if (elements_.share() > 0.0)
    for (int ring = 2; ring <= 4; ++ring) {
      if (!whole) distribution_->refresh(reach);
      reach = reconstruction_.extendReach(model_, reach, own);
    }
  return reach;
}

// The ghosts the next search needs: each own particle is sent as far as any other rank's particle
// may pair with it (its smoothing length and the largest), and an intact one as far as an erosion
// ball reaches and its lattice neighbours lie (so that a rank holds every intact neighbour of its own
// intact elements: their nodes are rebuilt as on one process).
void Integrator::rebuildHalo() {
  ScopedPhase phase(timers_, "halo");
  const PointStore& points = model_.points;
  const Share own = share();
  double h_max = 0.0, ball = 0.0;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (!own.own(p)) continue;
    h_max = std::max(h_max, smoothingLength(p));
    if (!points.broken[p]) ball = std::max(ball, settings_.solver.erosion_radius * points.spacing(p));
  }
  h_max = own.max(h_max);
  ball = own.max(ball);
  std::vector<double> work;
  if (pairs_.offset.size() == static_cast<std::size_t>(points.owned) + 1) {
    work.resize(static_cast<std::size_t>(points.owned));
    for (LocalIndex i = 0; i < points.owned; ++i)
      work[i] = pairs_per_particle + static_cast<double>(pairs_.offset[i + 1] - pairs_.offset[i] +
                                                         pairs_.listed_offset[i + 1] - pairs_.listed_offset[i]);
  }
  const auto reach = [&](LocalIndex p) {
    const double pairs = smoothingLength(p) + h_max;
    return points.broken[p] ? pairs : std::max({pairs, ball, lattice_reach_[p]});
  };
  if (distribution_->rebuild(model_, {volume_rate_, lattice_reach_}, work, reach)) {
    reconstruction_ = Reconstruction(model_);  // the elements of the particles held now
    elements_.renumbered();
  }
  body_points_ = bodyRanges(points.body, points.owned, model_.bodies.size());
}

void Integrator::step() {
  const double dt = std::min(clock_.dt_next, settings_.solver.end_time - clock_.time);
  KESSLER_VERIFY(dt > 0.0, "step called after the end time");
  PointStore& points = model_.points;
  try {
    {
      ScopedPhase phase(timers_, "point update");
      const double dt_kick = 0.5 * (clock_.dt_last + dt);
      const bool artificial = settings_.sph.artificial_stress > 0.0;
      if (artificial) artificial_work_.resize(static_cast<std::size_t>(points.owned));
#pragma omp parallel for schedule(static)
      for (LocalIndex p = 0; p < points.owned; ++p) {
        const Vec3 before = points.v[p];
        points.v[p] += dt_kick * acceleration_[p];
        // (A wall meets the particle's cell, as RKPM's: docs/theory.md §10.)
        imposeBoundaries(model_.constrained[p], model_.prescribed_v[p], settings_.walls, points.x[p], dt, points.v[p],
                         particle_reach * points.spacing0[p]);
        if (artificial) artificial_work_[p] = dt_kick * artificial_force_[p].dot(0.5 * (before + points.v[p]));
      }
      // The artificial stress is no stress of the material, and no law books its work: the kinetic
      // energy its forces gave over the kick (at the kick's mean velocity, exactly the leapfrog's) comes
      // out of the store (an exact sum over own particles and every rank).
      if (artificial) stored_ -= ownSum(share(), points.owned, [&](LocalIndex p) { return artificial_work_[p]; });
      deform(dt);
    }
    {
      ScopedPhase phase(timers_, "constitutive");
      updateMaterials(dt);
    }
    {
      ScopedPhase phase(timers_, "erosion");
      // (The lattice reach before this step's failures: a particle that fails now counts as intact.)
      if (distribution_) lattice_reach_ = latticeReach(false);
      reconstruction_.rebuild(model_);
      distorted_ += reconstruction_.failDistorted(model_, settings_.sph.element_min_quality, share());
      erosion_.apply(model_, share());
      release_.apply(model_, share());
    }
    search();
    forces();
  } catch (const NumericalError& e) {
    throw NumericalError(fmt::format("step {}, t = {:.6g} s: {}", clock_.steps + 1, clock_.time, e.what()));
  }
  clock_.advance(dt);
  ScopedPhase phase(timers_, "time step");
  clock_.dt_next = stableStep();
}

double Integrator::smoothingLength(LocalIndex p) const {
  return smoothingLength(p, model_.points.spacing(p));
}

double Integrator::smoothingLength(LocalIndex p, double spacing) const {
  const double h0 = settings_.sph.smoothing * model_.points.spacing0[p];
  return std::clamp(settings_.sph.smoothing * spacing, 0.1 * h0, 2.0 * h0);
}

double Integrator::meanNeighbours() const {
  const Share own = share();
  std::int64_t pairs = 0, particles = 0;
  for (LocalIndex i = 0; i < model_.points.owned; ++i) {
    if (!own.own(i)) continue;
    pairs += pairs_.offset[i + 1] - pairs_.offset[i] + pairs_.listed_offset[i + 1] - pairs_.listed_offset[i];
    ++particles;
  }
  pairs = own.sum(pairs);
  particles = own.sum(particles);
  return particles > 0 ? static_cast<double>(pairs) / static_cast<double>(particles) : 0.0;
}

// The corrected gradient of a particle vector field u at particle i over the active pairs (the
// velocity's or the acceleration's): sum_j V_j (u_j - u_i) (x) grad_i W_ij B_i.
Mat3 Integrator::gradientOf(LocalIndex i, std::span<const Vec3> u) const {
  const PointStore& points = model_.points;
  const Mirrors& mirrors = pairs_.mirrors();
  lanes::OuterSum gradient;
  const lanes::V ui = lanes::load(u[i]);
  pairs_.forEachOf(i, points.x, [&](LocalIndex j, std::uint8_t m, lanes::V, lanes::V grad, bool active) {
    if (!active) return;
    // (An image's vector reflected apart: a load of a vector just stored would wait for the stores.)
    const lanes::V uj = m == 0 ? lanes::load(u[j]) : lanes::load(mirrors.vector(u[j], m));
    gradient.add(lanes::times(points.volume[j], lanes::minus(uj, ui)), grad);
  });
  return gradient.matrix() * correction_[i];
}

// Step 2: each particle's deformation over the step from the kicked velocities, then the drift
// (two passes: the first reads the volumes and velocities that the second changes).
void Integrator::deform(double dt) {
  PointStore& points = model_.points;
  volume_rate_.resize(static_cast<std::size_t>(points.owned));
  const Share own = share();
  LocalIndex bad = points.owned;
  elements_.moveNodes(points.v, pairs_.mirrors());
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (LocalIndex i = 0; i < points.owned; ++i) {
    if (!own.own(i)) continue;  // a ghost's deformation is its owner's (refreshed below)
    points.dF[i].setIdentity();
    if (points.debris(i)) continue;
    Mat3 L = gradientOf(i, points.v);
    if (elements_.takesPart(i)) L = elements_.blend(i, L);
    switchViscosity(i, L, dt);
    const Mat3 half = 0.5 * dt * L;
    const Mat3 dF = (Mat3::Identity() - half).inverse() * (Mat3::Identity() + half);
    const double J = dF.determinant();
    if (J > 0.0 && std::isfinite(J))
      points.dF[i] = dF;
    else if (points.failed(i))
      points.carrier[i] = -1;  // failed material crushed through itself is debris (as in OTM, docs/theory.md §8)
    else
      bad = std::min(bad, i);
  }
  own.stopTogether(
      bad < points.owned, [&] { failAtPoint(bad, "volume inverted or collapsed over the step (det dF <= 0)"); },
      elsewhere);
#pragma omp parallel for schedule(static)
  for (LocalIndex i = 0; i < points.owned; ++i) {
    if (!own.own(i)) continue;
    points.x[i] += dt * points.v[i];
    if (points.debris(i)) {
      points.stress[i].setZero();
      points.viscous_pressure[i] = 0.0;
      volume_rate_[i] = 0.0;
      continue;
    }
    const double J = points.dF[i].determinant();
    points.F[i] = points.dF[i] * points.F[i];
    points.volume[i] *= J;
    volume_rate_[i] = std::log(J) / dt;
  }
  // A ghost's deformation, drift and viscosity coefficient are its owner's, before the material
  // update (its velocity gradient would lack the pairs this rank does not hold).
  if (distribution_) distribution_->refresh(model_);
}

// The viscosity switch (docs/theory.md §10), after Cullen & Dehnen (MNRAS 408:669, 2010, §2.3): alpha
// rises at once to its local target as a shock arrives, and decays towards it (at least alpha_min) at
// the rate decay c / h, implicitly. The target is alpha_max A / (A + c^2 + H^2 tr(L L)+), H = 2h the
// kernel's reach and A = xi H^2 max(-div a, 0), where the flow compresses: the rate at which the
// forces raise the compression. Its kinematic part -tr(L L), which steepens a smooth convergent flow
// no force acts on (Noh's cold inflow), is left out of A and weighs against it. xi = div^2 / (div^2 +
// |curl v|^2) keeps it off where the flow turns more than it compresses (Balsara, J. Comput. Phys.
// 121:357, 1995). A particle that touches another body takes alpha_max: the velocity jumps across a
// contact, before any force has acted.
void Integrator::switchViscosity(LocalIndex i, const Mat3& L, double dt) {
  const SphOptions& o = settings_.sph;
  const double div_v = L.trace(), c = model_.points.sound_speed[i], reach = 2.0 * h_[i];
  double target = o.viscosity_min;
  if (touches_[i] != 0) {
    target = o.viscosity_max;
  } else if (-div_v * h_[i] > 1e-4 * c) {
    // (Compression slower than this, such as round-off in matter at rest, would reach a target of
    // about 4e-4 at a shock's rise, -div a ~ -div v U_s / h: not evaluated.)
    const double rise = -gradientOf(i, acceleration_).trace();
    if (rise > 0.0) {
      const Vec3 curl(L(2, 1) - L(1, 2), L(0, 2) - L(2, 0), L(1, 0) - L(0, 1));
      const double xi = div_v * div_v / (div_v * div_v + curl.squaredNorm());
      const double A = xi * rise * reach * reach;
      const double steepening = std::max((L * L).trace(), 0.0) * reach * reach;
      target = std::max(target, o.viscosity_max * A / (A + c * c + steepening));
    }
  }
  double& alpha = model_.viscosity[i];
  if (alpha < target) {
    alpha = target;
  } else {
    const double decay = o.viscosity_decay * c / h_[i];  // 1 / tau
    alpha = (alpha + dt * decay * target) / (1.0 + dt * decay);
  }
}

void Integrator::updateMaterials(double dt) {
  PointStore& points = model_.points;
  if (dt > 0.0) {
    heat_.resize(static_cast<std::size_t>(points.owned));
    for (LocalIndex p = 0; p < points.owned; ++p) heat_[p] = heating_[p] * dt;
    heatBodies(model_, body_points_, heat_);
    // The laws heat no debris (it has no thermal update): its share is kept as internal energy, so
    // that a debris cloud's collisions conserve energy.
    for (LocalIndex p = 0; p < points.owned; ++p)
      if (points.debris(p)) points.energy[p] += heat_[p] / points.mass[p];
    // A law without a thermal state takes none: its share is booked apart (an exact sum over own
    // particles and every rank).
    std::vector<std::uint8_t> athermal(model_.bodies.size());
    for (std::size_t b = 0; b < athermal.size(); ++b)
      athermal[b] = !model_.materials[model_.bodies[b].material]->takesHeat();
    if (std::find(athermal.begin(), athermal.end(), 1) != athermal.end())  // the same on every rank
      stored_ += ownSum(share(), points.owned, [&](LocalIndex p) {
        return points.debris(p) || !athermal[static_cast<std::size_t>(points.body[p])] ? 0.0 : heat_[p];
      });
  }
  // SPH's viscosity is its own: the laws' bulk viscosity stays off (limiter 1).
  std::fill(points.viscosity_limiter.begin(), points.viscosity_limiter.end(), 1.0);
  const Share own = share();
  LocalIndex failed = -1;
  std::string why;
  try {
    updateBodies(model_, body_points_, dt);
  } catch (const PointError& e) {
    failed = static_cast<LocalIndex>(e.point());
    why = e.what();
  }
  own.stopTogether(
      failed >= 0, [&] { failAtPoint(failed, why); }, elsewhere);
  LocalIndex bad = points.owned;
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (LocalIndex p = 0; p < points.owned; ++p)
    if (own.own(p) && (!points.stress[p].allFinite() || !std::isfinite(points.energy[p]) ||
                       !(points.debris(p) || points.sound_speed[p] >= 0.0)))
      bad = std::min(bad, p);
  own.stopTogether(
      bad < points.owned,
      [&] { failAtPoint(bad, "the material update gave a non-finite stress, energy or sound speed"); }, elsewhere);
}

// Monaghan's stable step (Monaghan, Annu. Rev. Astron. Astrophys. 30:543, 1992):
// dt = cfl min_i h_i / (c_i + 1.2 (alpha c_i + beta mu_i)), mu_i the largest viscous signal of its
// pairs, and no particle's volume changing by more than cfl/3 in a step (as OTM's,
// solver/common/stable_step.hpp).
double Integrator::stableStep() const {
  const PointStore& points = model_.points;
  const SphOptions& o = settings_.sph;
  const Share own = share();
  double dt = std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static) reduction(min : dt)
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (!own.own(p)) continue;
    const double c = points.debris(p) ? 0.0 : points.sound_speed[p];
    // With the largest coefficients: a particle's alpha may rise within the step.
    const double signal = c + 1.2 * o.viscosity_max * (c + o.viscosity_ratio * signal_[p]);
    if (signal > 0.0) dt = std::min(dt, h_[p] / signal);
    if (volume_rate_[p] != 0.0) dt = std::min(dt, 1.0 / (3.0 * std::abs(volume_rate_[p])));
  }
  dt = own.min(dt);
  KESSLER_VERIFY(  // (the largest double: nothing bounded it, solver/common/stable_step.hpp)
      std::isfinite(dt) && dt > 0.0 && dt < std::numeric_limits<double>::max(),
      "no stable time step: every particle is debris or at rest without a sound speed, or the model is empty");
  return settings_.solver.cfl * dt;
}

Energies Integrator::energies() const {
  return pointEnergies(model_.points, stored_, share());
}

void Integrator::failAtPoint(LocalIndex p, const std::string& what) const {
  const PointStore& points = model_.points;
  const Vec3& x = points.x[p];
  throw NumericalError(fmt::format("particle {} of body '{}' at ({:.6g}, {:.6g}, {:.6g}) m: {}", points.id[p],
                                   model_.bodies[points.body[p]].name, x[0], x[1], x[2], what));
}

}  // namespace kessler::sph
