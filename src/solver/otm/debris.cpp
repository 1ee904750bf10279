#include "solver/otm/debris.hpp"

#include <cstdint>
#include <vector>

namespace kessler::otm {

namespace {

std::uint64_t bodyBit(int body) {
  return std::uint64_t{1} << body;
}

}  // namespace

void markNewDebris(Model& model) {
  PointStore& points = model.points;
  const bool capture = model.bodies.size() <= max_capturing_bodies;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (!points.debris(p) || points.passes_through[p] != 0) continue;
    const BodyInfo& body = model.bodies[static_cast<std::size_t>(points.body[p])];
    const std::uint64_t bits = capture ? bodyBit(points.body[p]) | body.touched : ~std::uint64_t{0};
    points.passes_through[p] = static_cast<std::int64_t>(bits);
  }
}

void recordContacts(Model& model, std::span<const std::uint64_t> touching) {
  const std::size_t bodies = model.bodies.size();
  if (bodies > max_capturing_bodies) return;
  for (std::size_t a = 0; a < bodies; ++a) {
    model.bodies[a].touched |= bodyBit(static_cast<int>(a));
    for (std::size_t b = 0; b < bodies; ++b)
      if ((touching[a] >> b) & 1u) {
        model.bodies[a].touched |= bodyBit(static_cast<int>(b));
        model.bodies[b].touched |= bodyBit(static_cast<int>(a));
      }
  }
}

double catchDebris(Model& model, std::span<const LocalIndex> caught) {
  PointStore& points = model.points;
  const Connectivity& conn = model.connectivity;
  const NodeStore& nodes = model.nodes;
  double dissipated = 0.0;
  auto kinetic = [&](LocalIndex p) { return 0.5 * points.mass[p] * points.v[p].squaredNorm(); };
  for (const LocalIndex d : caught) {
    Vec3 v_nodes = Vec3::Zero();
    for (Index e = conn.offset[d]; e < conn.offset[d + 1]; ++e) v_nodes += conn.N[e] * nodes.v[conn.node[e]];
    const Vec3 excess = points.mass[d] * (points.v[d] - v_nodes);
    double heat = kinetic(d);
    Vec3 kept = Vec3::Zero();  // the share of nodes that no intact point references
    for (Index e = conn.offset[d]; e < conn.offset[d + 1]; ++e) {
      const LocalIndex a = conn.node[e];
      const Vec3 share = conn.N[e] * excess;
      double weight = 0.0;
      for (Index k = conn.node_offset[a]; k < conn.node_offset[a + 1]; ++k) {
        const Index f = conn.node_slot[k].entry;
        const LocalIndex q = conn.node_slot[k].point;
        if (!points.debris(q)) weight += conn.N[f] * points.mass[q];
      }
      if (!(weight > 0.0)) {
        kept += share;
        continue;
      }
      for (Index k = conn.node_offset[a]; k < conn.node_offset[a + 1]; ++k) {
        const Index f = conn.node_slot[k].entry;
        const LocalIndex q = conn.node_slot[k].point;
        if (points.debris(q)) continue;
        heat += kinetic(q);
        points.v[q] += (conn.N[f] / weight) * share;
        heat -= kinetic(q);
      }
    }
    points.v[d] = v_nodes + kept / points.mass[d];
    heat -= kinetic(d);
    points.energy[d] += heat / points.mass[d];
    dissipated += heat;
  }
  return dissipated;
}

}  // namespace kessler::otm
