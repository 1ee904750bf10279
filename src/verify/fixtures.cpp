#include "verify/fixtures.hpp"

#include "geometry/structured_mesh.hpp"

#include <cstring>

namespace kessler::verify {

std::shared_ptr<const NeoHookean> elasticAluminium() {
  return std::make_shared<NeoHookean>("aluminium (elastic)",
                                      NeoHookeanParameters{.density = 2700.0, .youngs_modulus = 70e9, .poisson_ratio = 0.33});
}

int addBoxBody(otm::Model& model, const std::string& name, const geometry::Box& box, const std::array<int, 3>& cells,
               const Vec3& velocity, const MaterialPtr& material) {
  const geometry::Discretisation disc = geometry::discretise(geometry::structuredBoxMesh(box, cells));
  return otm::addBody(model, name, material, disc, velocity);
}

namespace {

template <typename T>
long differing(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return static_cast<long>(std::max(a.size(), b.size()));
  long count = 0;
  for (std::size_t i = 0; i < a.size(); ++i) count += std::memcmp(&a[i], &b[i], sizeof(T)) != 0;
  return count;
}

}  // namespace

long countDifferences(const otm::Model& a, const otm::Model& b) {
  return differing(a.nodes.x, b.nodes.x) + differing(a.nodes.v, b.nodes.v) + differing(a.points.x, b.points.x) +
         differing(a.points.v, b.points.v) + differing(a.points.F, b.points.F) +
         differing(a.points.stress, b.points.stress) + differing(a.points.volume, b.points.volume) +
         differing(a.connectivity.N, b.connectivity.N);
}

}  // namespace kessler::verify
