#pragma once
// Synthetic models for the analysis tests: structured blocks and hand-placed points, with an
// elastic aluminium (the analysis reads masses, positions and flags only).
#include "../blocks.hpp"
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

using kessler::testing::addBlock;
using kessler::testing::aluminium;

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
  forEachPointOf(model.points, body, [&](LocalIndex p) {
    if (pred(model.points.x[p])) {
      model.points.broken[p] = 1;
      ++count;
    }
  });
  return count;
}

}  // namespace kessler::analysis::testing
