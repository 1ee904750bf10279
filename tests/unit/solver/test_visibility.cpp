// Visibility across cracks (solver/otm/neighbourhoods.hpp): once a band of points across a body
// has eroded, no intact point on one side keeps a node on the far side of the band, and the
// shape functions stay a partition of unity; without the band such connections exist (so the
// test can fail).
#include "../blocks.hpp"
#include "solver/otm/neighbourhoods.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace kessler::otm {
namespace {

constexpr double h = 1e-3;

Model plate() {
  Model model;
  testing::addBlock(model, "plate", geometry::Box{Vec3(0, -4 * h, 0), Vec3(8 * h, 4 * h, 2 * h)}, {8, 8, 2});
  return model;
}

// Connections (with weight: hidden nodes stay in a row with N = 0 and grad N = 0) from intact
// points beyond the band y in (0, h) to nodes on the far side of it.
long connectionsAcross(const Model& model) {
  const PointStore& points = model.points;
  const Connectivity& conn = model.connectivity;
  long across = 0;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (points.broken[p]) continue;
    for (Index k = conn.offset[p]; k < conn.offset[p + 1]; ++k) {
      if (conn.N[k] == 0.0 && conn.dN[k].isZero(0.0)) continue;
      const double y = model.nodes.x[conn.node[k]][1];
      across += (points.x[p][1] > h && y < 0.5 * h) || (points.x[p][1] < 0.0 && y > 0.5 * h);
    }
  }
  return across;
}

TEST(Visibility, AnErodedBandCutsTheNeighbourhoods) {
  Settings settings;
  settings.crack_visibility = true;
  Model intact = plate();
  Neighbourhoods(settings).update(intact);
  EXPECT_GT(connectionsAcross(intact), 500);

  Model cracked = plate();
  for (LocalIndex p = 0; p < cracked.points.owned; ++p)
    if (cracked.points.x[p][1] > 0.0 && cracked.points.x[p][1] < h) cracked.points.broken[p] = 1;
  Neighbourhoods(settings).update(cracked);
  EXPECT_EQ(connectionsAcross(cracked), 0);
  Model off = cracked;
  Neighbourhoods(Settings{}).update(off);  // crack_visibility is off by default
  EXPECT_GT(connectionsAcross(off), 100);
  const Connectivity& conn = cracked.connectivity;
  for (LocalIndex p = 0; p < cracked.points.owned; ++p) {
    if (cracked.points.broken[p]) continue;
    double sum = 0.0;
    for (Index k = conn.offset[p]; k < conn.offset[p + 1]; ++k) sum += conn.N[k];
    EXPECT_NEAR(sum, 1.0, 1e-9) << "point " << p;
  }
}

}  // namespace
}  // namespace kessler::otm
