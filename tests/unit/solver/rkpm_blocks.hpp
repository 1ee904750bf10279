#pragma once
// The RKPM unit tests' blocks (test_rkpm.cpp, test_rkpm_contact.cpp): a body's problem, its particles moved
// within their cells, and its kernels.
#include "../blocks.hpp"
#include "solver/common/particle_bodies.hpp"
#include "solver/rkpm/kernels.hpp"
#include "solver/rkpm/rkpm_method.hpp"
#include "solver/rkpm/setup.hpp"

#include <algorithm>
#include <cstdint>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace kessler::rkpm::testing_blocks {

inline constexpr double h = 1e-3;

// The particles of `problem`'s single body, each moved up to a quarter spacing within its cell.
inline Model jittered(const Problem& problem, unsigned seed = 3) {
  Model model = buildModel(problem);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.25 * h, 0.25 * h);
  for (Vec3& x : model.reference) {
    const Vec3 moved = x + Vec3(jitter(random), jitter(random), jitter(random));
    // A particle on a symmetry plane's side stays on it.
    for (const int a : problem.symmetry_axes) x[a] = std::abs(moved[a]);
    for (int a = 0; a < 3; ++a)
      if (std::find(problem.symmetry_axes.begin(), problem.symmetry_axes.end(), a) == problem.symmetry_axes.end())
        x[a] = moved[a];
  }
  model.points.x = model.reference;
  return model;
}

inline Problem block(BodySetup body, std::vector<int> symmetry_axes = {}) {
  Problem problem;
  problem.method = "rkpm";
  problem.settings.solver.end_time = 1e-3;
  body.name = "block";
  body.material = testing::aluminium();
  problem.bodies = {body};
  problem.symmetry_axes = std::move(symmetry_axes);
  return problem;
}

inline Problem latticeBlock(std::vector<int> symmetry_axes = {}) {
  BodySetup body;
  body.mesh = geometry::MeshRequest{geometry::Box{Vec3(0, 0, 0), Vec3(5e-3, 4e-3, 3e-3)}, h};
  return block(body, std::move(symmetry_axes));
}

inline Kernels kernelsOf(const Model& model, const Problem& problem, std::span<const std::uint8_t> crack = {}) {
  std::vector<double> support;
  for (const double s : model.points.spacing0) support.push_back(problem.settings.rkpm.support * s);
  const std::vector<std::string> names{"block"};
  return buildKernels({model.reference,
                       model.points.body,
                       support,
                       model.points.volume0,
                       model.cell_volume,
                       model.faces,
                       names,
                       mirrorBox(problem),
                       {},
                       crack});
}

}  // namespace kessler::rkpm::testing_blocks
