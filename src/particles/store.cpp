#include "particles/store.hpp"

#include "core/error.hpp"

#include <cmath>
#include <type_traits>

namespace kessler {

namespace {

template <typename T>
void permuteArray(std::vector<T>& values, const std::vector<LocalIndex>& order, std::vector<T>& scratch) {
  KESSLER_VERIFY(values.size() == order.size(), "permutation of {} entries for an array of {}", order.size(),
                 values.size());
  scratch.resize(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) scratch[i] = values[order[i]];
  values.swap(scratch);
}

template <typename... Arrays>
void permuteAll(const std::vector<LocalIndex>& order, std::size_t size, Arrays&... arrays) {
  KESSLER_VERIFY(order.size() == size, "permutation of {} entries for {} particles", order.size(), size);
  auto one = [&](auto& values) {
    std::remove_reference_t<decltype(values)> scratch;
    permuteArray(values, order, scratch);
  };
  (one(arrays), ...);
}

}  // namespace

void NodeStore::permute(const std::vector<LocalIndex>& order) {
  permuteAll(order, x.size(), id, body, x, v, mass, momentum, force, constrained, prescribed_v);
}

void PointStore::permute(const std::vector<LocalIndex>& order) {
  permuteAll(order, x.size(), id, body, x, v, mass, volume, volume0, spacing0, F, dF, stress, energy, sound_speed,
             plastic_strain, temperature, damage, strain_energy, ductile_work, viscous_pressure, viscosity_limiter,
             volume_defect, be, eroded, passes_through, carrier, lambda);
}

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
  ductile_work.resize(n, 0.0);
  viscous_pressure.resize(n, 0.0);
  viscosity_limiter.resize(n, 0.0);
  volume_defect.resize(n, 0.0);
  be.resize(n, Mat3::Identity());
  eroded.resize(n, 0);
  passes_through.resize(n, 0);
  carrier.resize(n, -1);
  lambda.resize(n, Vec3::Zero());
  owned = static_cast<LocalIndex>(n);
}

double PointStore::spacing(LocalIndex p) const {
  return spacing0[p] * std::cbrt(volume[p] / volume0[p]);
}

}  // namespace kessler
