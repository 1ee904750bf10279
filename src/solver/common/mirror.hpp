#pragma once
// Images across a problem's symmetry planes (planes through the origin normal to coordinate axes):
// a particle method that leaves out the mirrored copy of its model sees it through these.
#include "core/types.hpp"

#include <cstdint>

namespace kessler {

// x reflected across the symmetry planes normal to the axes whose bits `mirror` sets.
inline Vec3 reflect(Vec3 x, std::uint8_t mirror) {
  for (int a = 0; a < 3; ++a)
    if (mirror & (1u << a)) x[a] = -x[a];
  return x;
}
// A tensor of the image (R T R with R the reflection).
inline Mat3 reflect(Mat3 t, std::uint8_t mirror) {
  for (int a = 0; a < 3; ++a)
    if (mirror & (1u << a)) {
      t.row(a) *= -1.0;
      t.col(a) *= -1.0;
    }
  return t;
}

}  // namespace kessler
