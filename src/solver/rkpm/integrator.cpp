#include "solver/rkpm/integrator.hpp"

#include "core/error.hpp"
#include "solver/common/body_laws.hpp"
#include "solver/common/mirror.hpp"
#include "solver/common/stable_step.hpp"
#include "solver/common/viscosity_limiter.hpp"
#include "solver/rkpm/surface.hpp"
#include "solver/rkpm/wall_contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kessler::rkpm {

namespace {

// The lumped projection's passes that carry the particles' velocities onto the new coefficients at a
// kernel update (interpolatingCoefficients).
constexpr int update_passes = 8;
// The steps after a refused kernel update (no usable kernels on the present configuration) before the
// next is tried, doubled at each refusal.
constexpr std::int64_t update_retry = 20;
// Debris still in the kernels makes an update due at every this many steps (a pure function of the
// step count, so that a restored run makes the updates the run it continues made). Within 20 steps of
// at most cfl h / c each, debris moving at u relative to its body moves at most 20 cfl (u / c) h:
// 0.3 spacings at cfl 0.3 and u = c / 20. An update costs about seven steps of a 13,000-particle
// run (the rod deck), so this bounds its cost to a third of the run's.
constexpr std::int64_t debris_update_every = 20;

// Row I of the transpose: the rows J that list I, with their values, in the order of J.
Table<Vec3> transpose(const Table<Vec3>& t) {
  const LocalIndex n = t.rows();
  Table<Vec3> out;
  out.offset.assign(static_cast<std::size_t>(n) + 1, 0);
  for (const LocalIndex i : t.column) ++out.offset[static_cast<std::size_t>(i) + 1];
  for (std::size_t r = 0; r < static_cast<std::size_t>(n); ++r) out.offset[r + 1] += out.offset[r];
  out.column.resize(t.column.size());
  out.mirror.resize(t.mirror.size());
  out.value.resize(t.value.size());
  std::vector<LocalIndex> cursor(out.offset.begin(), out.offset.end() - 1);
  for (LocalIndex j = 0; j < n; ++j)
    for (LocalIndex e = t.offset[j]; e < t.offset[j + 1]; ++e) {
      const auto slot = static_cast<std::size_t>(cursor[t.column[static_cast<std::size_t>(e)]]++);
      out.column[slot] = j;
      out.mirror[slot] = t.mirror[static_cast<std::size_t>(e)];
      out.value[slot] = t.value[static_cast<std::size_t>(e)];
    }
  return out;
}

}  // namespace

Integrator::Integrator(Model& model, const Settings& settings)
    : model_(model),
      settings_(settings),
      erosion_(settings.solver.erosion_radius),
      release_(settings.solver.erosion_radius, DebrisRelease::Velocities::interpolated),
      contact_(settings.solver.contact.friction, false) {
  KESSLER_VERIFY(settings.solver.cfl > 0.0 && settings.solver.cfl <= 1.0, "cfl must lie in (0, 1], got {}",
                 settings.solver.cfl);
  KESSLER_VERIFY(settings.solver.end_time > 0.0, "end_time must be positive, got {}", settings.solver.end_time);
  KESSLER_VERIFY(settings.rkpm.support > 1.0, "the RKPM support must exceed one spacing, got {}",
                 settings.rkpm.support);
  const std::size_t n = model.points.x.size();
  KESSLER_VERIFY(model.constrained.size() == n && model.prescribed_v.size() == n && model.reference.size() == n &&
                     model.coefficient_x.size() == n && model.coefficient_v.size() == n &&
                     model.cell_volume.size() == n,
                 "RKPM's arrays do not match its {} particles", n);
}

// The reference configuration's kernels, masses and collocation: a pure function of the model, so
// that a restored run has the same as the run that wrote it.
void Integrator::prepare() {
  PointStore& points = model_.points;
  const auto n = static_cast<std::size_t>(points.owned);
  body_points_ = bodyRanges(points.body, points.owned, model_.bodies.size());
  std::vector<double> support(n);
  // The support follows the spacing of the kernels' reference configuration: after a kernel update,
  // the first spacing times the largest principal stretch then, so that it still reaches two spacings
  // along the most stretched direction (and more along the others).
  for (std::size_t p = 0; p < n; ++p)
    support[p] = settings_.rkpm.support * points.spacing0[p] *
                 (model_.reference_F.empty() ? 1.0 : largestStretch(model_.reference_F[p]));
  std::vector<std::string> names;
  for (const BodyInfo& b : model_.bodies) names.push_back(b.name);
  const SurfaceHolds holds = surfaceHolds(model_);
  {
    ScopedPhase phase(timers_, "kernels");
    // The last kernels go first (a refused update builds them again), so that two sets are never held.
    kernels_ = Kernels{};
    transposed_ = Table<Vec3>{};
    kernels_ = buildKernels({model_.reference, points.body, support, points.volume0, model_.cell_volume, model_.faces,
                             names, settings_.mirrors, holds.faces, model_.crack, model_.reference_F, model_.origin,
                             model_.alone, !model_.reference_F.empty()});
    transposed_ = transpose(kernels_.gradient);
  }
  // Row-sum lumped masses: the coefficients carry the particles' momentum, sum_I m_I vhat_I =
  // sum_K m_K v_K.
  mass_.assign(n, 0.0);
  const Table<double>& psi = kernels_.psi;
  for (std::size_t k = 0; k < n; ++k)
    for (LocalIndex e = psi.offset[k]; e < psi.offset[k + 1]; ++e)
      mass_[static_cast<std::size_t>(psi.column[static_cast<std::size_t>(e)])] +=
          points.mass[k] * psi.value[static_cast<std::size_t>(e)];
  for (std::size_t i = 0; i < n; ++i)
    if (!(mass_[i] > 0.0))
      throw Error(fmt::format(
          "RKPM: the lumped mass of particle {} of body '{}' at ({:.4g}, {:.4g}, {:.4g}) mm is {:.3g} kg, not "
          "positive: its kernel's negative values outweigh the positive (docs/theory.md §12)",
          points.id[i], model_.bodies[static_cast<std::size_t>(points.body[i])].name, 1e3 * model_.reference[i].x(),
          1e3 * model_.reference[i].y(), 1e3 * model_.reference[i].z(), mass_[i]));
  collocation_ = VelocityCollocation(psi, model_.constrained, mass_, kernels_.at_faces, holds.held);
  acceleration_.assign(n, Vec3::Zero());
  volume_rate_.assign(n, 0.0);
  piola_.assign(n, Mat3::Zero());
  du_.assign(n, Vec3::Zero());
  displacement_.assign(n, Vec3::Zero());
  particle_v_.assign(n, Vec3::Zero());
  before_.assign(n, Vec3::Zero());
  coefficient_before_.assign(n, Vec3::Zero());
  particle_du_.assign(n, Vec3::Zero());
  moved_mark_.assign(n, 0);
  gap_.resize(n);
  for (std::size_t p = 0; p < n; ++p) gap_[p] = particle_reach * points.spacing0[p];
  // Bodies meet where they have surfaces (several lattice bodies); the surfaces follow the debris
  // where the particles' lattice elements are known (a checkpoint older than them keeps its own).
  sliding_ = !model_.surface.empty();
  rebuilds_ =
      std::any_of(model_.element.begin(), model_.element.end(), [](const std::array<int, 3>& e) { return e[0] >= 0; });
  surface_debris_ = -1;
}

void Integrator::initialise() {
  PointStore& points = model_.points;
  model_.crack.clear();
  if (std::any_of(points.broken.begin(), points.broken.begin() + points.owned, [](std::uint8_t b) { return b != 0; }))
    model_.crack.assign(points.broken.begin(), points.broken.begin() + points.owned);
  prepare();
  for (std::size_t b = 0; b < model_.bodies.size(); ++b)
    model_.materials[model_.bodies[b].material]->initialise(points, body_points_[b].begin, body_points_[b].end);
  collocation_.impose(model_.prescribed_v, model_.coefficient_v);
  {
    ScopedPhase phase(timers_, "constitutive");
    updateMaterials(0.0);
  }
  place();
  forces();
  // The initial velocity field's volume rate bounds the first step (a cold gas has no sound speed).
  const Table<Vec3>& g = kernels_.gradient;
#pragma omp parallel for schedule(static)
  for (LocalIndex j = 0; j < points.owned; ++j) {
    double divergence = 0.0;
    for (LocalIndex e = g.offset[j]; e < g.offset[j + 1]; ++e) {
      const auto slot = static_cast<std::size_t>(e);
      divergence +=
          reflect(model_.coefficient_v[static_cast<std::size_t>(g.column[slot])], g.mirror[slot]).dot(g.value[slot]);
    }
    volume_rate_[j] = divergence;
  }
  clock_.dt_next = clock_.dt_initial = stableStep(points, volume_rate_, std::numeric_limits<double>::infinity(),
                                                  settings_.solver.cfl, [&](LocalIndex p) { return stepLength(p); });
}

void Integrator::restore(const Clock& clock, double contact_energy, const KernelUpdates& updates) {
  prepare();
  clock_ = clock;
  contact_energy_ = contact_energy;
  update_energy_ = updates.energy;
  kernel_updates_ = updates.made;
  refused_updates_ = updates.refused;
  retry_at_ = updates.retry_at;
  forces();
}

void Integrator::step() {
  const double dt = std::min(clock_.dt_next, settings_.solver.end_time - clock_.time);
  KESSLER_VERIFY(dt > 0.0, "step called after the end time");
  const double dt_kick = 0.5 * (clock_.dt_last + dt);
  try {
    {
      ScopedPhase phase(timers_, "point update");
      kick(dt_kick, dt);
    }
    if (sliding_) {
      ScopedPhase phase(timers_, "contact");
      slide(dt, dt_kick);
    }
    {
      ScopedPhase phase(timers_, "point update");
      deform(dt);
    }
    {
      ScopedPhase phase(timers_, "constitutive");
      updateMaterials(dt);
    }
    {
      ScopedPhase phase(timers_, "erosion");
      erosion_.apply(model_);
      release_.apply(model_);
    }
    // Debris the kernels still hold leaves them at the next step that is a multiple of
    // `debris_update_every` (docs/theory.md §12, "Kernel updates"): until then its particle is placed
    // by its neighbours' coefficients, and theirs by its.
    update_due_ =
        update_due_ || ((clock_.steps + 1) % debris_update_every == 0 && clock_.steps >= retry_at_ && heldDebris());
    {
      ScopedPhase phase(timers_, "assembly");
      place();
    }
    if (update_due_) updateKernels();
    {
      ScopedPhase phase(timers_, "assembly");
      forces();
    }
  } catch (const NumericalError& e) {
    throw NumericalError(fmt::format("step {}, t = {:.6g} s: {}", clock_.steps + 1, clock_.time, e.what()));
  }
  clock_.advance(dt);
  ScopedPhase phase(timers_, "time step");
  clock_.dt_next = stableStep(model_.points, volume_rate_, std::numeric_limits<double>::infinity(),
                              settings_.solver.cfl, [&](LocalIndex p) { return stepLength(p); });
}

void Integrator::kick(double dt_kick, double dt) {
  const LocalIndex n = model_.points.owned;
  std::vector<Vec3>& v = model_.coefficient_v;
#pragma omp parallel for schedule(static)
  for (LocalIndex i = 0; i < n; ++i) v[i] += dt_kick * acceleration_[i];
  if (!settings_.walls.empty()) imposeWalls(settings_.walls, kernels_.psi, mass_, model_.points.x, gap_, dt, v);
  collocation_.impose(model_.prescribed_v, v);
#pragma omp parallel for schedule(static)
  for (LocalIndex i = 0; i < n; ++i) du_[i] = dt * v[i];
}

namespace {
constexpr int contact_passes = 8;  // at most, per step (Integrator::slide)

// Sorts the particle indices `ids` and drops repeats. A list of more than an eighth of the particles
// is put in order by marks, one per particle (`mark`: all clear before and after), in one pass
// over them, which costs less than its sort.
void indexOrder(std::vector<LocalIndex>& ids, std::vector<std::uint8_t>& mark) {
  if (8 * ids.size() < mark.size()) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return;
  }
  for (const LocalIndex p : ids) mark[static_cast<std::size_t>(p)] = 1;
  ids.clear();
  for (std::size_t p = 0; p < mark.size(); ++p)
    if (mark[p] != 0) {
      ids.push_back(static_cast<LocalIndex>(p));
      mark[p] = 0;
    }
}
}  // namespace

// The sliding contact between the bodies' surface particles (docs/theory.md §12): it acts on the
// particles, at their positions and with their velocities and masses, with velocity exchanges only
// (no position correction). Each particle's impulse m_K dv_K reaches the coefficients as a force
// does, through the shape functions: vhat_I += 1 / m_I  sum_K Psi_I(X_K) m_K dv_K, which conserves
// the linear momentum exactly (the shape functions sum to one). The energy it takes is booked apart:
// the work its impulses did on the coefficients over the passes (contactHeat), from their velocities
// before the kick, vhat_before - dt_kick a_I (docs/theory.md §12, "The contact's energy").
void Integrator::slide(double dt, double dt_kick) {
  const PointStore& points = model_.points;
  const LocalIndex n = points.owned;
  // The bodies' surfaces over the particles that are not debris, built again whenever more have left
  // as debris (a pure function of which have, so a restored run builds what the run it continues
  // had): the particles beneath an eroded surface become surface, and meet the other bodies.
  LocalIndex released = 0;
  for (LocalIndex p = 0; p < n; ++p) released += points.debris(p) ? 1 : 0;
  if (released != surface_debris_ && rebuilds_) {
    surface_debris_ = released;
    rebuildSurface();
  }
  // The surface now: a triangle stretched beyond three spacings (its particles have parted: the
  // surface is torn there) is not surface, nor one with a debris vertex (a surface a checkpoint kept
  // without its elements, which is not built again).
  surface_.triangles.clear();
  surface_.slaves.clear();
  for (const auto& t : model_.surface) {
    double longest = 0.0, spacing = 0.0;
    bool debris = false;
    for (int e = 0; e < 3; ++e) {
      const LocalIndex a = t[static_cast<std::size_t>(e)], b = t[static_cast<std::size_t>((e + 1) % 3)];
      longest = std::max(longest, (points.x[a] - points.x[b]).norm());
      spacing = std::max(spacing, points.spacing0[a]);
      debris = debris || points.debris(a);
    }
    if (debris || longest > 3.0 * spacing) continue;
    surface_.triangles.push_back(t);
    surface_.slaves.insert(surface_.slaves.end(), t.begin(), t.end());
  }
  // Debris meets the bodies as matter: each debris particle is a slave of every other body's surface.
  for (LocalIndex p = 0; p < n; ++p)
    if (points.debris(p)) surface_.slaves.push_back(p);
  indexOrder(surface_.slaves, moved_mark_);
  std::copy(model_.coefficient_v.begin(), model_.coefficient_v.end(), coefficient_before_.begin());
  // The contact's impulses reach the particles through the shape functions, which spread each over
  // its neighbours: a particle's velocity after one pass is not yet the one the contact asked for.
  // The passes repeat on the particles that moved in the last one and the triangles they are
  // vertices of, until the impulses are less than a thousandth of the first pass's (at most
  // `contact_passes`): an iterative solution of the collocation of the contact's velocities.
  std::vector<std::uint64_t> touching(model_.bodies.size(), 0);
  const Table<double>& psi = kernels_.psi;
  std::vector<Vec3>& v = model_.coefficient_v;
  std::vector<LocalIndex> active = surface_.slaves;  // the particles a pass reads: slaves and vertices
  double first = 0.0;
  for (int pass = 0; pass < contact_passes && !surface_.slaves.empty(); ++pass) {
    const auto count = static_cast<std::ptrdiff_t>(active.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t r = 0; r < count; ++r) {
      const LocalIndex k = active[static_cast<std::size_t>(r)];
      const Vec3 at = valueAt(psi, v, k);
      particle_v_[k] = before_[k] = at;
      particle_du_[k] = dt * at;
    }
    const SlidingCarriers carriers{points.x,    particle_du_,       particle_v_, points.mass,
                                   points.body, model_.constrained, gap_};
    const SlidingReport report = contact_.apply(surface_, carriers, model_.bodies.size());
    for (std::size_t b = 0; b < touching.size(); ++b) touching[b] |= report.touching[b];
    // A debris particle that met a body struck it (the rear-wall analysis counts those).
    for (const auto& [k, body] : report.met)
      if (points.debris(k)) model_.points.strike(k, body);
    double total = 0.0;
    std::vector<LocalIndex> moved;
    for (const LocalIndex k : active) {
      const Vec3 impulse = points.mass[k] * (particle_v_[k] - before_[k]);
      if (impulse == Vec3::Zero()) continue;
      moved.push_back(k);
      total += impulse.norm();
      spreadImpulse(psi, mass_, k, impulse, v);
    }
    if (pass == 0) first = total;
    if (!(total > 1e-3 * first)) break;
    for (const LocalIndex k : moved) moved_mark_[k] = 1;
    std::vector<std::array<LocalIndex, 3>> kept;
    for (const auto& t : surface_.triangles)
      if (moved_mark_[t[0]] || moved_mark_[t[1]] || moved_mark_[t[2]]) kept.push_back(t);
    for (const LocalIndex k : moved) moved_mark_[k] = 0;
    surface_.triangles = std::move(kept);
    active = moved;
    for (const auto& t : surface_.triangles) active.insert(active.end(), t.begin(), t.end());
    indexOrder(active, moved_mark_);
    surface_.slaves = std::move(moved);
  }
  contact_energy_ += contactHeat(mass_, coefficient_before_, v, n, [&](LocalIndex i) {
    return Vec3(coefficient_before_[i] - dt_kick * acceleration_[i]);
  });
  collocation_.impose(model_.prescribed_v, v);
#pragma omp parallel for schedule(static)
  for (LocalIndex i = 0; i < n; ++i) du_[i] = dt * v[i];
  for (std::size_t b = 0; b < touching.size(); ++b)
    for (std::size_t o = 0; o < touching.size(); ++o)
      if (touching[b] & (std::uint64_t{1} << o)) {
        model_.bodies[b].touched |= std::uint64_t{1} << o;
        model_.bodies[o].touched |= std::uint64_t{1} << b;
      }
}

void Integrator::rebuildSurface() {
  model_.surface.clear();
  const PointStore& points = model_.points;
  std::vector<LocalIndex> present;
  for (const IndexRange& range : body_points_) {
    present.clear();
    for (LocalIndex p = range.begin; p < range.end; ++p)
      if (!points.debris(p) && model_.element[static_cast<std::size_t>(p)][0] >= 0) present.push_back(p);
    const std::vector<std::array<LocalIndex, 3>> sheet = latticeSurface(model_.element, present);
    model_.surface.insert(model_.surface.end(), sheet.begin(), sheet.end());
  }
}

void Integrator::deform(double dt) {
  PointStore& points = model_.points;
  const LocalIndex n = points.owned;
  // The coefficients' displacements from the kernels' reference configuration, once each: the
  // gradient's loop below then reads one array at its scattered columns, not two. Debris alone in the
  // kernels is its own coefficient (its particle's position and velocity): once across a symmetry
  // plane or roller it goes on as its image, inside, where the bodies it may strike are (their images
  // are none of the contact's).
  const bool reflect_debris = !model_.alone.empty() && settings_.mirrors.any();
#pragma omp parallel for schedule(static)
  for (LocalIndex i = 0; i < n; ++i) {
    model_.coefficient_x[i] += du_[i];
    if (reflect_debris && model_.alone[static_cast<std::size_t>(i)] && points.debris(i))
      settings_.mirrors.reflectInto(model_.coefficient_x[i], model_.coefficient_v[i]);
    displacement_[i] = model_.coefficient_x[i] - model_.reference[i];
  }
  const Table<Vec3>& g = kernels_.gradient;
  LocalIndex bad = n;
  const bool updated = !model_.reference_F.empty();
  const double limit = settings_.rkpm.update_strain;
  int due = 0;
#pragma omp parallel for schedule(static) reduction(min : bad) reduction(max : due)
  for (LocalIndex j = 0; j < n; ++j) {
    points.dF[j].setIdentity();
    volume_rate_[j] = 0.0;
    if (points.debris(j)) continue;
    // The deformation since the kernels' reference configuration, then the whole.
    Mat3 F = Mat3::Identity();
    for (LocalIndex e = g.offset[j]; e < g.offset[j + 1]; ++e) {
      const auto slot = static_cast<std::size_t>(e);
      const auto i = static_cast<std::size_t>(g.column[slot]);
      F.noalias() += reflect(displacement_[i], g.mirror[slot]) * g.value[slot].transpose();
    }
    if (limit > 0.0 && !points.failed(j) && (F.transpose() * F - Mat3::Identity()).norm() > 2.0 * limit) due = 1;
    if (updated) F = F * model_.reference_F[j];
    const double J = F.determinant();
    const Mat3 dF = F * points.F[j].inverse();
    const double j_step = dF.determinant();
    if (J > 0.0 && j_step > 0.0 && std::isfinite(J) && std::isfinite(j_step)) {
      points.dF[j] = dF;
      points.F[j] = F;
      points.volume[j] = points.volume0[j] * J;
      volume_rate_[j] = std::log(j_step) / dt;
    } else if (points.failed(j)) {
      points.carrier[j] = -1;  // failed material crushed through itself is debris (docs/theory.md §8)
    } else {
      bad = std::min(bad, j);
    }
  }
  if (bad < n) failAtPoint(bad, "volume inverted or collapsed over the step (det F <= 0)");
  update_due_ = due != 0 && clock_.steps >= retry_at_;
  // The viscosity's limiter, from the step's volume change of the particles the kernel reaches.
  const Table<double>& psi = kernels_.psi;
#pragma omp parallel for schedule(static)
  for (LocalIndex j = 0; j < n; ++j) {
    points.viscosity_limiter[j] = 0.0;
    const double own = volume_rate_[j];
    if (points.debris(j) || !(own < 0.0)) continue;
    double weight = 0.0, mean = 0.0, least = std::numeric_limits<double>::infinity();
    for (LocalIndex e = psi.offset[j]; e < psi.offset[j + 1]; ++e) {
      const double w = psi.value[static_cast<std::size_t>(e)];
      if (w <= 0.0) continue;
      const double ratio = volume_rate_[static_cast<std::size_t>(psi.column[static_cast<std::size_t>(e)])] / own;
      weight += w;
      mean += w * ratio;
      least = std::min(least, ratio);
    }
    if (weight > 0.0) points.viscosity_limiter[j] = christensenLimiter(mean / weight, least);
  }
#pragma omp parallel for schedule(static)
  for (LocalIndex j = 0; j < n; ++j)
    if (points.debris(j)) {
      points.stress[j].setZero();
      points.viscous_pressure[j] = 0.0;
    }
}

void Integrator::updateMaterials(double dt) {
  PointStore& points = model_.points;
  try {
    updateBodies(model_, body_points_, dt);
  } catch (const PointError& e) {
    failAtPoint(static_cast<LocalIndex>(e.point()), e.what());
  }
  LocalIndex bad = points.owned;
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (LocalIndex p = 0; p < points.owned; ++p)
    if (!points.stress[p].allFinite() || !std::isfinite(points.energy[p]) ||
        !(points.debris(p) || points.sound_speed[p] >= 0.0))
      bad = std::min(bad, p);
  if (bad < points.owned) failAtPoint(bad, "the material update gave a non-finite stress, energy or sound speed");
}

// The particles where their coefficients put them.
void Integrator::place() {
  interpolate(kernels_.psi, model_.coefficient_x, model_.coefficient_v, model_.points.x, model_.points.v);
  if (!kernels_.shift.empty())
    for (LocalIndex k = 0; k < model_.points.owned; ++k)
      model_.points.x[k] += kernels_.shift[static_cast<std::size_t>(k)];
}

void Integrator::forces() {
  PointStore& points = model_.points;
  const LocalIndex n = points.owned;
#pragma omp parallel for schedule(static)
  for (LocalIndex j = 0; j < n; ++j) {
    if (points.debris(j)) {
      piola_[j].setZero();
      continue;
    }
    // The kernels' gradients are taken in their reference configuration (the last kernel update's):
    // the Piola stress is the one relative to it, V_J sigma_J F_inc^-T with F_inc = F F_ref^-1 the
    // deformation since, so F_inc^-T = F^-T F_ref^T.
    const Mat3& F = points.F[j];
    piola_[j] = points.volume0[j] * F.determinant() * points.stress[j] * F.inverse().transpose();
    if (!model_.reference_F.empty()) piola_[j] = piola_[j] * model_.reference_F[j].transpose();
  }
  const Table<Vec3>& t = transposed_;
#pragma omp parallel for schedule(static)
  for (LocalIndex i = 0; i < n; ++i) {
    Vec3 f = Vec3::Zero();
    for (LocalIndex e = t.offset[i]; e < t.offset[i + 1]; ++e) {
      const auto slot = static_cast<std::size_t>(e);
      f -= reflect(Vec3(piola_[static_cast<std::size_t>(t.column[slot])] * t.value[slot]), t.mirror[slot]);
    }
    acceleration_[i] = f / mass_[i];
  }
}

// A kernel update (docs/theory.md §12, "Kernel updates"): the particles' present positions become the
// kernels' centres, each cell its first cell mapped by the particle's F, debris stands alone; the
// coefficients are the positions (the kernels reproduce them) and the velocities that interpolate to
// the particles' velocities, so that the particles' motion, the coefficients' momentum and every
// particle's deformation gradient carry through.
void Integrator::updateKernels() {
  ScopedPhase phase(timers_, "kernel update");
  PointStore& points = model_.points;
  const auto n = static_cast<std::size_t>(points.owned);
  const double kinetic = coefficientKinetic();
  struct Kept {
    std::vector<Vec3> origin, reference, coefficient_x;
    std::vector<Mat3> reference_F;
    std::vector<std::uint8_t> alone;
  } kept{model_.origin, model_.reference, model_.coefficient_x, model_.reference_F, model_.alone};
  if (model_.origin.empty()) model_.origin = model_.reference;
  model_.reference_F.assign(points.F.begin(), points.F.begin() + points.owned);
  model_.reference.assign(points.x.begin(), points.x.begin() + points.owned);
  model_.coefficient_x = model_.reference;
  model_.alone.assign(n, 0);
  for (LocalIndex p = 0; p < points.owned; ++p) model_.alone[static_cast<std::size_t>(p)] = points.debris(p) ? 1 : 0;
  const std::vector<Vec3> velocity(points.v.begin(), points.v.begin() + points.owned);
  const std::vector<double> rate = volume_rate_;
  const LocalIndex surface_debris = surface_debris_;
  update_due_ = false;
  try {
    prepare();
  } catch (const Error& e) {
    // The present configuration gives no usable kernels (a lumped mass not positive where the particles
    // have tangled): the last ones are kept, and the update is tried again later.
    model_.origin = std::move(kept.origin);
    model_.reference = std::move(kept.reference);
    model_.coefficient_x = std::move(kept.coefficient_x);
    model_.reference_F = std::move(kept.reference_F);
    model_.alone = std::move(kept.alone);
    prepare();
    volume_rate_ = rate;
    surface_debris_ = surface_debris;
    // Each refusal doubles the wait (bounded), so that a tangle that stays costs few builds.
    retry_at_ = clock_.steps + (update_retry << std::min<std::int64_t>(refused_updates_, 10));
    ++refused_updates_;
    last_refusal_ = fmt::format("step {}: {}", clock_.steps + 1, e.what());
    return;
  }
  volume_rate_ = rate;
  surface_debris_ = surface_debris;
  model_.coefficient_v =
      interpolatingCoefficients(kernels_.psi, points.mass, mass_, velocity, model_.coefficient_v, update_passes);
  update_energy_ += kinetic - coefficientKinetic();
  ++kernel_updates_;
  place();
}

bool Integrator::heldDebris() const {
  const PointStore& points = model_.points;
  int held = 0;
#pragma omp parallel for schedule(static) reduction(max : held)
  for (LocalIndex p = 0; p < points.owned; ++p)
    if (points.debris(p) && (model_.alone.empty() || !model_.alone[static_cast<std::size_t>(p)])) held = 1;
  return held != 0;
}

double Integrator::coefficientKinetic() const {
  double kinetic = 0.0;
  for (std::size_t i = 0; i < mass_.size(); ++i) kinetic += 0.5 * mass_[i] * model_.coefficient_v[i].squaredNorm();
  return kinetic;
}

double Integrator::stepLength(LocalIndex p) const {
  return model_.points.spacing0[p] * smallestStretch(model_.points.F[p]);
}

Energies Integrator::energies() const {
  Energies e = pointEnergies(model_.points, contact_energy_ + update_energy_);
  Vec3 momentum = Vec3::Zero();
  for (std::size_t i = 0; i < mass_.size(); ++i) momentum += mass_[i] * model_.coefficient_v[i];
  e.kinetic = coefficientKinetic();
  e.momentum = momentum;
  return e;
}

double Integrator::meanNeighbours() const {
  const LocalIndex n = kernels_.gradient.rows();
  return n > 0 ? static_cast<double>(kernels_.gradient.column.size()) / static_cast<double>(n) : 0.0;
}

void Integrator::failAtPoint(LocalIndex p, const std::string& what) const {
  const PointStore& points = model_.points;
  const Vec3& x = points.x[p];
  throw NumericalError(fmt::format("particle {} of body '{}' at ({:.6g}, {:.6g}, {:.6g}) m: {}", points.id[p],
                                   model_.bodies[static_cast<std::size_t>(points.body[p])].name, x[0], x[1], x[2],
                                   what));
}

}  // namespace kessler::rkpm
