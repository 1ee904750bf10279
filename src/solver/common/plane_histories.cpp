#include "solver/common/plane_histories.hpp"

#include "core/error.hpp"
#include "particles/store.hpp"

namespace kessler {

void PlaneHistories::add(const PlaneConstraint& plane, std::vector<Index> ids) {
  histories_.push_back({plane.axis, plane.history, std::move(ids), {}});
}

void PlaneHistories::locate(std::span<const Index> ids, bool partial) {
  if (histories_.empty()) return;
  const IdIndex index(ids);
  for (History& h : histories_) {
    h.carriers.clear();
    for (const Index id : h.ids) {
      const LocalIndex a = index.find(id);
      KESSLER_VERIFY(a >= 0 || partial, "prescribed velocity history: carrier {} is not in the store", id);
      if (a >= 0) h.carriers.push_back(a);
    }
  }
}

void PlaneHistories::apply(double t, std::span<Vec3> prescribed) const {
  for (const History& h : histories_) {
    const double v = h.velocity(t);
    for (const LocalIndex a : h.carriers) prescribed[static_cast<std::size_t>(a)][h.axis] = v;
  }
}

bool prescribedWork(const PlaneHistories& histories, std::span<const std::uint8_t> constrained,
                    std::span<const Vec3> prescribed, LocalIndex owned) {
  bool here = !histories.empty();
  for (LocalIndex p = 0; p < owned && !here; ++p)
    here = constrained[static_cast<std::size_t>(p)] != 0 && prescribed[static_cast<std::size_t>(p)].squaredNorm() > 0.0;
  return here;
}

}  // namespace kessler
