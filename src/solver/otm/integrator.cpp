#include "solver/otm/integrator.hpp"

#include "core/error.hpp"
#include "core/reduce.hpp"
#include "solver/otm/debris.hpp"
#include "solver/otm/integrator_assembly.hpp"
#include "solver/otm/integrator_ordering.hpp"
#include "solver/otm/release.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kessler::otm {

Integrator::Integrator(Model& model, const Settings& settings)
    : model_(model), settings_(settings), neighbourhoods_(settings), erosion_(settings), release_(settings) {
  KESSLER_VERIFY(settings.cfl > 0.0 && settings.cfl <= 1.0, "cfl must lie in (0, 1], got {}", settings.cfl);
  KESSLER_VERIFY(settings.end_time > 0.0, "end_time must be positive, got {}", settings.end_time);
}

void Integrator::initialise() {
  // Points and nodes in Morton order, once, before anything refers to their indices (the first
  // output and checkpoint already see this order, so a restart continues with it).
  sortForLocality(model_);
  for (const BodyInfo& body : model_.bodies)
    model_.materials[body.material]->initialise(model_.points, body.point_begin,
                                                std::min(body.point_end, model_.points.owned));
  {
    ScopedPhase phase(timers_, "constitutive");
    updateMaterials(0.0);
  }
  neighbourhoods_.update(model_);
  timers_.add("search", neighbourhoods_.searchSeconds());
  timers_.add("shape functions", neighbourhoods_.shapeSeconds());
  dt_next_ = dt_initial_ = stableStep();
}

void Integrator::restore(const IntegratorState& state) {
  time_ = state.time;
  dt_last_ = state.dt_last;
  dt_next_ = state.dt_next;
  dt_initial_ = state.dt_initial;
  steps_ = state.steps;
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
  }
  {
    ScopedPhase phase(timers_, "node update");
    // Discrete Euler-Lagrange equations for a variable step (DESIGN.md §2 step 5).
    updateNodes(dt, 0.5 * (dt_last_ + dt));
  }
  {
    ScopedPhase phase(timers_, "point update");
    updatePoints();
  }
  {
    ScopedPhase phase(timers_, "constitutive");
    updateMaterials(dt);
  }
  {
    ScopedPhase phase(timers_, "erosion");
    eroded_ += erosion_.apply(model_);
    release_.apply(model_);
    if (settings_.debris_capture) markNewDebris(model_);
  }
  neighbourhoods_.update(model_);
  timers_.add("search", neighbourhoods_.searchSeconds());
  timers_.add("shape functions", neighbourhoods_.shapeSeconds());
  if (!neighbourhoods_.caught().empty()) {
    ScopedPhase phase(timers_, "erosion");
    catchDebris(model_, neighbourhoods_.caught());
  }
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
  otm::assembleNodes(model_.connectivity, model_.points, model_.nodes, loads_);
}

void Integrator::updateNodes(double dt, double dt_average) {
  NodeStore& nodes = model_.nodes;
  dt_step_ = dt;
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
    for (int i = 0; i < 3; ++i)
      if (nodes.constrained[a] & (1u << i)) v_new[i] = nodes.prescribed_v[a][i];
    // A rigid wall stops the normal motion that would carry the node through it.
    for (const RigidWall& wall : settings_.walls) {
      const double gap = nodes.x[a][wall.axis] - wall.position;
      if (wall.side * (gap + dt * v_new[wall.axis]) < 0.0) v_new[wall.axis] = -gap / dt;
    }
    increment_[a].dv = v_new - v_old;
    increment_[a].du = dt * v_new;
    nodes.v[a] = v_new;
    nodes.x[a] += increment_[a].du;
  }
}

// Material points follow the nodes (DESIGN.md §2 step 6), written with displacements so that
// round-off does not grow with the distance from the origin:
//   x_p += sum_a N_a u_a,  dF = I + sum_a u_a (x) grad N_a,  F <- dF F,  V <- det(dF) V.
// Velocities take the nodal increment (FLIP-style), which conserves momentum exactly and,
// unlike re-interpolating the nodal velocity, does not damp the resolved motion.
void Integrator::updatePoints() {
  PointStore& points = model_.points;
  const Connectivity& conn = model_.connectivity;
  LocalIndex bad = points.owned;
  j_point_.resize(static_cast<std::size_t>(points.owned));  // det(dF) of each point of the bodies
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (points.debris(p) && points.carrier[p] < 0) {
      // Debris in flight: ballistic, with the point's own velocity.
      points.x[p] += dt_step_ * points.v[p];
      points.dF[p].setIdentity();
      continue;
    }
    Vec3 dx = Vec3::Zero(), dv = Vec3::Zero();
    Mat3 dF = Mat3::Identity();
    for (Index e = conn.offset[p]; e < conn.offset[p + 1]; ++e) {
      const NodeIncrement& node = increment_[conn.node[e]];
      dx += conn.N[e] * node.du;
      dv += conn.N[e] * node.dv;
      dF.noalias() += node.du * conn.dN[e].transpose();
    }
    if (points.debris(p)) {
      // Debris a body has caught: carried by its nodes, with no strain of its own.
      points.x[p] += dx;
      points.v[p] += dv;
      points.dF[p].setIdentity();
      continue;
    }
    const double J = dF.determinant();
    if (points.failed(p) && !(J > 0.0)) {
      // Failed material crushed through itself by its nodes is tangled debris: released to fly
      // on with its velocity (stress-free from now on) rather than stopping the run.
      points.carrier[p] = -1;
      points.stress[p].setZero();
      points.viscous_pressure[p] = 0.0;
      points.x[p] += dt_step_ * points.v[p];
      points.dF[p].setIdentity();
      continue;
    }
    if (!(J > 0.0) || !std::isfinite(J)) bad = std::min(bad, p);
    j_point_[p] = J;
    points.x[p] += dx;
    points.v[p] += dv;
    points.dF[p] = dF;
  }
  if (bad < points.owned)
    failAtPoint(
        bad, fmt::format("volume inverted or collapsed: det(dF) = {:.6g} over the step", points.dF[bad].determinant()));
  if (settings_.volume_averaging) averageVolumeChange();
#pragma omp parallel for schedule(static)
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (points.debris(p)) continue;
    points.F[p] = points.dF[p] * points.F[p];
    points.volume[p] *= j_point_[p];
  }
}

// Volume averaging (F-bar over the nodal patch; docs/theory.md §4): the step's volume change
// det(dF) of the points of the bodies (intact or failed, not debris) is averaged, mass-weighted, to the nodes and
// interpolated back, and each point's dF is scaled isotropically to that average. Point-wise volume noise, which in a
// strong shock left some points at twice the density of their neighbours, is removed; the deviatoric part of dF, the
// motion and the momentum are untouched. A body at rest stays bitwise at rest (the weights are normalised by the same
// sums).
void Integrator::averageVolumeChange() {
  PointStore& points = model_.points;
  const Connectivity& conn = model_.connectivity;
  j_node_.resize(static_cast<std::size_t>(model_.nodes.size()));
  j_weight_.resize(static_cast<std::size_t>(points.owned));
#pragma omp parallel
  {
    // The weights packed per point first, so that the gather reads one record per entry.
#pragma omp for schedule(static)
    for (LocalIndex p = 0; p < points.owned; ++p)
      j_weight_[p] = points.debris(p) ? std::array<double, 2>{0.0, 0.0}
                                      : std::array<double, 2>{points.mass[p], points.mass[p] * j_point_[p]};
#pragma omp for schedule(static)
    for (LocalIndex a = 0; a < model_.nodes.owned; ++a) {
      double m = 0.0, mj = 0.0;
      for (Index k = conn.node_offset[a]; k < conn.node_offset[a + 1]; ++k) {
        const Connectivity::NodeSlot slot = conn.node_slot[k];
        const double N = conn.N[slot.entry];
        const std::array<double, 2>& w = j_weight_[slot.point];
        m += N * w[0];
        mj += N * w[1];
      }
      j_node_[a] = m > 0.0 ? mj / m : 1.0;
    }
  }
#pragma omp parallel for schedule(static)
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (points.debris(p)) continue;
    double weight = 0.0, average = 0.0;
    for (Index e = conn.offset[p]; e < conn.offset[p + 1]; ++e) {
      weight += conn.N[e];
      average += conn.N[e] * j_node_[conn.node[e]];
    }
    if (weight > 0.0 && average > 0.0) {
      points.dF[p] *= std::cbrt(average / weight / j_point_[p]);
      j_point_[p] = points.dF[p].determinant();
    }
  }
}

void Integrator::updateMaterials(double dt) {
  PointStore& points = model_.points;
  for (const BodyInfo& body : model_.bodies)
    model_.materials[body.material]->update(points, body.point_begin, std::min(body.point_end, points.owned), dt);
  LocalIndex bad = points.owned;
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (LocalIndex p = 0; p < points.owned; ++p)
    if (!points.stress[p].allFinite() || !std::isfinite(points.energy[p]) ||
        !(points.debris(p) || points.sound_speed[p] > 0.0))  // debris takes no part in the time step
      bad = std::min(bad, p);
  if (bad < points.owned) failAtPoint(bad, "the material update gave a non-finite stress, energy or sound speed");
}

double smallestStretch(const Mat3& F) {
  Eigen::SelfAdjointEigenSolver<Mat3> eigen;
  eigen.computeDirect(F.transpose() * F, Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(eigen.eigenvalues()[0], 0.0));
}

double stepLength(const PointStore& points, LocalIndex p) {
  // Failed material has no shear stiffness and its F is history only (its shape functions, as
  // everyone's, are built on the current nodes with support h): its length is its current spacing.
  if (points.failed(p)) return points.spacing(p);
  return points.spacing0[p] * smallestStretch(points.F[p]);
}

// CFL condition over material points: dt = cfl * min_p l_p / c_p (DESIGN.md §2 step 9). The
// length l_p is the reference spacing times the smallest principal stretch of F: plastic flow
// keeps the volume (so h0 J^(1/3) would not shrink) while it can flatten the material, and the
// nodes, to a fraction of their spacing in one direction.
double Integrator::stableStep() const {
  const PointStore& points = model_.points;
  double dt = std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static) reduction(min : dt)
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (points.debris(p)) continue;
    dt = std::min(dt, stepLength(points, p) / points.sound_speed[p]);
  }
  KESSLER_VERIFY(std::isfinite(dt) && dt > 0.0, "no stable time step: every point is debris or the model is empty");
  return settings_.cfl * dt;
}

Energies Integrator::energies() const {
  const PointStore& points = model_.points;
  Energies e;
  e.kinetic = deterministicSum(points.owned, 0.0,
                               [&](LocalIndex p) { return 0.5 * points.mass[p] * points.v[p].squaredNorm(); });
  e.internal = deterministicSum(points.owned, 0.0, [&](LocalIndex p) { return points.mass[p] * points.energy[p]; });
  e.momentum = deterministicSum(points.owned, Vec3(Vec3::Zero()),
                                [&](LocalIndex p) -> Vec3 { return points.mass[p] * points.v[p]; });
  return e;
}

void Integrator::failAtPoint(LocalIndex p, const std::string& what) const {
  const PointStore& points = model_.points;
  const Vec3& x = points.x[p];
  throw NumericalError(fmt::format("material point {} of body '{}' at ({:.6g}, {:.6g}, {:.6g}) m: {}", points.id[p],
                                   model_.bodies[points.body[p]].name, x[0], x[1], x[2], what));
}

}  // namespace kessler::otm
