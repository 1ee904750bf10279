// thread-determinism: the collision of the momentum problem run for 100 steps with one thread
// and with two must give bitwise identical fields. Assembly gathers over each node's points in
// a fixed order and reductions use fixed blocks, so the thread count cannot change a bit.
#include "solver/methods.hpp"
#include "verify/fixtures.hpp"
#include "verify/problems.hpp"

#include <omp.h>

namespace kessler::verify {

namespace {

std::unique_ptr<Method> runWithThreads(int threads) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  auto material = elasticAluminium();
  Problem problem;
  problem.bodies = {
      boxBody("cube", {Vec3(0, 0, 0), Vec3(4e-3, 4e-3, 4e-3)}, {4, 4, 4}, Vec3(400.0, 30.0, 0.0), material),
      boxBody("plate", {Vec3(4.2e-3, -3e-3, -3e-3), Vec3(6.2e-3, 7e-3, 7e-3)}, {2, 10, 10}, Vec3::Zero(), material)};
  problem.settings.solver.end_time = 1.0;
  problem.settings.solver.max_steps = 100;
  std::unique_ptr<Method> method = makeCheckMethod(problem);
  method->initialise();
  for (int s = 0; s < 100; ++s) method->step();
  omp_set_num_threads(saved);
  return method;
}

}  // namespace

Outcome threadDeterminism() {
  const std::unique_ptr<Method> one = runWithThreads(1);
  const std::unique_ptr<Method> two = runWithThreads(2);
  Outcome o;
  o.name = "thread-determinism";
  o.quantity = "values differing between 1 and 2 threads";
  o.measured = static_cast<double>(countDifferences(*one, *two));
  o.reference = 0.0;
  o.tolerance = 0.0;
  o.comparison = Comparison::absolute;
  o.note = fmt::format("{} points, {} nodes, 100 steps", one->state().points.owned, one->nodes().owned);
  return compare(o);
}

}  // namespace kessler::verify
