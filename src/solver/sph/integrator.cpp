#include "solver/sph/integrator.hpp"

#include "core/error.hpp"
#include "core/transpose.hpp"
#include "solver/common/body_laws.hpp"
#include "solver/common/stable_step.hpp"
#include "solver/sph/kernel.hpp"

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include <omp.h>

namespace kessler::sph {

namespace {

// Particles of different bodies (or debris) start to interact when the gap between their elements
// (each reaching half a spacing from its particle) closes to half a spacing, as OTM's seizing
// contact at its default contact_distance (docs/theory.md §10).
constexpr double contact_gap = 0.5;

// Pair::active's bit, during the search, of a pair across bodies that lies beyond touching but
// within the kernel: it takes part only if one of its ends touches the other's body.
constexpr std::uint8_t through_contact = 4;

std::uint32_t bodyBit(int body) {
  return std::uint32_t{1} << (static_cast<unsigned>(body) % 32u);
}

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

// The pairs at the current positions; which take part in the deformation, the stress and the
// viscosity (those within a body always; across bodies, or with debris, while the two lie within
// `contact_gap` spacings of touching and either approach or are both under pressure: bodies in
// contact push and shear each other as one body, and part freely once their pressure is released,
// never pulled together, and no body feels another across a gap, pressed or not). Once a particle
// touches another body so, its other pairs with that body within the kernel take part too (while
// they approach or are pressed), as within one body: a contact's particles see the other body as far
// as they see their own, and their own pressure does not push them into it, as it pushes a free
// surface's particles outwards. A pair of intact and failed material takes part from its failed
// end only (docs/theory.md §10): the failed particle's velocity gradient counts the intact one and
// its pressure acts on both, but the intact particle's deformation and stress ignore failed
// material, as at a free surface (its fractured neighbours' flow does not strain it). The kernel
// correction B_i over the pairs i takes part in.
void Integrator::search() {
  if (distribution_) rebuildHalo();
  ScopedPhase phase(timers_, "search");
  const Share own = share();
  PointStore& points = model_.points;
  const auto n = static_cast<std::size_t>(points.owned);
  h_.resize(n);
  spacing_.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t p = 0; p < n; ++p) {
    spacing_[p] = points.spacing(static_cast<LocalIndex>(p));
    h_[p] = smoothingLength(static_cast<LocalIndex>(p), spacing_[p]);
  }
  struck_.assign(n, -1);
  correction_.resize(n);
  touches_.assign(n, 0);
  // Which ends of a pair take part (Pair::active): once per pair, those across bodies beyond touching
  // marked `through_contact` until every particle's contacts are known (below).
  std::atomic<bool> through{false};
  pairs_.build(points.x, h_, points.owned, settings_.mirrors, own,
               [&](LocalIndex i, LocalIndex j, std::uint8_t m, const Vec3& d) -> std::uint8_t {
                 const auto ends = [&]() -> std::uint8_t {
                   const bool failed_i = points.failed(i), failed_j = points.failed(j);
                   if (failed_i == failed_j || points.debris(i) || points.debris(j)) return 3;
                   return failed_i ? 1 : 2;  // failed and intact
                 };
                 // (Most pairs lie within a body: the other ends' velocity and stress are read only
                 // for the rest.)
                 if (points.body[i] == points.body[j] && !points.debris(i) && !points.debris(j)) return ends();
                 const double touching = (1.0 + contact_gap) * 0.5 * (spacing_[i] + spacing_[j]);
                 const bool close = d.squaredNorm() < touching * touching;
                 const bool debris = points.debris(i) || points.debris(j);
                 if (!close && debris) return 0;
                 const bool approaching = (points.v[i] - pairs_.mirrors().vector(points.v[j], m)).dot(d) < 0.0;
                 const bool pressed = points.stress[i].trace() < 0.0 && points.stress[j].trace() < 0.0;
                 if (!approaching && !pressed) return 0;
                 if (!close) {
                   through.store(true, std::memory_order_relaxed);
                   return static_cast<std::uint8_t>(ends() | through_contact);
                 }
                 if (!debris) {  // i touches j's body and j i's (an OR: the same in any order)
                   std::atomic_ref(touches_[i]).fetch_or(bodyBit(points.body[j]), std::memory_order_relaxed);
                   std::atomic_ref(touches_[j]).fetch_or(bodyBit(points.body[i]), std::memory_order_relaxed);
                 }
                 return ends();
               });
  // A pair beyond touching takes part where one end touches the other's body (a ghost's contacts are
  // its owner's: this rank may not hold the pair that makes one).
  if (distribution_) distribution_->refresh(touches_);
  if (own.any(through.load())) {
#pragma omp parallel for schedule(static)
    for (LocalIndex i = 0; i < points.owned; ++i)
      for (Index e = pairs_.offset[i]; e < pairs_.offset[i + 1]; ++e) {
        Pair& pair = pairs_.pair[e];
        if (!(pair.active & through_contact)) continue;
        const LocalIndex j = pair.other;
        const bool contact = (touches_[i] & bodyBit(points.body[j])) || (touches_[j] & bodyBit(points.body[i]));
        pair.active = contact ? static_cast<std::uint8_t>(pair.active & ~through_contact) : std::uint8_t{0};
      }
  }
  std::int64_t uncorrected = 0;
#pragma omp parallel for schedule(static) reduction(+ : uncorrected)
  for (LocalIndex i = 0; i < points.owned; ++i) {
    if (!own.own(i)) continue;  // a ghost's correction is its owner's (refreshed below)
    lanes::OuterSum sum;
    pairs_.forEachOf(i, points.x, [&](LocalIndex j, std::uint8_t, lanes::V d, lanes::V grad, bool active) {
      if (!active) return;
      sum.subtract(lanes::times(points.volume[j], d), grad);
      if (points.debris(i) && !points.debris(j) && points.body[j] != points.body[i]) struck_[i] = points.body[j];
    });
    const Mat3 moment = sum.matrix();
    // The correction where the moment is well conditioned: its smallest singular value at least a
    // tenth of an interior particle's (1), as at a surface, an edge or a corner of a body. Near the
    // identity, as within a body, that needs no eigenvalue: the smallest singular value of M is at
    // least 1 - |M - I|_2 >= 1 - |M - I|_F (0.15 and more where |M - I|_F < 0.85).
    const auto well_conditioned = [](const Mat3& M) {
      return (M - Mat3::Identity()).squaredNorm() < 0.85 * 0.85 || smallestRootEigenvalue(M.transpose() * M) > 0.1;
    };
    if (!points.debris(i) && moment.allFinite() && well_conditioned(moment)) {
      correction_[i] = moment.inverse();
    } else {
      correction_[i].setIdentity();
      uncorrected += points.debris(i) ? 0 : 1;
    }
  }
  uncorrected_ = static_cast<LocalIndex>(own.sum(uncorrected));
  // A ghost's correction lacks the pairs this rank does not hold: its owner's replaces it.
  if (distribution_) distribution_->refresh(correction_);
  // A debris particle that met another body strikes it (the rear-wall analysis counts those): after
  // the loop, which reads every particle's state.
  for (LocalIndex i = 0; i < points.owned; ++i)
    if (struck_[i] >= 0) points.strike(i, struck_[i]);
}

// The forces at the current state (docs/theory.md §10): the stress's over the active pairs, Monaghan's
// viscosity over the pairs that approach, and the artificial stress within intact material.
void Integrator::forces() {
  ScopedPhase phase(timers_, "assembly");
  const PointStore& points = model_.points;
  const Mirrors& mirrors = pairs_.mirrors();
  const SphOptions& o = settings_.sph;
  // (A + T B) g for the tensors A of i and B of j seen from i, on whole columns in AVX lanes, loaded
  // from where they lie (a 3 x 3 sum stored and read back by columns would stall each load that
  // straddles two stores: only an image's tensor is formed first).
  const auto sumTimes = [&](const Mat3& A, const Mat3& B, std::uint8_t m, const Vec3& g) -> Vec3 {
    return lanes::vec3(m == 0 ? lanes::sumTimes(A, B, g) : lanes::sumTimes(A, mirrors.tensor(B, m), g));
  };
  const Mat3 zero = Mat3::Zero();
  const auto n = static_cast<std::size_t>(points.owned);
  acceleration_.resize(n);
  heating_.resize(n);
  artificial_force_.resize(n);
  signal_.resize(n);
  // Per particle, what a pair reads of either end, in one record (a pair's other end is near in
  // space, not in memory: its record is three cache lines where a dozen arrays were a dozen): among
  // them sigma B^T, the density and the sound speed the viscosity uses (none for debris); and apart,
  // the artificial stress R (tensile principal stresses only; `tensile` where it is not zero).
  ends_.resize(n);
  artificial_.resize(n);
  elements_.update(model_, reconstruction_, mirrors, touches_, distribution_ ? distribution_->layout() : 0);
#pragma omp parallel for schedule(static)
  for (LocalIndex p = 0; p < points.owned; ++p) {
    PairEnd& end = ends_[p];
    end.stress_b = elements_.pairStress(p, points.stress[p]) * correction_[p].transpose();
    end.x = points.x[p];
    end.v = points.v[p];
    end.volume = points.volume[p];
    end.mass = points.mass[p];
    end.density = points.density(p);
    end.sound = points.debris(p) ? 0.0 : points.sound_speed[p];
    end.alpha = model_.viscosity[p];
    end.h = h_[p];
    end.spacing = spacing_[p];
    end.energy = points.energy[p];
    end.body = points.body[p];
    end.broken = points.broken[p];
    end.tensile = 0;
    Mat3& artificial = artificial_[p];
    artificial.setZero();
    if (points.broken[p] || o.artificial_stress <= 0.0) continue;
    // No principal stress is tensile where -sigma is positive definite (Sylvester's criterion: its
    // leading minors are positive) or sigma is zero, as in matter at rest or compressed: the
    // principal stresses are solved for only where one may be.
    const Mat3& sigma = points.stress[p];
    const bool compressed =
        sigma(0, 0) < 0.0 && sigma(0, 0) * sigma(1, 1) - sigma(0, 1) * sigma(1, 0) > 0.0 && sigma.determinant() < 0.0;
    if (compressed || sigma.isZero(0.0)) continue;
    Eigen::SelfAdjointEigenSolver<Mat3> principal;
    principal.computeDirect(points.stress[p]);
    const double rho2 = end.density * end.density;
    for (int a = 0; a < 3; ++a) {
      const double s = principal.eigenvalues()[a];
      if (s > 0.0) {
        const Vec3 e = principal.eigenvectors().col(a);
        artificial.noalias() -= o.artificial_stress * s / rho2 * e * e.transpose();
        end.tensile = 1;
      }
    }
  }
  // Each pair's force on its listing particle i, once: that on its other end j is -R times it (the
  // image of the reaction). The viscosity's heating and signal speed are the same at both ends, the
  // heat flux's opposite. Each particle's sums run over the pairs it lists, then over those that list
  // it, in their order (a ghost's are its owner's, refreshed below). The pairs that list i are those
  // of lower particles, so a thread that goes up its block of particles has them all at hand, just
  // computed (still in cache), once it has computed i's own: but for those a lower block lists,
  // summed after the barrier.
  const auto pairs = static_cast<std::size_t>(pairs_.size());
  pair_share_.resize(pairs);
  const Share own = share();
  const auto sumListed = [&](LocalIndex i, Vec3 f, double power, double signal) {
    for (Index k = pairs_.listed_offset[i]; k < pairs_.listed_offset[i + 1]; ++k) {
      const PairShare& share = pair_share_[pairs_.listed_by[k]];
      f -= mirrors.vector(share.force, pairs_.listed_mirror[k]);
      power += share.power - share.heat;
      signal = std::max(signal, share.signal);
    }
    acceleration_[i] = f / points.mass[i];
    heating_[i] = power;
    signal_[i] = signal;
  };
#pragma omp parallel
  {
    // Blocks of about equal numbers of pairs.
    const int t = omp_get_thread_num(), nt = omp_get_num_threads();
#pragma omp single
    artificial_reactions_.resize(static_cast<std::size_t>(nt));
    std::vector<std::pair<Index, Vec3>>& reactions = artificial_reactions_[static_cast<std::size_t>(t)];
    reactions.clear();
    const LocalIndex begin = entryBlockStart(pairs_.offset, t, nt), end = entryBlockStart(pairs_.offset, t + 1, nt);
    const auto listedHere = [&](LocalIndex i) {
      return pairs_.listed_offset[i] == pairs_.listed_offset[i + 1] ||
             pairs_.listed_other[pairs_.listed_offset[i]] >= begin;  // (the first is the lowest)
    };
    for (LocalIndex i = begin; i < end; ++i) {
      const PairEnd& a = ends_[i];
      Vec3 force = Vec3::Zero();
      double power = 0.0, signal = 0.0;
      Vec3 artificial_force = Vec3::Zero();
      for (Index e = pairs_.offset[i]; e < pairs_.offset[i + 1]; ++e) {
        const Pair& pair = pairs_.pair[e];
        const LocalIndex j = pair.other;
        const PairEnd& b = ends_[j];
        const std::uint8_t m = pair.mirror;
        const Vec3 d = a.x - mirrors.point(b.x, m);
        const Vec3 grad = pair.gradient(d);
        Vec3 f = Vec3::Zero();
        if (pair.active) {
          // (Either end's stress alone over a pair of intact and failed material.)
          const Mat3& stress_a = pair.active & 1 ? a.stress_b : zero;
          const Mat3& stress_b = pair.active & 2 ? b.stress_b : zero;
          f.noalias() += a.volume * b.volume * sumTimes(stress_a, stress_b, m, grad);
          if ((a.tensile || b.tensile) && a.body == b.body && !a.broken && !b.broken) {
            const double h_ij = 0.5 * (a.h + b.h);
            const double reference = CubicSpline::value(0.5 * (a.spacing + b.spacing), h_ij);
            // (The pair's kernel at |d|, as the search formed its gradient: only the pairs that need it.)
            const double kernel = CubicSpline::value(d.norm(), h_ij);
            const double ratio = reference > 0.0 ? std::min(kernel / reference, 1.0) : 0.0;
            double fn = 1.0;
            for (int k = 0; k < o.artificial_stress_exponent; ++k) fn *= ratio;
            const double scale = a.mass * b.mass * fn;
            const Vec3 stress = sumTimes(artificial_[i], artificial_[j], m, grad);
            for (int k = 0; k < 3; ++k) f[k] = std::fma(scale, stress[k], f[k]);  // (one rounding each)
            const Vec3 artificial = scale * stress;
            artificial_force += artificial;
            if (j != i) reactions.emplace_back(e, artificial);  // (a pair with its own image acts on i alone)
          }
        }
        PairShare& share = pair_share_[e];
        share.power = share.signal = share.heat = 0.0;
        const Vec3 v = a.v - mirrors.vector(b.v, m);
        const double approach = v.dot(d);
        if (approach < 0.0 && pair.active) {
          const double h_ij = 0.5 * (a.h + b.h);
          const double mu = h_ij * approach / (d.squaredNorm() + 0.01 * h_ij * h_ij);
          const double rho = 0.5 * (a.density + b.density);
          const double alpha = 0.5 * (a.alpha + b.alpha);
          const double viscosity = alpha * (-0.5 * (a.sound + b.sound) * mu + o.viscosity_ratio * mu * mu) / rho;
          const double mm = a.mass * b.mass;
          f.noalias() -= mm * viscosity * grad;
          share.power = 0.5 * mm * viscosity * v.dot(grad);
          share.signal = -mu;
          // The heat flux (docs/theory.md §10): alpha_u m_i m_j |v . r^| (u_i - u_j) / rho dW/dr into
          // i, down the specific internal energy's difference, and as much out of j.
          share.heat = -o.heat_conduction * approach * pair.slope * (a.energy - b.energy) * mm / rho;
        }
        share.force = f;
        force += f;
        power += share.power + share.heat;
        signal = std::max(signal, share.signal);
      }
      artificial_force_[i] = artificial_force;
      if (!own.own(i)) continue;
      if (listedHere(i)) {
        sumListed(i, force, power, signal);
      } else {  // (kept for after the barrier)
        acceleration_[i] = force;
        heating_[i] = power;
        signal_[i] = signal;
      }
    }
#pragma omp barrier
    for (LocalIndex i = begin; i < end; ++i)
      if (own.own(i) && !listedHere(i)) sumListed(i, acceleration_[i], heating_[i], signal_[i]);
  }
  // The artificial forces' reactions on the other ends, in the order of the listing particles (the
  // same for any thread count): the kick books their work (step()).
  for (const std::vector<std::pair<Index, Vec3>>& reactions : artificial_reactions_)
    for (const auto& [e, f] : reactions) {
      const Pair& pair = pairs_.pair[static_cast<std::size_t>(e)];
      artificial_force_[pair.other] -= mirrors.vector(f, mirrors.inverse(pair.mirror));
    }
  // The elements' share of the deviator, from their nodes (in the nodes' order: the same for any
  // thread count, and on every rank for the particles it owns).
  if (elements_.share() > 0.0) {
    element_force_.assign(n, Vec3::Zero());
    elements_.addForces(points, reconstruction_, mirrors, element_force_);
    for (LocalIndex p = 0; p < points.owned; ++p) acceleration_[p] += element_force_[p] / points.mass[p];
  }
  // A ghost's sums lack the pairs this rank does not hold (the kick and the heating read them).
  if (distribution_) {
    distribution_->refresh(acceleration_);
    distribution_->refresh(heating_);
  }
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
