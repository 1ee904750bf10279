#pragma once
// The energy and momentum budget of a run, as every method reports it (history.csv,
// summary.json, the health checks).
#include "core/types.hpp"
#include "particles/store.hpp"
#include "solver/common/own_sums.hpp"

namespace kessler {

struct Energies {
  double kinetic = 0.0;   // 1/2 sum m_p |v_p|^2
  double internal = 0.0;  // sum m_p e_p
  // Energy a method's stabilisation stores, kept apart from the material's internal energy, which it
  // must not heat (OTM: the work of the volume stabilisation's pressure, docs/theory.md §4; SPH: the
  // heat of its viscosity in a law without a thermal state, which takes none, less the work of its
  // artificial stress, docs/theory.md §10); 0 for a method without one.
  double stabilisation = 0.0;
  Vec3 momentum = Vec3::Zero();
  double total() const { return kinetic + internal + stabilisation; }
};

// The budget of the points, summed exactly (the same bits for any thread count and partition), with
// `stored` as the stabilisation energy; over a rank's own points and every rank with `share`.
Energies pointEnergies(const PointStore& points, double stored, const Share& share = {});

}  // namespace kessler
