#include "solver/common/energies.hpp"

#include "core/reduce.hpp"

namespace kessler {

Energies pointEnergies(const PointStore& points, double stored) {
  Energies e;
  e.kinetic = deterministicSum(points.owned, 0.0,
                               [&](LocalIndex p) { return 0.5 * points.mass[p] * points.v[p].squaredNorm(); });
  e.internal = deterministicSum(points.owned, 0.0, [&](LocalIndex p) { return points.mass[p] * points.energy[p]; });
  e.stabilisation = stored;
  e.momentum = deterministicSum(points.owned, Vec3(Vec3::Zero()),
                                [&](LocalIndex p) -> Vec3 { return points.mass[p] * points.v[p]; });
  return e;
}

}  // namespace kessler
