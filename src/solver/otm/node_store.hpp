#pragma once
// OTM's nodes (docs/theory.md §1-4): the carriers of the motion, whose positions the shape
// functions interpolate and on which mass, momentum and forces are assembled.
#include "core/types.hpp"
#include "solver/common/node_cloud.hpp"

#include <cstdint>
#include <vector>

namespace kessler::otm {

struct NodeStore {
  std::vector<Index> id;                  // global id
  std::vector<std::int32_t> body;         // body the node was created with
  std::vector<Vec3> x;                    // position
  std::vector<Vec3> v;                    // velocity over the last step, (x_k+1 - x_k)/dt
  std::vector<double> mass;               // lumped mass, sum_p N_a(x_p) m_p
  std::vector<Vec3> momentum;             // l_a = sum_p N_a(x_p) m_p v_p
  std::vector<Vec3> force;                // internal force
  std::vector<std::uint8_t> constrained;  // bit i set: velocity component i is prescribed
  std::vector<Vec3> prescribed_v;         // prescribed velocity components
  LocalIndex owned = 0;

  // Every array, once: visit(name, array, value of a new entry). Store is NodeStore, const or not.
  template <class Store, class Visit>
  static void fields(Store& s, Visit&& visit) {
    const Vec3 zero = Vec3::Zero();
    visit("id", s.id, Index{0});
    visit("body", s.body, std::int32_t{0});
    visit("x", s.x, zero);
    visit("v", s.v, zero);
    visit("mass", s.mass, 0.0);
    visit("momentum", s.momentum, zero);
    visit("force", s.force, zero);
    visit("constrained", s.constrained, std::uint8_t{0});
    visit("prescribed_v", s.prescribed_v, zero);
  }
  static constexpr int field_count = 9;

  LocalIndex size() const { return static_cast<LocalIndex>(x.size()); }
  // What output and analysis see of them (Method::nodes).
  NodeCloud cloud() const { return {id, body, x, v, mass, owned}; }
  void resize(std::size_t n);
  // Reorders every array: new index i holds what old index order[i] held (order: a permutation).
  void permute(const std::vector<LocalIndex>& order);
};

}  // namespace kessler::otm
