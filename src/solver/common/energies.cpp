#include "solver/common/energies.hpp"

#include "core/exact_sum.hpp"

namespace kessler {

Energies pointEnergies(const PointStore& points, double stored) {
  Energies e;
  using Terms = Eigen::Matrix<double, 5, 1>;
  const Terms sum = exactSums<5>(points.owned, [&](LocalIndex p) {
    const Vec3 momentum = points.mass[p] * points.v[p];
    Terms t;
    t << 0.5 * momentum.dot(points.v[p]), points.mass[p] * points.energy[p], momentum;
    return t;
  });
  e.kinetic = sum[0];
  e.internal = sum[1];
  e.stabilisation = stored;
  e.momentum = sum.tail<3>();
  return e;
}

}  // namespace kessler
