#pragma once
// Test helper for SPH's unit tests: a problem of one body, run by SPH.
#include "solver/common/problem.hpp"

#include <functional>
#include <string>
#include <utility>

namespace kessler::testing {

// One body `name` of `material`, discretised from `mesh` and moving at `velocity`, to `end_time`
// (s), with SPH's default settings.
inline Problem oneBody(std::string name, MaterialPtr material, decltype(BodySetup::mesh) mesh, double end_time,
                       std::function<Vec3(const Vec3&)> velocity = {}) {
  Problem problem;
  problem.method = "sph";
  problem.settings.solver.end_time = end_time;
  BodySetup body;
  body.name = std::move(name);
  body.material = std::move(material);
  body.mesh = std::move(mesh);
  body.velocity_field = std::move(velocity);
  problem.bodies = {std::move(body)};
  return problem;
}

}  // namespace kessler::testing
