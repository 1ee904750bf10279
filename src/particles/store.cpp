#include "particles/store.hpp"

#include <cmath>

namespace kessler {

void NodeStore::resize(std::size_t n) {
  id.resize(n);
  body.resize(n);
  x.resize(n, Vec3::Zero());
  v.resize(n, Vec3::Zero());
  mass.resize(n, 0.0);
  momentum.resize(n, Vec3::Zero());
  force.resize(n, Vec3::Zero());
  constrained.resize(n, 0);
  prescribed_v.resize(n, Vec3::Zero());
  owned = static_cast<LocalIndex>(n);
}

void PointStore::resize(std::size_t n) {
  id.resize(n);
  body.resize(n);
  x.resize(n, Vec3::Zero());
  v.resize(n, Vec3::Zero());
  mass.resize(n, 0.0);
  volume.resize(n, 0.0);
  volume0.resize(n, 0.0);
  spacing0.resize(n, 0.0);
  F.resize(n, Mat3::Identity());
  dF.resize(n, Mat3::Identity());
  stress.resize(n, Mat3::Zero());
  energy.resize(n, 0.0);
  sound_speed.resize(n, 0.0);
  plastic_strain.resize(n, 0.0);
  temperature.resize(n, 0.0);
  damage.resize(n, 0.0);
  strain_energy.resize(n, 0.0);
  plastic_work.resize(n, 0.0);
  viscous_pressure.resize(n, 0.0);
  be.resize(n, Mat3::Identity());
  eroded.resize(n, 0);
  lambda.resize(n, Vec3::Zero());
  owned = static_cast<LocalIndex>(n);
}

double PointStore::spacing(LocalIndex p) const {
  return spacing0[p] * std::cbrt(volume[p] / volume0[p]);
}

}  // namespace kessler
