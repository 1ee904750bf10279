// SPH's two passes over its pairs (docs/theory.md §10): the search, which lists the pairs, decides
// which of their ends take part and forms the kernel corrections; and the forces, from the stresses,
// the viscosity, the heat flux, the artificial stress and the elements' share. The rest of the step
// is integrator.cpp.
#include "core/error.hpp"
#include "core/transpose.hpp"
#include "solver/common/stable_step.hpp"
#include "solver/sph/integrator.hpp"
#include "solver/sph/kernel.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <atomic>
#include <cmath>

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

}  // namespace

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

}  // namespace kessler::sph
