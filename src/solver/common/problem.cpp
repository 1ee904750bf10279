#include "solver/common/problem.hpp"

#include "core/error.hpp"

#include <cmath>

namespace kessler {

MirrorBox mirrorBox(const Problem& problem) {
  MirrorBox box;
  const auto add = [&](int axis, double offset, int side) {
    KESSLER_VERIFY(axis >= 0 && axis < 3 && (side == 1 || side == -1),
                   "a mirror plane needs an axis 0-2 and a side +-1, got {} and {}", axis, side);
    double& end = side > 0 ? box.lo[axis] : box.hi[axis];
    KESSLER_VERIFY(std::isinf(end), "two mirror planes on the {} side of axis {} (at {} and {} m)",
                   side > 0 ? "lower" : "upper", "xyz"[axis], end, offset);
    end = offset;
  };
  for (const int axis : problem.symmetry_axes) add(axis, 0.0, 1);
  for (const Roller& r : problem.rollers) add(r.axis, r.offset, r.side);
  return box;
}

}  // namespace kessler
