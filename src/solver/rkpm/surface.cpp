#include "solver/rkpm/surface.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>

namespace kessler::rkpm {

namespace {

using Cell = std::array<int, 3>;

// The present particles on a dense grid of their elements' bounding box (one cell of margin all
// round, so that a neighbour of any element is inside): the particle of each element, or -1.
class Grid {
 public:
  Grid(std::span<const Cell> element, std::span<const LocalIndex> present) {
    for (int a = 0; a < 3; ++a) {
      lo_[a] = std::numeric_limits<int>::max();
      int hi = std::numeric_limits<int>::min();
      for (const LocalIndex p : present) {
        lo_[a] = std::min(lo_[a], element[static_cast<std::size_t>(p)][a]);
        hi = std::max(hi, element[static_cast<std::size_t>(p)][a]);
      }
      lo_[a] -= 1;
      size_[a] = present.empty() ? 0 : hi - lo_[a] + 2;
    }
    at_.assign(static_cast<std::size_t>(size_[0]) * size_[1] * size_[2], -1);
    for (const LocalIndex p : present) at_[slot(element[static_cast<std::size_t>(p)])] = p;
  }
  // The particle of element e, or -1 (also off the grid).
  LocalIndex operator()(const Cell& e) const {
    for (int a = 0; a < 3; ++a)
      if (e[a] - lo_[a] < 0 || e[a] - lo_[a] >= size_[a]) return -1;
    return at_[slot(e)];
  }
  // f(e, p) for every present element in the order of (i, j, k).
  template <class F>
  void forEach(F&& f) const {
    Cell e;
    for (e[0] = lo_[0]; e[0] < lo_[0] + size_[0]; ++e[0])
      for (e[1] = lo_[1]; e[1] < lo_[1] + size_[1]; ++e[1])
        for (e[2] = lo_[2]; e[2] < lo_[2] + size_[2]; ++e[2])
          if (const LocalIndex p = at_[slot(e)]; p >= 0) f(e, p);
  }

 private:
  std::size_t slot(const Cell& e) const {
    return (static_cast<std::size_t>(e[0] - lo_[0]) * static_cast<std::size_t>(size_[1]) +
            static_cast<std::size_t>(e[1] - lo_[1])) *
               static_cast<std::size_t>(size_[2]) +
           static_cast<std::size_t>(e[2] - lo_[2]);
  }
  Cell lo_{}, size_{};
  std::vector<LocalIndex> at_;
};

}  // namespace

std::vector<std::array<LocalIndex, 3>> latticeSurface(std::span<const std::array<int, 3>> element,
                                                      std::span<const LocalIndex> present) {
  const Grid grid(element, present);
  const auto shifted = [](Cell e, int axis, int by) {
    e[static_cast<std::size_t>(axis)] += by;
    return e;
  };
  std::vector<std::array<LocalIndex, 3>> triangles;
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (const int side : {1, -1}) {
      const auto exposed = [&](const Cell& e) { return grid(e) >= 0 && grid(shifted(e, a, side)) < 0; };
      // The sheet's particle in the column beside: level, one step out, or one step in.
      const auto beside = [&](const Cell& e) -> std::optional<LocalIndex> {
        for (const int step : {0, side, -side})
          if (const Cell f = shifted(e, a, step); exposed(f)) return grid(f);
        return std::nullopt;
      };
      grid.forEach([&](const Cell& e, LocalIndex p) {
        if (!exposed(e)) return;
        const auto p1 = beside(shifted(e, b, 1)), p2 = beside(shifted(e, c, 1)),
                   p3 = beside(shifted(shifted(e, b, 1), c, 1));
        // e_b x e_c = e_a: (p, p1, p3, p2) runs counter-clockwise seen from +a.
        const auto add = [&](LocalIndex u, LocalIndex v, LocalIndex w) {
          triangles.push_back(side > 0 ? std::array<LocalIndex, 3>{u, v, w} : std::array<LocalIndex, 3>{u, w, v});
        };
        if (p1 && p2 && p3) {
          add(p, *p1, *p3);
          add(p, *p3, *p2);
        } else if (p1 && p2) {
          add(p, *p1, *p2);
        } else if (p1 && p3) {
          add(p, *p1, *p3);
        } else if (p2 && p3) {
          add(p, *p3, *p2);
        }
      });
    }
  }
  return triangles;
}

}  // namespace kessler::rkpm
