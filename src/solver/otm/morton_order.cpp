#include "solver/otm/morton_order.hpp"

#include "search/cell_list.hpp"

#include <numeric>

namespace kessler::otm {

void sortForLocality(Model& model) {
  PointStore& points = model.points;
  NodeStore& nodes = model.nodes;
  if (points.size() == 0 || nodes.size() == 0) return;
  const CellList::Bounds box = CellList::boundsOf(nodes.x, nodes.size());
  const Vec3 &lo = box.lo, &hi = box.hi;
  points.permute(mortonOrder(points.x, points.body, model.bodies.size(), lo, hi));
  model.lme_lambda.assign(points.x.size(), Vec3::Zero());  // before the first solve: no warm start yet
  nodes.permute(mortonOrder(nodes.x, nodes.body, model.bodies.size(), lo, hi));
  model.connectivity = Connectivity{};
}

void numberInOrder(Model& model) {
  numberPointsInOrder(model);
  std::iota(model.nodes.id.begin(), model.nodes.id.end(), Index{0});
}

}  // namespace kessler::otm
