#include "solver/common/energies.hpp"

#include "solver/common/own_sums.hpp"

namespace kessler {

Energies pointEnergies(const PointStore& points, double stored, const Share& share) {
  Energies e;
  using Terms = Eigen::Matrix<double, 5, 1>;
  const Terms sum = ownSums<5>(share, points.owned, [&](LocalIndex p) {
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
