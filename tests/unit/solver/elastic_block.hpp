#pragma once
// Test helper: a body of elastic aluminium (neo-Hookean, rho = 2700 kg/m^3, E = 70 GPa, nu = 0.33)
// on a structured box mesh of `cells` cubes.
#include "geometry/structured_mesh.hpp"
#include "material/neo_hookean.hpp"
#include "solver/otm/setup.hpp"

#include <array>
#include <memory>
#include <string>

namespace kessler::otm {

inline void addElasticBlock(Model& model, const std::string& name, const geometry::Box& box,
                            const std::array<int, 3>& cells, const Vec3& velocity = Vec3::Zero()) {
  NeoHookeanParameters p;
  p.density = 2700.0;
  p.youngs_modulus = 70e9;
  p.poisson_ratio = 0.33;
  addBody(model, name, std::make_shared<NeoHookean>("al", p),
          geometry::discretise(geometry::structuredBoxMesh(box, cells)), velocity);
}

}  // namespace kessler::otm
