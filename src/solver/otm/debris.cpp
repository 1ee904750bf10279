#include "solver/otm/debris.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace kessler::otm {

namespace {

std::uint64_t bodyBit(int body) {
  return std::uint64_t{1} << body;
}

// Critical damping of each pair: a linear spring-dashpot with zeta = 1 whose force may only push
// lets go at t = 2 / omega with e^-2 of the approach speed (restitution 0.14).
constexpr double damping_ratio = 1.0;

}  // namespace

void markNewDebris(Model& model) {
  PointStore& points = model.points;
  const bool contact = model.bodies.size() <= max_debris_bodies;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (!points.debris(p) || points.passes_through[p] != 0) continue;
    const BodyInfo& body = model.bodies[static_cast<std::size_t>(points.body[p])];
    const std::uint64_t bits = contact ? bodyBit(points.body[p]) | body.touched : ~std::uint64_t{0};
    points.passes_through[p] = static_cast<std::int64_t>(bits);
  }
}

void recordContacts(Model& model, std::span<const std::uint64_t> touching) {
  const std::size_t bodies = model.bodies.size();
  if (bodies > max_debris_bodies) return;
  for (std::size_t a = 0; a < bodies; ++a) {
    model.bodies[a].touched |= bodyBit(static_cast<int>(a));
    for (std::size_t b = 0; b < bodies; ++b)
      if ((touching[a] >> b) & 1u) {
        model.bodies[a].touched |= bodyBit(static_cast<int>(b));
        model.bodies[b].touched |= bodyBit(static_cast<int>(a));
      }
  }
}

void DebrisContact::apply(Model& model, double dt_kick) {
  PointStore& points = model.points;
  NodeStore& nodes = model.nodes;
  stored_ = 0.0;
  step_bound_ = std::numeric_limits<double>::infinity();
  const std::size_t bodies = model.bodies.size();
  if (bodies > max_debris_bodies) return;
  const std::uint64_t every_body =
      bodies == max_debris_bodies ? ~std::uint64_t{0} : (bodyBit(static_cast<int>(bodies)) - 1);
  // Debris in flight that some body may stop (passes_through is 0 until markNewDebris).
  auto flying = [&](LocalIndex p) {
    const auto passes = static_cast<std::uint64_t>(points.passes_through[p]);
    return points.debris(p) && passes != 0 && (passes & every_body) != every_body;
  };
  bool any = false;
  for (LocalIndex p = 0; p < points.owned && !any; ++p) any = flying(p);
  if (!any) return;

  if (body_spacing_.size() != bodies) {
    // Each body's mean reference spacing and reference modulus: fixed for a run, found once.
    body_spacing_.assign(bodies, 0.0);
    body_modulus_.assign(bodies, 0.0);
    for (std::size_t b = 0; b < bodies; ++b) {
      const BodyInfo& body = model.bodies[b];
      const LocalIndex begin = body.point_begin, end = std::min(body.point_end, points.owned);
      double sum = 0.0;
      for (LocalIndex p = begin; p < end; ++p) sum += points.spacing0[p];
      body_spacing_[b] = end > begin ? sum / static_cast<double>(end - begin) : 0.0;
      const Material& material = *model.materials[static_cast<std::size_t>(body.material)];
      const double c = material.referenceSoundSpeed();
      body_modulus_[b] = material.referenceDensity() * c * c;
    }
  }
  const double largest = *std::max_element(body_spacing_.begin(), body_spacing_.end());
  cells_.build(nodes.x, nodes.size(), std::max(largest, 1e-300));
  node_stiffness_.resize(static_cast<std::size_t>(nodes.size()), 0.0);
  touched_.clear();

  for (LocalIndex d = 0; d < points.owned; ++d) {
    if (!flying(d)) continue;
    const auto passes = static_cast<std::uint64_t>(points.passes_through[d]);
    const int own = points.body[d];
    const double h_d = points.spacing0[d];
    const double modulus_d = body_modulus_[static_cast<std::size_t>(own)];
    const double m_d = points.mass[d];
    const double speed = points.v[d].norm();
    // Twice the largest contact radius, and what the point flies in two steps: every node it may
    // meet within the next step is seen, and bounds the step.
    const double reach = (h_d + largest) + 2.0 * speed * dt_kick;
    pairs_.clear();
    cells_.forEachWithin(points.x[d], reach, [&](LocalIndex a, double d2) {
      const int b = nodes.body[a];
      if (nodes.mass[a] <= 0.0 || ((passes >> b) & 1u)) return;
      const double h_b = body_spacing_[static_cast<std::size_t>(b)];
      const double radius = 0.5 * (h_d + h_b);
      const double dist = std::sqrt(d2);
      const Vec3 v_a = nodes.momentum[a] / nodes.mass[a];
      const Vec3 relative = points.v[d] - v_a;
      if (dist > 0.0 && relative.norm() > 0.0) step_bound_ = std::min(step_bound_, radius / relative.norm());
      const double h_min = std::min(h_d, h_b);
      // The debris' half and the body's half in series, over the smaller face.
      const double k = h_min * h_min / (0.5 * h_d / modulus_d + 0.5 * h_b / body_modulus_[static_cast<std::size_t>(b)]);
      const double m_reduced = m_d * nodes.mass[a] / (m_d + nodes.mass[a]);
      const double c = 2.0 * damping_ratio * std::sqrt(k * m_reduced);
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
      pair.c = c;
      pair.m = m_reduced;
      stored_ += 0.5 * k * overlap * overlap;
      pairs_.push_back(pair);
    });
    if (pairs_.empty()) continue;
    // Each pair's force from the approach speed u' it leaves after the kick. Spring and dashpot act
    // on the state at the end of the step (implicit, u' = u - (k (overlap + u' dt) + c u') dt / m), so
    // that no step, however long, lets the pair overshoot (the debris point's own springs need no
    // step bound), with each of the debris point's n pairs stopping a share m / n of it; and no kick
    // gives the pair more speed apart than its spring's energy could, sqrt(k / m) overlap.
    const double share = 1.0 / static_cast<double>(pairs_.size());
    for (Pair& pair : pairs_) {
      const double m = share * pair.m;
      const double rate = dt_kick / m;
      double approach_after = (pair.approach - pair.spring * rate) / (1.0 + (pair.c + pair.k * dt_kick) * rate);
      approach_after = std::max(approach_after, -std::sqrt(pair.spring * pair.spring / (pair.k * m)));
      pair.force = std::max(m * (pair.approach - approach_after) / dt_kick, 0.0);
    }
    Vec3 dv = Vec3::Zero();
    for (const Pair& pair : pairs_) dv += (dt_kick * pair.force / m_d) * pair.n;
    // The heat: the work the kick takes from the pair's relative motion (the force times the approach
    // speed at the middle of the kick, exact for the debris' kinetic energy) less what the spring
    // stores by the end of the step, where the overlap will be (overlap + u' dt), u' the approach
    // speed the kick leaves.
    double heat = 0.0;
    for (const Pair& pair : pairs_) {
      const LocalIndex a = pair.node;
      const double node_dv = dt_kick * pair.force / nodes.mass[a];
      const double approach_after = pair.approach - (dv.dot(pair.n) + node_dv);
      const double overlap = pair.spring / pair.k;
      const double overlap_after = std::max(overlap + approach_after * dt_kick, 0.0);
      heat += pair.force * 0.5 * (pair.approach + approach_after) * dt_kick -
              0.5 * pair.k * (overlap_after * overlap_after - overlap * overlap);
      nodes.force[a] -= pair.force * pair.n;
    }
    points.v[d] += dv;
    points.energy[d] += heat / m_d;
    points.strike(d, nodes.body[pairs_.front().node]);
  }
  // Each node's springs together: many debris points may strike one node in a step.
  for (const LocalIndex a : touched_) {
    step_bound_ = std::min(step_bound_, std::sqrt(nodes.mass[a] / node_stiffness_[a]));
    node_stiffness_[a] = 0.0;
  }
}

}  // namespace kessler::otm
