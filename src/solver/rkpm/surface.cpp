#include "solver/rkpm/surface.hpp"

#include <map>
#include <optional>

namespace kessler::rkpm {

std::vector<std::array<LocalIndex, 3>> latticeSurface(const std::vector<std::array<int, 3>>& element,
                                                      LocalIndex first) {
  using Cell = std::array<int, 3>;
  std::map<Cell, LocalIndex> at;
  for (std::size_t i = 0; i < element.size(); ++i) at[element[i]] = first + static_cast<LocalIndex>(i);
  const auto shifted = [](Cell e, int axis, int by) {
    e[static_cast<std::size_t>(axis)] += by;
    return e;
  };
  std::vector<std::array<LocalIndex, 3>> triangles;
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (const int side : {1, -1}) {
      const auto exposed = [&](const Cell& e) { return at.count(e) && !at.count(shifted(e, a, side)); };
      // The sheet's particle in the column beside: level, one step out, or one step in.
      const auto beside = [&](const Cell& e) -> std::optional<LocalIndex> {
        for (const int step : {0, side, -side})
          if (const Cell f = shifted(e, a, step); exposed(f)) return at.at(f);
        return std::nullopt;
      };
      for (const auto& [e, p] : at) {
        if (!exposed(e)) continue;
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
      }
    }
  }
  return triangles;
}

}  // namespace kessler::rkpm
