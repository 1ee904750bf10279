#include "solver/common/debris_contact.hpp"

#include "core/exact_sum.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace kessler {

namespace {

// Critical damping of each pair: a linear spring-dashpot with zeta = 1 whose force may only push
// lets go at t = 2 / omega with e^-2 of the approach speed (restitution 0.14).
constexpr double damping_ratio = 1.0;

// A node lighter than this share of its body's mass per node carries no material a strike could
// meet: LME lumps a ten-thousandth of the others' mass, or less, on a few surface nodes. Debris does
// not strike those; kicking one (its Delta v as large as the debris' own) broke the energy of a
// strike, and bounding the step by its springs collapsed the step.
constexpr double least_struck_node_mass = 0.1;

// A pair's spring for spacings h and moduli K: the two halves in series over the smaller face.
double stiffness(double h_a, double modulus_a, double h_b, double modulus_b) {
  const double h_min = std::min(h_a, h_b);
  return h_min * h_min / (0.5 * h_a / modulus_a + 0.5 * h_b / modulus_b);
}

}  // namespace

bool mayStrike(const PointStore& points, LocalIndex p, std::size_t bodies) {
  if (!points.debris(p) || bodies > max_contact_bodies) return false;
  const std::uint64_t every_body =
      bodies == max_contact_bodies ? ~std::uint64_t{0} : (bodyBit(static_cast<int>(bodies)) - 1);
  const auto passes = static_cast<std::uint64_t>(points.passes_through[p]);
  return passes != 0 && (passes & every_body) != every_body;
}

void DebrisContact::apply(ParticleState& model, const Carriers& nodes, double dt_kick, const Share& share) {
  PointStore& points = model.points;
  stored_ = 0.0;
  step_bound_ = std::numeric_limits<double>::infinity();
  const std::size_t bodies = model.bodies.size();
  if (bodies > max_contact_bodies) return;
  auto flying = [&](LocalIndex p) { return mayStrike(points, p, bodies); };
  bool any = false;
  for (LocalIndex p = 0; p < points.owned && !any; ++p) any = share.own(p) && flying(p);
  if (!share.any(any)) return;
  auto total = [&](ExactSum& sum) { return share.comm ? share.comm->sum(sum) : sum.value(); };
  auto ownNode = [&](LocalIndex a) { return nodes.ghost.empty() || nodes.ghost[static_cast<std::size_t>(a)] == 0; };

  if (body_spacing_.size() != bodies) {
    // Each body's mean reference spacing and reference modulus, and its mass per node: fixed for a
    // run (so a restarted run finds the same), found once, over every rank.
    std::vector<ExactSum> spacing(bodies), mass(bodies);
    std::vector<std::int64_t> count(2 * bodies, 0);  // each body's points, then its nodes
    for (LocalIndex p = 0; p < points.owned; ++p) {
      if (!share.own(p)) continue;
      const auto b = static_cast<std::size_t>(points.body[p]);
      spacing[b].add(points.spacing0[p]);
      mass[b].add(points.mass[p]);
      ++count[b];
    }
    for (LocalIndex a = 0; a < nodes.owned; ++a)
      if (ownNode(a)) ++count[bodies + static_cast<std::size_t>(nodes.body[a])];
    if (share.comm) share.comm->sum(count);
    body_spacing_.assign(bodies, 0.0);
    body_modulus_.assign(bodies, 0.0);
    body_node_mass_.assign(bodies, 0.0);
    for (std::size_t b = 0; b < bodies; ++b) {
      const double points_b = total(spacing[b]), mass_b = total(mass[b]);
      if (count[b] > 0) body_spacing_[b] = points_b / static_cast<double>(count[b]);
      if (count[bodies + b] > 0) body_node_mass_[b] = mass_b / static_cast<double>(count[bodies + b]);
      const Material& material = *model.materials[static_cast<std::size_t>(model.bodies[b].material)];
      const double c = material.referenceSoundSpeed();
      body_modulus_[b] = material.referenceDensity() * c * c;
    }
  }
  const double largest = *std::max_element(body_spacing_.begin(), body_spacing_.end());
  // Cells of one size on every rank: they order each debris point's pairs.
  double cell = std::max(largest, 1e-300);
  if (share.comm) {
    std::int64_t own = 0;
    for (LocalIndex a = 0; a < nodes.owned; ++a) own += ownNode(a) ? 1 : 0;
    cell = agreedCellSize(nodes.x, static_cast<LocalIndex>(nodes.x.size()), own, cell, share);
  }
  cells_.build(nodes.x, static_cast<LocalIndex>(nodes.x.size()), cell, /*enlarge=*/!share.comm);
  ExactSum stored;
  node_pairs_.resize(nodes.x.size(), 0);
  node_dv_.resize(nodes.x.size(), Vec3::Zero());
  node_stiffness_.resize(nodes.x.size(), 0.0);
  touched_.clear();

  // The pairs of every flying debris point first, so that each node knows how many it has.
  pairs_.clear();
  strikes_.clear();
  for (LocalIndex d = 0; d < points.owned; ++d) {
    if (!flying(d)) continue;
    const auto passes = static_cast<std::uint64_t>(points.passes_through[d]);
    const double h_d = points.spacing0[d];
    const double modulus_d = body_modulus_[static_cast<std::size_t>(points.body[d])];
    const double m_d = points.mass[d];
    // Twice the largest contact radius, and what the point flies in two steps: every node it may
    // meet within the next step is seen, and bounds the step.
    const double reach = (h_d + largest) + 2.0 * points.v[d].norm() * dt_kick;
    const std::size_t begin = pairs_.size();
    cells_.forEachWithin(points.x[d], reach, [&](LocalIndex a, double d2) {
      const int b = nodes.body[a];
      if (((passes >> b) & 1u) || nodes.mass[a] < least_struck_node_mass * body_node_mass_[static_cast<std::size_t>(b)])
        return;
      const double h_b = body_spacing_[static_cast<std::size_t>(b)];
      const double radius = 0.5 * (h_d + h_b);
      const double dist = std::sqrt(d2);
      const Vec3 v_a = nodes.momentum[a] / nodes.mass[a];
      const Vec3 relative = points.v[d] - v_a;
      if (dist > 0.0 && relative.norm() > 0.0) step_bound_ = std::min(step_bound_, radius / relative.norm());
      const double k = stiffness(h_d, modulus_d, h_b, body_modulus_[static_cast<std::size_t>(b)]);
      // A node's pairs that may touch within the next step count in its bound already: the first
      // step of a contact must resolve it too. The travel bound keeps a pair from closing by more
      // than cfl (< 1/2) of its radius in a step, so those within 1.5 radii are the ones.
      if (dist < 1.5 * radius) {
        if (node_stiffness_[a] == 0.0) touched_.push_back(a);
        node_stiffness_[a] += k;
      }
      if (dist >= radius || dist <= 0.0) return;
      Pair pair;
      pair.node = a;
      pair.n = (points.x[d] - nodes.x[a]) / dist;  // from the node to the debris
      const double overlap = radius - dist;
      pair.approach = -relative.dot(pair.n);
      pair.spring = k * overlap;
      pair.k = k;
      pair.m = m_d * nodes.mass[a] / (m_d + nodes.mass[a]);
      pair.c = 2.0 * damping_ratio * std::sqrt(k * pair.m);
      if (share.own(d)) stored.add(0.5 * k * overlap * overlap);
      ++node_pairs_[static_cast<std::size_t>(a)];
      pairs_.push_back(pair);
    });
    if (pairs_.size() > begin) strikes_.push_back(Strike{d, begin, pairs_.size()});
  }
  // A ghost carrier's pairs with debris this rank does not hold are counted by its owner.
  if (nodes.refresh_pairs) nodes.refresh_pairs(node_pairs_);
  // Each pair's force from the approach speed u' it leaves after the kick. Spring and dashpot act
  // on the state at the end of the step (implicit, u' = u - (k (overlap + u' dt) + c u') dt / m), so
  // that no step, however long, lets the pair overshoot, with each pair stopping a share m / n of its
  // reduced mass's motion, n the larger of its debris point's and its node's numbers of pairs: the
  // pairs of one debris point, or of one node struck by many, cannot together stop more than its
  // motion, and neither needs a bound on the step. No kick gives the pair more speed apart than its
  // spring's energy could, sqrt(k / m) overlap.
  for (Strike& strike : strikes_) {
    const double m_d = points.mass[strike.debris];
    const auto own = static_cast<int>(strike.end - strike.begin);
    const std::span<Pair> pairs(pairs_.data() + strike.begin, strike.end - strike.begin);
    for (Pair& pair : pairs) {
      const double m = pair.m / static_cast<double>(std::max(own, node_pairs_[static_cast<std::size_t>(pair.node)]));
      const double rate = dt_kick / m;
      double approach_after = (pair.approach - pair.spring * rate) / (1.0 + (pair.c + pair.k * dt_kick) * rate);
      approach_after = std::max(approach_after, -std::sqrt(pair.spring * pair.spring / (pair.k * m)));
      pair.force = std::max(m * (pair.approach - approach_after) / dt_kick, 0.0);
      strike.dv += (dt_kick * pair.force / m_d) * pair.n;
      node_dv_[static_cast<std::size_t>(pair.node)] -= (dt_kick * pair.force / nodes.mass[pair.node]) * pair.n;
    }
  }
  if (nodes.refresh_kicks) nodes.refresh_kicks(node_dv_);
  // The heat: the work the kick takes from each pair's relative motion (the force times the approach
  // speed at the middle of the kick, from the kicks of all the pairs of the debris point and of the
  // node) less what the spring stores by the end of the step, where the overlap will be
  // (overlap + u' dt), u' the approach speed the kicks leave.
  for (const Strike& strike : strikes_) {
    const LocalIndex d = strike.debris;
    const std::span<const Pair> pairs(pairs_.data() + strike.begin, strike.end - strike.begin);
    double heat = 0.0;
    for (const Pair& pair : pairs) {
      const LocalIndex a = pair.node;
      const double approach_after = pair.approach - (strike.dv - node_dv_[static_cast<std::size_t>(a)]).dot(pair.n);
      const double overlap = pair.spring / pair.k;
      const double overlap_after = std::max(overlap + approach_after * dt_kick, 0.0);
      heat += pair.force * 0.5 * (pair.approach + approach_after) * dt_kick -
              0.5 * pair.k * (overlap_after * overlap_after - overlap * overlap);
      nodes.force[a] -= pair.force * pair.n;
    }
    points.v[d] += strike.dv;
    points.energy[d] += heat / points.mass[d];
    points.strike(d, nodes.body[pairs.front().node]);
  }
  if (nodes.refresh_pairs || nodes.refresh_kicks) {  // ghosts' owners may have set any carrier's
    std::fill(node_pairs_.begin(), node_pairs_.end(), 0);
    std::fill(node_dv_.begin(), node_dv_.end(), Vec3::Zero());
  }
  for (const Pair& pair : pairs_) {
    node_pairs_[static_cast<std::size_t>(pair.node)] = 0;
    node_dv_[static_cast<std::size_t>(pair.node)].setZero();
  }
  // Each node's springs together, with its body's mass per node: many debris points may strike one
  // node in a step. (The shares above keep a node from being overshot at any step; this bound keeps
  // a strike's energy. A node's own mass, which may be a tenth of that, would cost steps for no
  // accuracy.)
  for (const LocalIndex a : touched_) {
    const double mass = body_node_mass_[static_cast<std::size_t>(nodes.body[a])];
    step_bound_ = std::min(step_bound_, std::sqrt(mass / node_stiffness_[a]));
    node_stiffness_[a] = 0.0;
  }
  stored_ = total(stored);
}

}  // namespace kessler
