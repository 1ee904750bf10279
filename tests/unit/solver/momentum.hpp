#pragma once
// Test helper: the linear momentum of one body's points.
#include "solver/otm/model.hpp"

namespace kessler::otm {

inline Vec3 bodyMomentum(const Model& model, int body) {
  Vec3 sum = Vec3::Zero();
  for (LocalIndex p = 0; p < model.points.owned; ++p)
    if (model.points.body[p] == body) sum += model.points.mass[p] * model.points.v[p];
  return sum;
}

}  // namespace kessler::otm
