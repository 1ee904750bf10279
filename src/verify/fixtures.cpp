#include "verify/fixtures.hpp"

#include "geometry/structured_mesh.hpp"
#include "solver/methods.hpp"

#include <cstring>
#include <limits>

namespace kessler::verify {

NeoHookeanParameters elasticAluminiumParameters() {
  return {.density = 2700.0, .youngs_modulus = 70e9, .poisson_ratio = 0.33};
}

std::shared_ptr<const NeoHookean> elasticAluminium() {
  return std::make_shared<NeoHookean>("aluminium (elastic)", elasticAluminiumParameters());
}

BodySetup boxBody(const std::string& name, const geometry::Box& box, const std::array<int, 3>& cells,
                  const Vec3& velocity, const MaterialPtr& material) {
  BodySetup body;
  body.name = name;
  body.material = material;
  body.mesh = geometry::StructuredBox{box, cells};
  body.velocity = velocity;
  return body;
}

PlaneConstraint lockAxis(int axis) {
  PlaneConstraint every;
  every.axis = axis;
  every.tolerance = std::numeric_limits<double>::infinity();
  return every;
}

namespace {

std::string& chosenMethod() {
  static std::string name = "otm";
  return name;
}

}  // namespace

void useMethod(const std::string& name) {
  chosenMethod() = name;
}

const std::string& checkedMethod() {
  return chosenMethod();
}

std::unique_ptr<Method> makeCheckMethod(Problem problem) {
  problem.method = checkedMethod();
  return makeMethod(problem);
}

std::unique_ptr<Method> runToEnd(const Problem& problem, const std::function<bool(const Method&)>& after_step) {
  std::unique_ptr<Method> method = makeCheckMethod(problem);
  method->initialise();
  while (!method->finished()) {
    method->step();
    if (after_step && !after_step(*method)) break;
  }
  return method;
}

namespace {

template <typename T>
long differing(std::span<const T> a, std::span<const T> b) {
  if (a.size() != b.size()) return static_cast<long>(std::max(a.size(), b.size()));
  long count = 0;
  for (std::size_t i = 0; i < a.size(); ++i) count += std::memcmp(&a[i], &b[i], sizeof(T)) != 0;
  return count;
}

}  // namespace

long countDifferences(const Method& a, const Method& b) {
  const PointStore &p = a.state().points, &q = b.state().points;
  const NodeCloud m = a.nodes(), n = b.nodes();
  auto all = [](const auto& values) { return std::span(values); };
  return differing(m.x, n.x) + differing(m.v, n.v) + differing(all(p.x), all(q.x)) + differing(all(p.v), all(q.v)) +
         differing(all(p.F), all(q.F)) + differing(all(p.stress), all(q.stress)) +
         differing(all(p.volume), all(q.volume));
}

}  // namespace kessler::verify
