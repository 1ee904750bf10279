#include "solver/otm/integrator.hpp"

#include "approx/lme.hpp"
#include "core/error.hpp"
#include "core/lanes.hpp"
#include "solver/common/body_laws.hpp"
#include "solver/common/debris_contact.hpp"
#include "solver/common/release.hpp"
#include "solver/common/stable_step.hpp"
#include "solver/otm/integrator_assembly.hpp"
#include "solver/otm/volume_patch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace kessler::otm {

namespace {

constexpr const char* kAnotherRank = "another rank stopped the step (its message says why)";

}  // namespace

Integrator::Integrator(Model& model, const Settings& settings, Distribution* distribution)
    : model_(model),
      settings_(settings),
      distribution_(distribution),
      neighbourhoods_(settings),
      erosion_(settings.erosion_radius),
      release_(settings.erosion_radius),
      sliding_(settings.contact.friction) {
  KESSLER_VERIFY(settings.cfl > 0.0 && settings.cfl <= 1.0, "cfl must lie in (0, 1], got {}", settings.cfl);
  KESSLER_VERIFY(settings.end_time > 0.0, "end_time must be positive, got {}", settings.end_time);
  // Its occluders are found over the points a rank holds, which do not reach as far as its searches.
  if (distribution && settings.crack_visibility)
    throw Error("otm.crack_visibility does not yet run on several ranks (docs/parallel.md); run on one");
  if (distribution && sliding())
    throw Error("solver.contact: a sliding contact does not yet run on several ranks (docs/parallel.md); run on one");
  std::vector<double> limits;
  for (const BodyInfo& body : model_.bodies) limits.push_back(model_.materials[body.material]->tensileLimit());
  patch_.setTensileLimits(std::move(limits));
}

void Integrator::initialise() {
  requireFacesInOrder();
  if (distribution_) distribution_->split(model_);
  findBodyRanges();
  for (std::size_t b = 0; b < model_.bodies.size(); ++b)
    model_.materials[model_.bodies[b].material]->initialise(model_.points, body_points_[b].begin, body_points_[b].end);
  {
    ScopedPhase phase(timers_, "constitutive");
    updateMaterials(0.0);
  }
  search();
  timers_.add("search", neighbourhoods_.searchSeconds());
  timers_.add("shape functions", neighbourhoods_.shapeSeconds());
  initialVolumeRates();
  dt_next_ = dt_initial_ = stableStep();
}

// div v = sum_a v_a . grad N_a of each point in the initial velocity field, for the first step's
// volume-change bound (stableStep): a cold gas has no sound speed to set it, and no step has yet
// measured its rate.
void Integrator::initialVolumeRates() {
  const PointStore& points = model_.points;
  const Connectivity& conn = model_.connectivity;
  volume_rate_.assign(static_cast<std::size_t>(points.owned), 0.0);
#pragma omp parallel for schedule(static)
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (points.debris(p)) continue;
    double div_v = 0.0;
    for (Index e = conn.offset[p]; e < conn.offset[p + 1]; ++e) div_v += model_.nodes.v[conn.node[e]].dot(conn.dN[e]);
    volume_rate_[p] = div_v;
  }
}

void Integrator::search() {
  if (!distribution_) {
    neighbourhoods_.update(model_);
    return;
  }
  // Halos for the widest search of the last step or the widest cut-off now, with a quarter to
  // spare (supports grow as material expands, and a search widens by a quarter at a time);
  // wider, and the search again, while a search reaches beyond them.
  double radius = haloRadius(0.0);
  for (;;) {
    {
      ScopedPhase phase(timers_, "halo");
      rebuildHalos(radius);
    }
    if (neighbourhoods_.update(model_, share(), distribution_->nodeShare(), radius, distribution_->searched())) {
      halo_support_ = radius;
      return;
    }
    radius = std::max(1.25 * radius, neighbourhoods_.largestRadius());
    ++searches_repeated_;
  }
}

double Integrator::haloRadius(double reach) const {
  const PointStore& points = model_.points;
  const Share own = share();
  double spacing = 0.0;
  for (LocalIndex p = 0; p < points.owned; ++p)
    if (own.own(p) && !points.debris(p)) spacing = std::max(spacing, points.spacing(p));
  const double cutoff = lme::cutoffRadius(settings_.lme_gamma, 1.0, settings_.lme_tolerance) * own.max(spacing);
  return 1.25 * std::max({cutoff, neighbourhoods_.largestRadius(), reach});
}

// The fastest debris point's speed over every rank, m/s.
double Integrator::debrisSpeed() const {
  const PointStore& points = model_.points;
  const Share own = share();
  double speed = 0.0;
  for (LocalIndex p = 0; p < points.owned; ++p)
    if (own.own(p) && points.debris(p)) speed = std::max(speed, points.v[p].norm());
  return own.max(speed);
}

void Integrator::rebuildHalos(double support) {
  // What a debris contact may reach in the next step (solver/common/debris_contact.hpp): the two
  // spacings of a pair and twice its flight over the kick, for a step up to twice this one. The
  // reference spacings do not change: their largest is found once.
  const Share own = share();
  if (contact_spacing_ == 0.0) {
    const PointStore& points = model_.points;
    double spacing = 0.0;
    for (LocalIndex p = 0; p < points.owned; ++p)
      if (own.own(p)) spacing = std::max(spacing, points.spacing0[p]);
    contact_spacing_ = own.max(spacing);
  }
  contact_reach_ = 2.0 * contact_spacing_ + 2.0 * debrisSpeed() * 2.0 * std::max(dt_last_, dt_next_);
  distribution_->rebuild(model_, volume_rate_, support, settings_.erosion_radius, contact_reach_);
  findBodyRanges();
}

void Integrator::requireContactReach(double dt_kick) const {
  const double speed = debrisSpeed();  // the same on every rank, so every rank stops
  if (2.0 * contact_spacing_ + 2.0 * speed * dt_kick > contact_reach_)
    throw NumericalError(
        fmt::format("debris flies further in a step than a distributed run's halo holds ({:.3g} m "
                    "at {:.3g} m/s over {:.3g} s; docs/parallel.md, \"The distributed step\")",
                    contact_reach_, speed, dt_kick));
}

void Integrator::requireFacesInOrder() const {
  if (!sliding()) return;
  // One process holds the points and nodes in id order (orderForLocality, and a checkpoint keeps it):
  // the faces name them by id.
  for (LocalIndex a = 0; a < model_.nodes.size(); ++a)
    KESSLER_VERIFY(model_.nodes.id[a] == a, "sliding contact: node {} has id {}", a, model_.nodes.id[a]);
  for (LocalIndex p = 0; p < model_.points.size(); ++p)
    KESSLER_VERIFY(model_.points.id[p] == p, "sliding contact: point {} has id {}", p, model_.points.id[p]);
  if (model_.faces.empty() && model_.points.size() > 0)
    throw Error("solver.contact: a sliding contact needs the bodies' faces, which this model was built without");
}

void Integrator::restore(const IntegratorState& state) {
  time_ = state.time;
  dt_last_ = state.dt_last;
  dt_next_ = state.dt_next;
  dt_initial_ = state.dt_initial;
  steps_ = state.steps;
  stabilisation_energy_ = state.stabilisation_energy;
  requireFacesInOrder();
  if (distribution_)
    distributeRestored();
  else
    findBodyRanges();
}

// Every rank read the whole checkpoint, rows included (each point's nodes by index into the whole
// node store). The split and the halos are those of a first step, wide enough for the farthest node
// of any row, so that every point held finds its row's nodes among the nodes held; the rows are then
// those the one-process run would use, rewritten with this rank's node indices. The results do not
// depend on where the points are cut, so the run goes on bitwise as the one that wrote the
// checkpoint, on any number of ranks.
void Integrator::distributeRestored() {
  PointStore& points = model_.points;
  NodeStore& nodes = model_.nodes;
  Connectivity whole = std::move(model_.connectivity);
  KESSLER_VERIFY(whole.offset.size() == static_cast<std::size_t>(points.owned) + 1, "restoring {} rows for {} points",
                 whole.offset.size() - 1, points.owned);
  const std::vector<Index> point_ids = points.id, node_ids = nodes.id;
  double reach = 0.0;
  for (LocalIndex p = 0; p < points.owned; ++p)
    for (Index e = whole.offset[p]; e < whole.offset[p + 1]; ++e)
      reach = std::max(reach, (nodes.x[whole.node[e]] - points.x[p]).norm());
  distribution_->split(model_);
  const double radius = haloRadius(reach);
  rebuildHalos(radius);
  halo_support_ = radius;

  // Rows for the points a search gives rows (Distribution::searched).
  const IdIndex whole_point(point_ids), node_at(nodes.id);
  const std::span<const std::uint8_t> searched = distribution_->searched();
  Connectivity& conn = model_.connectivity;
  std::vector<LocalIndex> at_whole(static_cast<std::size_t>(points.owned));
  conn.offset.assign(static_cast<std::size_t>(points.owned) + 1, 0);
  for (LocalIndex p = 0; p < points.owned; ++p) {
    const LocalIndex w = at_whole[p] = whole_point.find(points.id[p]);
    conn.offset[p + 1] = conn.offset[p] + (searched[p] ? whole.offset[w + 1] - whole.offset[w] : 0);
  }
  conn.resizeRows(static_cast<std::size_t>(conn.offset.back()));
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (!searched[p]) continue;
    const LocalIndex w = at_whole[p];
    Index to = conn.offset[p];
    for (Index e = whole.offset[w]; e < whole.offset[w + 1]; ++e, ++to) {
      const Index id = node_ids[static_cast<std::size_t>(whole.node[e])];
      const LocalIndex a = node_at.find(id);
      KESSLER_VERIFY(a >= 0, "restoring point {}: its node {} is not among the {} nodes held", points.id[p], id,
                     nodes.size());
      conn.node[to] = a;
      conn.N[to] = whole.N[e];
      conn.dN[to] = whole.dN[e];
    }
  }
  conn.buildTranspose(nodes.size());
}

// The owned points of each body, together in the store (the Morton sort orders within bodies):
// the materials update them body by body.
void Integrator::findBodyRanges() {
  body_points_ = bodyRanges(model_.points.body, model_.points.owned, model_.bodies.size());
}

void Integrator::step() {
  const double dt = std::min(dt_next_, settings_.end_time - time_);
  KESSLER_VERIFY(dt > 0.0, "step called after the end time");
  try {
    advance(dt);
  } catch (const NumericalError& e) {
    // Failures inside a step (LME, inverted points) happen before the step count moves on.
    throw NumericalError(fmt::format("step {}, t = {:.6g} s: {}", steps_ + 1, time_, e.what()));
  }
}

void Integrator::advance(double dt) {
  {
    ScopedPhase phase(timers_, "assembly");
    assembleNodes();
    // Debris that strikes a body pushes its nodes (solver/common/debris_contact.hpp).
    if (settings_.debris_contact) {
      NodeStore& nodes = model_.nodes;
      const double dt_kick = 0.5 * (dt_last_ + dt);
      if (distribution_) {
        requireContactReach(dt_kick);
        // The contact weighs a struck node by its mass and velocity: a ghost node's owner holds all
        // its points.
        distribution_->refreshNodes(nodes.mass);
        distribution_->refreshNodes(nodes.momentum);
      }
      Carriers carriers{nodes.x, nodes.momentum, nodes.mass, nodes.body, nodes.force, nodes.owned, {}, {}, {}};
      if (distribution_) {
        carriers.ghost = distribution_->ghostNodes();
        carriers.refresh_pairs = [&](std::vector<int>& pairs) { distribution_->refreshNodes(pairs); };
        carriers.refresh_kicks = [&](std::vector<Vec3>& kicks) { distribution_->refreshNodes(kicks); };
      }
      contact_.apply(model_, carriers, dt_kick, share());
    }
  }
  {
    ScopedPhase phase(timers_, "node update");
    // Discrete Euler-Lagrange equations for a variable step (docs/theory.md §4 step 2).
    updateNodes(dt, 0.5 * (dt_last_ + dt));
  }
  // A ghost node gathered only the points this rank holds: its owner's update replaces it.
  if (distribution_) {
    ScopedPhase phase(timers_, "halo");
    distribution_->refreshNodes(model_.nodes);
    distribution_->refreshNodes(increment_);
  }
  {
    ScopedPhase phase(timers_, "point update");
    updatePoints();
  }
  if (refresh_seconds_ > 0.0) {
    timers_.add("point update", -refresh_seconds_);
    timers_.add("halo", refresh_seconds_);
    refresh_seconds_ = 0.0;
  }
  {
    ScopedPhase phase(timers_, "constitutive");
    updateMaterials(dt);
    stabilisation_energy_ += patch_.closeStep(model_.points, settings_.volume_stabilisation, share());
    balanceEnergy();
  }
  {
    ScopedPhase phase(timers_, "erosion");
    eroded_ += erosion_.apply(model_, share());
    release_.apply(model_, share());
    if (settings_.debris_contact) markNewDebris(model_);
  }
  search();
  timers_.add("search", neighbourhoods_.searchSeconds());
  timers_.add("shape functions", neighbourhoods_.shapeSeconds());
  time_ += dt;
  dt_last_ = dt;
  ++steps_;
  {
    ScopedPhase phase(timers_, "time step");
    dt_next_ = stableStep();
  }
}

// Lumped mass, momentum and internal force gathered over each node's points
// (solver/otm/integrator_assembly.hpp).
void Integrator::assembleNodes() {
  if (!settings_.volume_averaging) {
    otm::assembleNodes(model_.connectivity, model_.points, model_.nodes, loads_);
    return;
  }
  patch_.stabilisationPressures(model_.points, settings_.volume_stabilisation, stabilisation_pressure_);
  otm::assembleNodes(model_.connectivity, model_.points, model_.nodes, loads_, &stabilisation_pressure_);
}

void Integrator::updateNodes(double dt, double dt_average) {
  NodeStore& nodes = model_.nodes;
  dt_step_ = dt;
  dt_average_ = dt_average;
  increment_.resize(static_cast<std::size_t>(nodes.size()));
#pragma omp parallel for schedule(static)
  for (LocalIndex a = 0; a < nodes.owned; ++a) {
    // A node that no point references carries no mass and does not move.
    if (nodes.mass[a] <= 0.0) {
      increment_[a].du.setZero();
      increment_[a].dv.setZero();
      nodes.v[a].setZero();
      continue;
    }
    const Vec3 v_old = nodes.momentum[a] / nodes.mass[a];
    Vec3 v_new = v_old + dt_average * nodes.force[a] / nodes.mass[a];
    imposeBoundaries(nodes.constrained[a], nodes.prescribed_v[a], settings_.walls, nodes.x[a], dt, v_new);
    increment_[a].dv = v_new - v_old;
    increment_[a].du = dt * v_new;
    nodes.v[a] = v_new;
  }
  if (sliding()) slide();
#pragma omp parallel for schedule(static)
  for (LocalIndex a = 0; a < nodes.owned; ++a) nodes.x[a] += increment_[a].du;
}

void Integrator::buildSurface() {
  const PointStore& points = model_.points;
  const NodeStore& nodes = model_.nodes;
  surface_.triangles.clear();
  surface_.slaves.clear();
  // Intact material only: with failed material (compression only) as a surface too, the contact
  // drove sphere-plate's shock nearer the Hugoniot but cylinder-oblique's energy ran away
  // (docs/validation.md, "Sliding contact").
  const auto intact = [&](Index p) { return p >= 0 && !points.broken[static_cast<std::size_t>(p)]; };
  for (const ContactFace& f : model_.faces) {
    const bool in = intact(f.inner), out = intact(f.outer);
    if (in == out) continue;
    std::array<LocalIndex, 3> t{static_cast<LocalIndex>(f.nodes[0]), static_cast<LocalIndex>(f.nodes[1]),
                                static_cast<LocalIndex>(f.nodes[2])};
    if (out) std::swap(t[1], t[2]);  // seen from the outer point's side
    surface_.triangles.push_back(t);
    for (const LocalIndex a : t) surface_.slaves.push_back(a);
  }
  std::sort(surface_.slaves.begin(), surface_.slaves.end());
  surface_.slaves.erase(std::unique(surface_.slaves.begin(), surface_.slaves.end()), surface_.slaves.end());
  KESSLER_VERIFY(surface_.slaves.empty() || surface_.slaves.back() < nodes.size(), "a contact face names node {} of {}",
                 surface_.slaves.back(), nodes.size());
}

void Integrator::slide() {
  buildSurface();
  NodeStore& nodes = model_.nodes;
  std::vector<Vec3>& du = slide_du_;
  du.resize(increment_.size());
  for (std::size_t a = 0; a < du.size(); ++a) du[a] = increment_[a].du;
  const std::vector<Vec3>& v_before = slide_v_;
  slide_v_.assign(nodes.v.begin(), nodes.v.begin() + nodes.owned);
  sliding_report_ = sliding_.apply(
      surface_, SlidingCarriers{nodes.x, du, nodes.v, nodes.mass, nodes.body, nodes.constrained}, model_.bodies.size());
  for (std::size_t a = 0; a < du.size(); ++a) {
    increment_[a].du = du[a];
    increment_[a].dv += nodes.v[a] - v_before[a];
  }
  // The energy the contact took (the work of its impulses, from the step's starting velocity
  // momentum / mass) is booked apart (Energies::stabilisation), not given to the material: all of it
  // in the one layer of points at the interface (where a shock would spread it over the material it
  // crosses) made them hot enough to collapse the time step (docs/theory.md §11).
  stabilisation_energy_ += contactHeat(nodes.mass, v_before, nodes.v, nodes.owned,
                                       [&](LocalIndex a) { return Vec3(nodes.momentum[a] / nodes.mass[a]); });
  recordContacts(model_, sliding_report_.touching);
}

// Material points follow the nodes (docs/theory.md §4 step 3), written with displacements so that
// round-off does not grow with the distance from the origin:
//   x_p += sum_a N_a u_a,  dF = I + sum_a u_a (x) grad N_a,  F <- dF F,  V <- det(dF) V.
// Velocities take the nodal increment (FLIP-style), which conserves momentum exactly and,
// unlike re-interpolating the nodal velocity, does not damp the resolved motion.
void Integrator::updatePoints() {
  PointStore& points = model_.points;
  const Connectivity& conn = model_.connectivity;
  LocalIndex bad = points.owned;
  j_point_.resize(static_cast<std::size_t>(points.owned));  // det(dF) of each point of the bodies
  transfer_heat_.assign(static_cast<std::size_t>(points.owned), 0.0);
  force_work_.assign(static_cast<std::size_t>(points.owned), 0.0);
  const double kick = dt_step_ > 0.0 ? dt_average_ / dt_step_ : 1.0;
  const Share own = share();
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (points.debris(p)) {
      // Debris: ballistic, with the point's own velocity (the contact's kicks included).
      points.x[p] += dt_step_ * points.v[p];
      points.dF[p].setIdentity();
      continue;
    }
    lanes::V dx_sum = lanes::zero(), dv_sum = lanes::zero();
    lanes::OuterSum dF_sum(Mat3::Identity()), dv_grad_sum;
    double dv2 = 0.0;  // sum_a N_a |dv_a|^2
    for (Index e = conn.offset[p]; e < conn.offset[p + 1]; ++e) {
      const NodeIncrement& node = increment_[conn.node[e]];
      const lanes::V du = lanes::load(node.du), dv_a = lanes::load(node.dv);
      dx_sum = lanes::plusScaled(dx_sum, conn.N[e], du);
      dv_sum = lanes::plusScaled(dv_sum, conn.N[e], dv_a);
      dv2 += conn.N[e] * node.dv.squaredNorm();
      dF_sum.add(du, conn.dN[e]);
      dv_grad_sum.add(dv_a, conn.dN[e]);
    }
    const Vec3 dx = lanes::vec3(dx_sum), dv = lanes::vec3(dv_sum);
    const Mat3 dF = dF_sum.matrix(), dv_grad = dv_grad_sum.matrix();
    // The kinetic energy the transfer takes from the point (docs/theory.md §4 step 4): half its mass
    // times the spread of its nodes' increments, sum_a N_a |dv_a - dv|^2 (never negative: N >= 0,
    // sum N = 1). It becomes heat, so the step conserves energy as the nodes' leapfrog does.
    const double heat = 0.5 * points.mass[p] * std::max(dv2 - dv.squaredNorm(), 0.0);
    transfer_heat_[p] = heat;
    // The work the point's forces did on its nodes over the step, at the nodes' mean velocity
    // (v_old + v_new)/2 over the kick's interval: what the nodes' kinetic energy gave up to it
    // (docs/theory.md §4 step 5). du_a = dt v_new, so sum_a (v_old + v_new)/2 dt_kick (x) grad N_a
    // = (dt_kick/dt)(dF - I) - dt_kick/2 sum_a dv_a (x) grad N_a.
    const Mat3 mean_motion = kick * (dF - Mat3::Identity()) - 0.5 * dt_average_ * dv_grad;
    force_work_[p] = -loads_[p].minus_volume_stress.cwiseProduct(mean_motion).sum();
    const double J = dF.determinant();
    if (points.failed(p) && !(J > 0.0)) {
      // Failed material crushed through itself by its nodes is tangled debris: released to fly
      // on with its velocity (stress-free from now on) rather than stopping the run.
      points.carrier[p] = -1;
      points.stress[p].setZero();
      points.viscous_pressure[p] = 0.0;
      points.energy[p] += heat / points.mass[p];
      transfer_heat_[p] = 0.0;
      points.x[p] += dt_step_ * points.v[p];
      points.dF[p].setIdentity();
      continue;
    }
    if ((!(J > 0.0) || !std::isfinite(J)) && own.own(p)) bad = std::min(bad, p);
    j_point_[p] = J;
    points.x[p] += dx;
    points.v[p] += dv;
    points.dF[p] = dF;
  }
  share().stopTogether(
      bad < points.owned,
      [&] {
        failAtPoint(bad, fmt::format("volume inverted or collapsed: det(dF) = {:.6g} over the step",
                                     points.dF[bad].determinant()));
      },
      kAnotherRank);
  // A ghost node's means come from its owner, which holds all its points.
  std::function<void(VolumePatch::NodeMeans&)> refresh_means;
  if (distribution_) refresh_means = [&](VolumePatch::NodeMeans& means) { distribution_->refreshNodes(means); };
  stabilisation_energy_ +=
      patch_.apply(conn, model_.nodes.owned, settings_.volume_averaging, settings_.volume_stabilisation,
                   settings_.volume_relaxation, dt_step_, points, j_point_, own, refresh_means);
  // A ghost point near the edge of the halo moved with nodes it may not all hold, and averaged over
  // patches it may not all see: its owner's values replace what this rank got.
  if (distribution_) {
    const Stopwatch watch;
    distribution_->refreshPoints(points);
    for (std::vector<double>* a : {&j_point_, &transfer_heat_, &force_work_}) distribution_->refreshPoints(*a);
    patch_.forEachPointArray([&](std::vector<double>& a) { distribution_->refreshPoints(a); });
    refresh_seconds_ += watch.seconds();  // booked as "halo", not "point update" (advance())
  }
  volume_rate_.resize(static_cast<std::size_t>(points.owned));
#pragma omp parallel for schedule(static)
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (points.debris(p)) {
      volume_rate_[p] = 0.0;
      continue;
    }
    points.F[p] = points.dF[p] * points.F[p];
    points.volume[p] *= j_point_[p];
    volume_rate_[p] = std::log(j_point_[p]) / dt_step_;
  }
}

// The compatible energy update (Caramana, Burton, Shashkov & Whalen, JCP 146:227, 1998): each point
// takes as internal energy exactly the work its forces did on the nodes over the step (updatePoints),
// less what the volume stabilisation stored. The material's own update books P dV with the averaged
// volume change and the trapezoidal rule; the difference, small and of either sign, is added as heat,
// so that kinetic, internal and stabilisation energy balance step by step (docs/theory.md §4 step 5).
// Intact points only: the forces of failed material (compression only) also carry a seizing
// contact's inelastic merge, which given to them as heat made a few contact points 20,000 K hot;
// that loss stays unbooked (the energy error of an impact). Points of a law without a thermal state
// take none (Material::heat).
void Integrator::balanceEnergy() {
  PointStore& points = model_.points;
  const std::vector<double>& stored = patch_.work();  // apply() sizes it every step
#pragma omp parallel for schedule(static)
  for (LocalIndex p = 0; p < points.owned; ++p)
    transfer_heat_[p] = points.broken[p] ? 0.0 : force_work_[p] - stored[p] - points.mass[p] * points.energy[p];
  heatBodies(model_, body_points_, transfer_heat_);
}

void Integrator::updateMaterials(double dt) {
  PointStore& points = model_.points;
  if (dt > 0.0) {
    heatBodies(model_, body_points_, transfer_heat_);
    // What each point's energy must be after the step, less the stabilisation's share (balanceEnergy).
#pragma omp parallel for schedule(static)
    for (LocalIndex p = 0; p < points.owned; ++p) force_work_[p] += points.mass[p] * points.energy[p];
  }
  // A material that refuses a point's state stops every rank (the others hold no copy of it).
  LocalIndex refused = -1;
  std::string why;
  try {
    updateBodies(model_, body_points_, dt);
  } catch (const PointError& e) {
    refused = static_cast<LocalIndex>(e.point());
    why = e.what();
  }
  share().stopTogether(
      refused >= 0, [&] { failAtPoint(refused, why); }, kAnotherRank);
  LocalIndex bad = points.owned;
  const Share own = share();
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (LocalIndex p = 0; p < points.owned; ++p)
    if (own.own(p) && (!points.stress[p].allFinite() || !std::isfinite(points.energy[p]) ||
                       !(points.debris(p) || points.sound_speed[p] >= 0.0)))  // debris takes no part in the time step
      bad = std::min(bad, p);
  share().stopTogether(
      bad < points.owned,
      [&] { failAtPoint(bad, "the material update gave a non-finite stress, energy or sound speed"); }, kAnotherRank);
}

double stepLength(const Model& model, LocalIndex p) {
  const PointStore& points = model.points;
  // Failed material has no shear stiffness and its F is history only (its shape functions, as
  // everyone's, are built on the current nodes with support h): its length is its current spacing.
  if (points.failed(p)) return points.spacing(p);
  const double stretch = smallestStretch(points.F[p]);
  const double stretched = points.spacing0[p] * stretch;
  // stretched >= flattened * spacing, with the spacing h0 (V/V0)^(1/3), without the cube root.
  if (stretch * stretch * stretch >= flattened * flattened * flattened * points.volume[p] / points.volume0[p])
    return stretched;
  const double spacing = points.spacing(p);
  // A flattened point: its support is rebuilt on the current nodes within a sphere, so its gradients,
  // which set the stiffness the step must resolve, vary over the spread of those nodes, not over the
  // thickness its F has squeezed it to.
  const Connectivity& conn = model.connectivity;
  Mat3 covariance = Mat3::Zero();
  for (Index e = conn.offset[p]; e < conn.offset[p + 1]; ++e) {
    const Vec3 d = model.nodes.x[conn.node[e]] - points.x[p];
    covariance.noalias() += conn.N[e] * d * d.transpose();
  }
  return std::max(stretched, std::min(spacing, support_lengths * smallestRootEigenvalue(covariance)));
}

// The stable step over material points (solver/common/stable_step.hpp), each measured by stepLength,
// and no longer than debris contact allows.
double Integrator::stableStep() const {
  const double bound = settings_.debris_contact ? contact_.stepBound() : std::numeric_limits<double>::infinity();
  return kessler::stableStep(
      model_.points, volume_rate_, bound, settings_.cfl, [&](LocalIndex p) { return stepLength(model_, p); }, share());
}

Energies Integrator::energies() const {
  return pointEnergies(model_.points, stabilisation_energy_ + contact_.storedEnergy(), share());
}

void Integrator::failAtPoint(LocalIndex p, const std::string& what) const {
  const PointStore& points = model_.points;
  const Vec3& x = points.x[p];
  throw NumericalError(fmt::format("material point {} of body '{}' at ({:.6g}, {:.6g}, {:.6g}) m: {}", points.id[p],
                                   model_.bodies[points.body[p]].name, x[0], x[1], x[2], what));
}

}  // namespace kessler::otm
