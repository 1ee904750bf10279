#pragma once
// Test helper shared by the layers' unit tests: structured blocks of an elastic aluminium
// (neo-Hookean; the tests that use it read geometry, masses and flags, not the stiffness).
#include "geometry/structured_mesh.hpp"
#include "material/neo_hookean.hpp"
#include "solver/otm/setup.hpp"

#include <array>
#include <memory>
#include <string>

namespace kessler::testing {

// An aluminium-like elastic material (an existing law keeps the tests independent of the Material
// interface's evolution).
inline MaterialPtr aluminium() {
  static const MaterialPtr material = [] {
    NeoHookeanParameters p;
    p.density = 2700.0;
    p.youngs_modulus = 68.9e9;
    p.poisson_ratio = 0.33;
    return std::make_shared<NeoHookean>("al", p);
  }();
  return material;
}

// A box body meshed by the structured Kuhn triangulation (six tets per cube).
inline int addBlock(otm::Model& model, const std::string& name, const geometry::Box& box,
                    const std::array<int, 3>& cells, const MaterialPtr& material = aluminium(),
                    const Vec3& velocity = Vec3::Zero()) {
  const geometry::Discretisation d = geometry::discretise(geometry::structuredBoxMesh(box, cells));
  const int body = otm::addBody(model, name, material, d, velocity);
  model.points.owned = model.points.size();
  model.nodes.owned = model.nodes.size();
  return body;
}

}  // namespace kessler::testing
