// SPH's finite-element reconstruction (solver/sph/reconstruction.hpp, docs/theory.md §10): nodes exact
// under affine motion, not the bodies' surface, sheared elements failing with their material intact;
// and the elements' share of the deviator (solver/sph/element_gradient.hpp): exact for a linear
// field, its forces the gradient's adjoint.
#include "../blocks.hpp"
#include "material/library.hpp"
#include "solver/methods.hpp"
#include "solver/sph/element_gradient.hpp"
#include "solver/sph/reconstruction.hpp"
#include "solver/sph/setup.hpp"
#include "sph_problem.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace kessler::sph {
namespace {

// An n x n x n lattice block (1 mm elements) from the origin, as SPH's setup builds it.
Model latticeBlock(int n = 3) {
  return buildModel(testing::oneBody(
      "block", testing::aluminium(),
      geometry::StructuredBox{geometry::Box{Vec3::Zero(), Vec3::Constant(n * 1e-3)}, {n, n, n}}, 1e-6));
}

// Under any affine motion x = A X + c the reconstructed nodes are the affine images of the lattice's
// corners, interior (the mean of 8 particles) and surface (extrapolated by F) alike.
TEST(SphReconstruction, AffineMotionIsReconstructedExactly) {
  Model model = latticeBlock();
  Mat3 A;
  A << 1.1, 0.2, 0.0, -0.1, 0.9, 0.05, 0.0, 0.1, 1.2;
  const Vec3 c(1e-3, -2e-3, 0.5e-3);
  const std::vector<Vec3> reference = model.points.x;
  for (LocalIndex p = 0; p < model.points.size(); ++p) {
    model.points.x[p] = A * reference[p] + c;
    model.points.F[p] = A;
  }
  Reconstruction r(model);
  const NodeCloud before = r.cloud();
  ASSERT_EQ(before.owned, 64);  // 4 x 4 x 4 corners
  const std::vector<Vec3> corners(before.x.begin(), before.x.end());
  r.rebuild(model);
  const NodeCloud after = r.cloud();
  for (LocalIndex a = 0; a < after.owned; ++a)
    EXPECT_LT((after.x[a] - (A * corners[a] + c)).norm(), 1e-15) << "node " << a;
  EXPECT_EQ(r.failDistorted(model, 0.2), 0);
  // The quality of a sheared cube is the sine of its corner angle: for this A, at least 0.2.
  for (LocalIndex p = 0; p < model.points.size(); ++p) EXPECT_GT(r.quality(p), 0.8);
}

// The reconstructed nodes are drawn and linked, but they are not the surface SPH's walls and contact
// act on: the verifications that measure a body's surface (the Taylor bar's footprint, the contact
// gap) read the particles' cells instead (solver/common/node_cloud.hpp).
TEST(SphReconstruction, ItsNodesAreNotTheBodiesSurface) {
  const Model model = latticeBlock();
  const Reconstruction r(model);
  const NodeCloud nodes = r.cloud();
  EXPECT_EQ(nodes.owned, 64);
  EXPECT_FALSE(surfaceOnNodes(nodes));
}

// A block sheared by gamma = 6 (corner angle atan(1/6), 9.5 degrees, below 11.5): every element fails,
// its particle loose (in no fragment) with its material intact and its stress kept; a second pass
// finds nothing more to fail.
TEST(SphReconstruction, ShearedElementsFailTheirMaterialDoesNot) {
  Model model = latticeBlock();
  Mat3 A = Mat3::Identity();
  A(0, 2) = 6.0;
  for (LocalIndex p = 0; p < model.points.size(); ++p) {
    model.points.x[p] = A * model.points.x[p];
    model.points.F[p] = A;
    model.points.stress[p] = 1e8 * Mat3::Identity();
  }
  Reconstruction r(model);
  r.rebuild(model);
  EXPECT_EQ(r.failDistorted(model, 0.2), 27);
  for (LocalIndex p = 0; p < model.points.size(); ++p) {
    EXPECT_TRUE(model.points.loose[p]);
    EXPECT_FALSE(model.points.broken[p]);
    EXPECT_EQ(model.points.stress[p], (1e8 * Mat3::Identity()).eval());
  }
  r.rebuild(model);
  EXPECT_EQ(r.failDistorted(model, 0.2), 0);
}

// A 4 x 4 x 4 lattice block moved by x = A X + c.
Model movedBlock(const Mat3& A, const Vec3& c) {
  Model model = latticeBlock(4);
  for (LocalIndex p = 0; p < model.points.size(); ++p) {
    model.points.x[p] = A * model.points.x[p] + c;
    model.points.F[p] = A;
  }
  return model;
}

// The particle of element (1, 1, 1), inside the block.
LocalIndex insideParticle(const Model& model) {
  for (LocalIndex p = 0; p < model.points.size(); ++p)
    if (model.element[p] == std::array<int, 3>{1, 1, 1}) return p;
  return -1;
}

// The elements' gradient is exact for a linear velocity field on an affinely moved lattice: with
// SPH's gradient exact too, the blend is the field's gradient, at interior, surface and corner
// particles, and beside a loose particle (whose neighbours' nodes are fitted). With a mirror plane at
// x = 0 and a field symmetric across it, the plane's nodes are the means of their particles and
// images.
TEST(SphElementGradient, LinearVelocityGivesItsGradient) {
  Mat3 A;
  A << 1.1, 0.2, 0.0, -0.1, 0.9, 0.05, 0.0, 0.1, 1.2;
  Mat3 G;
  G << 100.0, -30.0, 20.0, 50.0, -80.0, 10.0, -40.0, 60.0, 30.0;
  Mat3 S = G;  // symmetric across x = 0: v_x odd in x, v_y and v_z even
  S(0, 1) = S(0, 2) = S(1, 0) = S(2, 0) = 0.0;
  MirrorBox plane;
  plane.lo[0] = 0.0;
  const Mat3 A_plane = Vec3(1.1, 0.9, 1.2).asDiagonal();
  for (const bool mirrored : {false, true}) {
    const Mat3& move = mirrored ? A_plane : A;
    const Mat3& field = mirrored ? S : G;
    Model model = movedBlock(move, mirrored ? Vec3(0.0, 1e-3, 2e-3) : Vec3(1e-3, -2e-3, 0.5e-3));
    model.points.loose[insideParticle(model)] = 1;
    const Mirrors mirrors = mirrored ? Mirrors(plane, 3e-3) : Mirrors();
    std::vector<Vec3> v(model.points.x.size());
    for (LocalIndex p = 0; p < model.points.size(); ++p)
      v[p] = field * model.points.x[p] + Vec3(mirrored ? 0.0 : 1.0, 2.0, 3.0);
    const Reconstruction reconstruction(model);
    ElementGradient elements(0.5, 0.2);
    const std::vector<std::uint32_t> touches(model.points.x.size(), 0);
    elements.update(model, reconstruction, mirrors, touches, 0);
    elements.moveNodes(v, mirrors);
    int taking = 0;
    for (LocalIndex p = 0; p < model.points.size(); ++p) {
      if (!elements.takesPart(p)) continue;
      ++taking;
      EXPECT_LT((elements.blend(p, field) - field).norm(), 1e-12 * field.norm()) << "particle " << p;
    }
    EXPECT_EQ(taking, 63) << (mirrored ? "with" : "without") << " the plane";  // all but the loose one
  }
}

// The elements' forces are the adjoint of their gradient: for any velocities, their power is minus the
// elements' share of the stress power, sum_p V_p dev(sigma_p) : (s dev L_e,p), and they sum to zero
// (momentum is exact); and a particle at a contact takes no part.
TEST(SphElementGradient, ForcesAreTheAdjointOfTheGradient) {
  Mat3 A;
  A << 1.05, 0.1, 0.0, -0.05, 0.95, 0.02, 0.03, 0.0, 1.1;
  Model model = movedBlock(A, Vec3::Zero());
  const LocalIndex inside = insideParticle(model);
  model.points.loose[inside] = 1;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<Vec3> v(model.points.x.size());
  for (LocalIndex p = 0; p < model.points.size(); ++p) {
    v[p] = Vec3(uniform(random), uniform(random), uniform(random));
    Mat3 t;
    for (int k = 0; k < 9; ++k) t(k / 3, k % 3) = 1e8 * uniform(random);
    model.points.stress[p] = t + t.transpose();
  }
  std::vector<std::uint32_t> touches(model.points.x.size(), 0);
  touches[0] = 2;  // a corner particle touches body 1
  const Reconstruction reconstruction(model);
  const Mirrors mirrors;
  ElementGradient elements(0.5, 0.2);
  elements.update(model, reconstruction, mirrors, touches, 0);
  EXPECT_FALSE(elements.takesPart(0));
  EXPECT_FALSE(elements.takesPart(inside));
  elements.moveNodes(v, mirrors);
  std::vector<Vec3> f(model.points.x.size(), Vec3::Zero());
  elements.addForces(model.points, reconstruction, mirrors, f);
  double stress_power = 0.0, force_power = 0.0, scale = 0.0;
  Vec3 total = Vec3::Zero();
  for (LocalIndex p = 0; p < model.points.size(); ++p) {
    force_power += f[p].dot(v[p]);
    total += f[p];
    scale += f[p].norm() * v[p].norm();
    if (!elements.takesPart(p)) continue;
    const Mat3 sigma = model.points.stress[p];
    const Mat3 deviator = sigma - sigma.trace() / 3.0 * Mat3::Identity();
    stress_power += model.points.volume[p] * (deviator.cwiseProduct(elements.blend(p, Mat3::Zero()))).sum();
  }
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(std::abs(force_power + stress_power), 1e-12 * scale);
  EXPECT_LT(total.norm(), 1e-12 * scale);
  // SPH's pairs carry the rest of the stress: all of a particle's that takes no part.
  EXPECT_EQ(elements.pairStress(0, model.points.stress[0]), model.points.stress[0]);
  const Mat3 sigma = model.points.stress[inside + 1];
  ASSERT_TRUE(elements.takesPart(inside + 1));
  const Mat3 rest = elements.pairStress(inside + 1, sigma);
  EXPECT_LT((rest - (sigma - 0.5 * (sigma - sigma.trace() / 3.0 * Mat3::Identity()))).norm(), 1e-6);
}

}  // namespace
}  // namespace kessler::sph
