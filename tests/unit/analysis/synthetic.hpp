#pragma once
// Synthetic models for the analysis tests: structured blocks and hand-placed points, with an
// elastic aluminium (the analysis reads masses, positions and flags only).
#include "geometry/mesh.hpp"
#include "geometry/structured_mesh.hpp"
#include "material/neo_hookean.hpp"
#include "solver/otm/setup.hpp"

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace kessler::analysis::testing {

// An aluminium-like elastic material (the analysis reads only the reference density and the
// name; an existing law keeps the tests independent of the Material interface's evolution).
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

// A body of hand-placed points, each of volume `volume`, without links.
inline int addCloud(otm::Model& model, const std::string& name, const std::vector<Vec3>& positions, double volume,
                    const MaterialPtr& material = aluminium(), const Vec3& velocity = Vec3::Zero()) {
  geometry::Discretisation d;
  d.points = positions;
  d.volumes.assign(positions.size(), volume);
  d.spacings.assign(positions.size(), std::cbrt(volume));
  const int body = otm::addBody(model, name, material, d, velocity);
  model.points.owned = model.points.size();
  return body;
}

// Erodes the points of `body` for which pred(x) holds; returns how many.
template <class Pred>
int erodeWhere(otm::Model& model, int body, const Pred& pred) {
  int count = 0;
  const BodyInfo& info = model.bodies[body];
  for (LocalIndex p = info.point_begin; p < info.point_end; ++p) {
    if (pred(model.points.x[p])) {
      model.points.eroded[p] = 1;
      ++count;
    }
  }
  return count;
}

}  // namespace kessler::analysis::testing
