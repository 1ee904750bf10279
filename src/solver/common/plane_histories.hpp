#pragma once
// Prescribed velocities that follow a history (a verification problem's piston,
// solver/common/problem.hpp's PlaneConstraint::history), as every method applies them to its
// carriers (OTM: its nodes; a particle method: its particles): each plane's carriers are found by id
// when the model is built, located in the store's current order (after a sort, a restart or a
// distributed run's migration), and given the history's value at the middle of each step.
#include "core/types.hpp"
#include "solver/common/problem.hpp"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace kessler {

class PlaneHistories {
 public:
  // A plane with a history, and the ids of the carriers it prescribes.
  void add(const PlaneConstraint& plane, std::vector<Index> ids);
  bool empty() const { return histories_.empty(); }
  // The carriers in a store whose entries hold `ids`; with `partial` (a distributed run's rank), a
  // carrier the store does not hold is passed over, otherwise it is an internal error.
  void locate(std::span<const Index> ids, bool partial);
  // Each located carrier's prescribed component set to its plane's history at time t.
  void apply(double t, std::span<Vec3> prescribed) const;

 private:
  struct History {
    int axis = 0;
    std::function<double(double)> velocity;
    std::vector<Index> ids;
    std::vector<LocalIndex> carriers;  // where they are now (locate)
  };
  std::vector<History> histories_;
};

// Whether prescribed velocities do work that the energy check does not count: a history, or a
// non-zero prescribed velocity on any of the first `owned` carriers.
bool prescribedWork(const PlaneHistories& histories, std::span<const std::uint8_t> constrained,
                    std::span<const Vec3> prescribed, LocalIndex owned);

}  // namespace kessler
