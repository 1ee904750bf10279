#pragma once
// Building blocks shared by the verification problems.
#include "geometry/shape.hpp"
#include "material/neo_hookean.hpp"
#include "solver/otm/integrator.hpp"
#include "solver/otm/setup.hpp"

#include <array>
#include <memory>

namespace kessler::verify {

// An aluminium-like neo-Hookean solid: rho 2700 kg/m^3, E 70 GPa, nu 0.33.
std::shared_ptr<const NeoHookean> elasticAluminium();

// Adds a box body meshed with the structured Kuhn triangulation; returns the body index.
int addBoxBody(otm::Model& model, const std::string& name, const geometry::Box& box, const std::array<int, 3>& cells,
               const Vec3& velocity, const MaterialPtr& material);

// Number of node and point values (positions, velocities, F, stress, volume, shape functions)
// that differ bitwise between two models.
long countDifferences(const otm::Model& a, const otm::Model& b);

}  // namespace kessler::verify
