// RKPM (solver/rkpm/, docs/theory.md §12): the reproducing kernels' consistency, the singular moment
// matrix refused, the smoothed gradients' patch test on irregular particles (lattice cells, tet
// cells, and across a symmetry plane), a crack the kernels do not reach across, velocity collocation,
// the walls' impulses, linear momentum, kernel updates and debris that leaves the kernels. The
// surfaces and the sliding contact are in test_rkpm_contact.cpp.
#include "../blocks.hpp"
#include "approx/reproducing_kernel.hpp"
#include "core/error.hpp"
#include "geometry/structured_mesh.hpp"
#include "rkpm_blocks.hpp"
#include "solver/common/mirror.hpp"
#include "solver/common/particle_bodies.hpp"
#include "solver/methods.hpp"
#include "solver/rkpm/collocation.hpp"
#include "solver/rkpm/kernels.hpp"
#include "solver/rkpm/rkpm_method.hpp"
#include "solver/rkpm/setup.hpp"
#include "solver/rkpm/surface.hpp"
#include "solver/rkpm/wall_contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <map>
#include <random>
#include <string>

namespace kessler::rkpm {
namespace {

using namespace testing_blocks;

TEST(ReproducingKernel, ReproducesLinearFieldsOnIrregularParticles) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3), inside(0.5, 5.5);
  std::vector<Vec3> particles;
  for (int k = 0; k < 7; ++k)
    for (int j = 0; j < 7; ++j)
      for (int i = 0; i < 7; ++i) particles.push_back(Vec3(i + jitter(random), j + jitter(random), k + jitter(random)));
  for (int trial = 0; trial < 50; ++trial) {
    const Vec3 x(inside(random), inside(random), inside(random));
    std::vector<rk::Sample> samples;
    for (const Vec3& p : particles) samples.push_back({x - p, 2.0, 1.0});
    std::vector<double> psi(samples.size());
    ASSERT_GE(rk::shapeValues(samples, 1.0, psi), rk::min_rcond);
    double sum = 0.0;
    Vec3 position = Vec3::Zero();
    for (std::size_t k = 0; k < particles.size(); ++k) {
      sum += psi[k];
      position += psi[k] * particles[k];
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
    EXPECT_LT((position - x).norm(), 1e-12);
  }
}

TEST(ReproducingKernel, RefusesASingularMomentMatrix) {
  // Particles in one plane: no linear field across it can be reproduced.
  std::vector<rk::Sample> samples;
  for (int j = -2; j <= 2; ++j)
    for (int i = -2; i <= 2; ++i) samples.push_back({Vec3(0.5 * i, 0.5 * j, 0.0), 2.0, 1.0});
  std::vector<double> psi(samples.size(), -7.0);
  EXPECT_LT(rk::shapeValues(samples, 1.0, psi), rk::min_rcond);
  EXPECT_EQ(psi.front(), -7.0);  // untouched
  // And the kernels name where: a support too small to reach four particles.
  Problem problem = latticeBlock();
  problem.settings.rkpm.support = 0.6;
  const Model model = buildModel(problem);
  try {
    kernelsOf(model, problem);
    FAIL() << "a singular moment matrix was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("singular at ("), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("body 'block'"), std::string::npos) << e.what();
  }
}

// The smoothed gradients of a linear field are its gradient, in every cell (its surface's too), and the
// kernels give the field at the particles: the patch test, on particles moved within their cells.
void expectPatchTest(const Problem& problem, const Model& model, const Mat3& G, const Vec3& b,
                     std::span<const std::uint8_t> crack = {}) {
  const Kernels k = kernelsOf(model, problem, crack);
  const auto n = static_cast<LocalIndex>(model.reference.size());
  double worst_gradient = 0.0, worst_value = 0.0;
  for (LocalIndex j = 0; j < n; ++j) {
    Mat3 gradient = Mat3::Zero();
    Vec3 sum = Vec3::Zero();
    for (LocalIndex e = k.gradient.offset[j]; e < k.gradient.offset[j + 1]; ++e) {
      const auto s = static_cast<std::size_t>(e);
      const Vec3 u = G * model.reference[static_cast<std::size_t>(k.gradient.column[s])] + b;
      gradient += reflect(u, k.gradient.mirror[s]) * k.gradient.value[s].transpose();
      sum += k.gradient.value[s];
    }
    worst_gradient = std::max(worst_gradient, (gradient - G).norm() / G.norm());
    EXPECT_LT(sum.norm() * h, 1e-12);  // the gradient of a constant is zero
    Vec3 value = Vec3::Zero();
    for (LocalIndex e = k.psi.offset[j]; e < k.psi.offset[j + 1]; ++e) {
      const auto s = static_cast<std::size_t>(e);
      value += k.psi.value[s] *
               reflect(Vec3(G * model.reference[static_cast<std::size_t>(k.psi.column[s])] + b), k.psi.mirror[s]);
    }
    worst_value = std::max(worst_value, (value - (G * model.reference[j] + b)).norm());
  }
  EXPECT_LT(worst_gradient, 1e-10);
  EXPECT_LT(worst_value, 1e-12);
}

TEST(Rkpm, PatchTestOnLatticeCells) {
  Mat3 G;
  G << 0.1, -0.03, 0.02, 0.05, -0.08, 0.01, -0.04, 0.06, 0.03;
  const Problem problem = latticeBlock();
  expectPatchTest(problem, jittered(problem), G, Vec3(1e-3, 2e-3, 3e-3));
}

// A crack made before the first step (a layer of broken particles' cells) is a boundary no kernel
// reaches across (the visibility criterion): no intact particle's values or smoothed gradients take
// a coefficient from the other side of it, or from the crack's own particles; beyond the tip's reach
// the kernels are those of the uncracked block; and they still pass the patch test.
TEST(Rkpm, KernelsDoNotReachAcrossACrack) {
  BodySetup body;
  body.mesh = geometry::MeshRequest{geometry::Box{Vec3(0, 0, 0), Vec3(9e-3, 8e-3, 3e-3)}, h};
  const Problem problem = block(body);
  const Model model = jittered(problem), lattice = buildModel(problem);
  const auto n = model.reference.size();
  // The crack: the row of cells 3 mm < y < 4 mm over x < 4 mm, its tip at x = 4 mm.
  std::vector<std::uint8_t> crack(n, 0);
  auto cellCentre = [&](std::size_t p) { return lattice.reference[p]; };  // the particles are moved within them
  Mat3 G;
  G << 0.1, -0.03, 0.02, 0.05, -0.08, 0.01, -0.04, 0.06, 0.03;
  for (std::size_t p = 0; p < n; ++p)
    crack[p] = cellCentre(p)[1] > 3e-3 && cellCentre(p)[1] < 4e-3 && cellCentre(p)[0] < 4e-3;
  ASSERT_EQ(std::count(crack.begin(), crack.end(), std::uint8_t{1}), 4 * 3);
  const Kernels plain = kernelsOf(model, problem), cracked = kernelsOf(model, problem, crack);
  auto side = [&](std::size_t p) { return cellCentre(p)[1] < 3e-3 ? -1 : cellCentre(p)[1] > 4e-3 ? 1 : 0; };
  int checked = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (crack[k]) continue;
    auto expectOneSided = [&](const auto& table) {
      for (LocalIndex e = table.offset[k]; e < table.offset[k + 1]; ++e) {
        const auto i = static_cast<std::size_t>(table.column[static_cast<std::size_t>(e)]);
        EXPECT_FALSE(crack[i]) << "particle " << k << " sees the crack's particle " << i;
        // Well behind the tip (x < 2 mm), nothing across it.
        if (cellCentre(k)[0] < 2e-3 && cellCentre(i)[0] < 2e-3 && side(k) != 0) {
          EXPECT_NE(side(i), -side(k)) << "particle " << k << " sees " << i << " across the crack";
        }
      }
    };
    expectOneSided(cracked.psi);
    expectOneSided(cracked.gradient);
    // Beyond the tip by more than the support and the cell (x > 7 mm), nothing changed.
    if (cellCentre(k)[0] > 7e-3) {
      ASSERT_EQ(cracked.psi.offset[k + 1] - cracked.psi.offset[k], plain.psi.offset[k + 1] - plain.psi.offset[k]);
      for (LocalIndex e = 0; e < cracked.psi.offset[k + 1] - cracked.psi.offset[k]; ++e) {
        const auto c = static_cast<std::size_t>(cracked.psi.offset[k] + e),
                   p = static_cast<std::size_t>(plain.psi.offset[k] + e);
        EXPECT_EQ(cracked.psi.column[c], plain.psi.column[p]);
        EXPECT_EQ(cracked.psi.value[c], plain.psi.value[p]);
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
  expectPatchTest(problem, model, G, Vec3(1e-3, 2e-3, 3e-3), crack);
}

// A tet mesh's faces as cell faces, the tetrahedra as the cells.
std::vector<CellFace> tetCellFaces(const geometry::Discretisation& d) {
  std::vector<CellFace> faces;
  for (const geometry::TetFace& t : d.faces) {
    const Vec3 &a = d.nodes[t.nodes[0]], &b = d.nodes[t.nodes[1]], &c = d.nodes[t.nodes[2]];
    faces.push_back(
        {.area = 0.5 * (b - a).cross(c - a), .centroid = (a + b + c) / 3.0, .inner = t.inner, .outer = t.outer});
  }
  return faces;
}

// The smoothed gradients hold for any closed cells, not only a lattice's: the kernels built directly
// on a tet mesh's barycentres with the tetrahedra as cells (a problem's bodies are lattices:
// setup.cpp) pass the patch test too.
TEST(Rkpm, PatchTestOnTetCells) {
  Mat3 G;
  G << 0.1, -0.03, 0.02, 0.05, -0.08, 0.01, -0.04, 0.06, 0.03;
  const geometry::Discretisation d =
      geometry::discretise(geometry::structuredBoxMesh(geometry::Box{Vec3::Zero(), Vec3(4e-3, 3e-3, 3e-3)}, {4, 3, 3}));
  const std::vector<CellFace> faces = tetCellFaces(d);
  std::vector<double> support;
  for (const double v : d.volumes) support.push_back(2.0 * std::cbrt(v));
  const std::vector<int> body(d.points.size(), 0);
  const std::vector<std::string> names{"block"};
  const Kernels k = buildKernels({d.points, body, support, d.volumes, d.volumes, faces, names, MirrorBox{}});
  double worst_gradient = 0.0;
  for (std::size_t j = 0; j < d.points.size(); ++j) {
    Mat3 gradient = Mat3::Zero();
    for (LocalIndex e = k.gradient.offset[j]; e < k.gradient.offset[j + 1]; ++e) {
      const auto slot = static_cast<std::size_t>(e);
      gradient +=
          (G * d.points[static_cast<std::size_t>(k.gradient.column[slot])]) * k.gradient.value[slot].transpose();
    }
    worst_gradient = std::max(worst_gradient, (gradient - G).norm() / G.norm());
  }
  EXPECT_LT(worst_gradient, 1e-10);
}

// A few supports stretched far beyond the rest (as after kernel updates) are searched apart from the
// others (kernels.cpp, Search): every row still holds exactly the particles whose support reaches it,
// and the kernels still reproduce a linear field.
TEST(Rkpm, StretchedSupportsReachEveryPointTheyCover) {
  const geometry::Discretisation d =
      geometry::discretise(geometry::structuredBoxMesh(geometry::Box{Vec3::Zero(), Vec3(6e-3, 4e-3, 4e-3)}, {6, 4, 4}));
  const std::vector<CellFace> faces = tetCellFaces(d);
  std::vector<double> support;
  for (const double v : d.volumes) support.push_back(2.0 * std::cbrt(v));
  const double common = *std::max_element(support.begin(), support.end());
  // Fewer than one particle in a hundred, each reaching four times as far.
  const std::vector<std::size_t> stretched{0, d.points.size() / 2};
  ASSERT_LT(100 * stretched.size(), d.points.size());
  for (const std::size_t p : stretched) support[p] *= 4.0;
  const std::vector<int> body(d.points.size(), 0);
  const std::vector<std::string> names{"block"};
  const Kernels k = buildKernels({d.points, body, support, d.volumes, d.volumes, faces, names, MirrorBox{}});
  long beyond = 0;  // entries of a stretched particle farther than any other support reaches
  const Vec3 shift(1e-3, -2e-3, 0.5e-3);
  const Mat3 G = Vec3(0.1, -0.05, 0.02).asDiagonal();
  for (std::size_t q = 0; q < d.points.size(); ++q) {
    std::vector<LocalIndex> expected, found;
    for (std::size_t i = 0; i < d.points.size(); ++i)
      if ((d.points[q] - d.points[i]).norm() < support[i]) expected.push_back(static_cast<LocalIndex>(i));
    Vec3 value = Vec3::Zero();
    for (LocalIndex e = k.psi.offset[q]; e < k.psi.offset[q + 1]; ++e) {
      const auto slot = static_cast<std::size_t>(e);
      const auto i = static_cast<std::size_t>(k.psi.column[slot]);
      found.push_back(k.psi.column[slot]);
      value += k.psi.value[slot] * (G * d.points[i] + shift);
      if ((d.points[q] - d.points[i]).norm() >= common) ++beyond;
    }
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, expected) << "row " << q;
    EXPECT_LT((value - (G * d.points[q] + shift)).norm(), 1e-15) << "row " << q;
  }
  EXPECT_GT(beyond, 0);
}

TEST(Rkpm, PatchTestAcrossSymmetryPlanes) {
  // A field the mirror images share (u_x odd in x and even in y, u_y the other way, u_z even in both):
  // a diagonal gradient.
  const Mat3 G = Vec3(0.1, -0.08, 0.03).asDiagonal();
  const Problem problem = latticeBlock({0, 1});
  expectPatchTest(problem, jittered(problem), G, Vec3(0.0, 0.0, 3e-3));
}

// Between two rollers facing each other (x = 0 and x = 4 mm) and beside a third (y <= 3 mm), on
// jittered particles: the images repeat across both x planes. A field they share (u_x = 0, u_y odd about y = 3 mm,
// u_z even about every plane) passes the patch test, and the kernels with their shifts put every
// particle where it is.
TEST(Rkpm, PatchTestBetweenRollers) {
  BodySetup body;
  body.mesh = geometry::MeshRequest{geometry::Box{Vec3::Zero(), Vec3(4e-3, 3e-3, 3e-3)}, h};
  Problem problem = block(body);
  problem.rollers = {{.axis = 0, .offset = 0.0, .side = 1},
                     {.axis = 0, .offset = 4e-3, .side = -1},
                     {.axis = 1, .offset = 3e-3, .side = -1}};
  const Model model = jittered(problem);
  const Mat3 G = Vec3(0.0, -0.08, 0.03).asDiagonal();
  expectPatchTest(problem, model, G, Vec3(0.0, 0.08 * 3e-3, 1e-3));
  const Kernels k = kernelsOf(model, problem);
  ASSERT_EQ(k.shift.size(), model.reference.size());
  double worst = 0.0;
  for (std::size_t j = 0; j < model.reference.size(); ++j) {
    Vec3 x = k.shift[j];
    for (LocalIndex e = k.psi.offset[j]; e < k.psi.offset[j + 1]; ++e) {
      const auto s = static_cast<std::size_t>(e);
      x += k.psi.value[s] * reflect(model.reference[static_cast<std::size_t>(k.psi.column[s])], k.psi.mirror[s]);
    }
    worst = std::max(worst, (x - model.reference[j]).norm());
  }
  EXPECT_LT(worst, 1e-15);
  // Each particle beside x = 4 mm sees images across it.
  bool image = false;
  for (std::size_t e = 0; e < k.psi.mirror.size(); ++e) image = image || k.psi.mirror[e] != 0;
  EXPECT_TRUE(image);
}

// The prescribed velocities hold at their particles after collocation, to round-off, whatever the
// other coefficients are.
TEST(Rkpm, VelocityCollocationHoldsThePrescribedVelocity) {
  const Problem problem = latticeBlock({0});
  const Model model = jittered(problem);
  const Kernels k = kernelsOf(model, problem);
  const auto n = static_cast<LocalIndex>(model.reference.size());
  std::vector<std::uint8_t> constrained(static_cast<std::size_t>(n), 0);
  std::vector<Vec3> prescribed(static_cast<std::size_t>(n), Vec3::Zero());
  for (LocalIndex p = 0; p < n; ++p) {
    const Vec3& x = model.reference[p];
    if (x.z() < h) {  // the bottom layer: every component, varying over it
      constrained[p] = 7;
      prescribed[p] = Vec3(3.0 + 1e3 * x.y(), -2.0 * x.x() * 1e3, 0.5);
    } else if (x.y() > 3e-3) {  // the far side: its normal component only
      constrained[p] = 2;
      prescribed[p].y() = 1.5;
    }
  }
  std::mt19937 random(5);
  std::uniform_real_distribution<double> speed(-100.0, 100.0);
  std::vector<Vec3> v(static_cast<std::size_t>(n));
  for (Vec3& c : v) c = Vec3(speed(random), speed(random), speed(random));
  std::uniform_real_distribution<double> spread(0.5, 1.5);
  std::vector<double> mass(static_cast<std::size_t>(n));
  for (double& m : mass) m = 1e-6 * spread(random);
  auto kinetic = [&](const std::vector<Vec3>& u) {
    double e = 0.0;
    for (std::size_t i = 0; i < u.size(); ++i) e += 0.5 * mass[i] * u[i].squaredNorm();
    return e;
  };
  const VelocityCollocation collocation(k.psi, constrained, mass);
  const std::vector<Vec3> before = v;
  collocation.impose(prescribed, v);
  std::vector<Vec3> at(static_cast<std::size_t>(n));
  interpolate(k.psi, v, at);
  double worst = 0.0;
  for (LocalIndex p = 0; p < n; ++p)
    for (int a = 0; a < 3; ++a)
      if (constrained[p] & (1u << a)) worst = std::max(worst, std::abs(at[p][a] - prescribed[p][a]));
  EXPECT_LT(worst, 1e-12 * 100.0);  // relative to the speeds

  // A still boundary takes kinetic energy and never gives it: the coefficients are the nearest in the
  // masses' metric to those before that meet it, so the energy falls by exactly that of the change.
  for (Vec3& g : prescribed) g.setZero();
  v = before;
  collocation.impose(prescribed, v);
  double change = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) change += 0.5 * mass[i] * (v[i] - before[i]).squaredNorm();
  EXPECT_GT(change, 0.0);
  EXPECT_NEAR(kinetic(before) - kinetic(v), change, 1e-9 * kinetic(before));
}

// A plane holds the velocity on the body's surface faces in it, where the cells' smoothed gradients
// read it, not at particles inside: on jittered particles, only those whose cells have a face in the
// plane are held, and after collocation the velocity at those faces' centroids is the plane's.
TEST(Rkpm, PlanesHoldTheVelocityOnTheSurfaceFaces) {
  BodySetup body;
  body.mesh = geometry::MeshRequest{geometry::Box{Vec3::Zero(), Vec3(4e-3, 3e-3, 3e-3)}, h};
  Problem problem = block(body);
  const double tol = 1e-9 * h;
  problem.planes = {{.axis = 0, .offset = 0.0, .tolerance = tol, .velocity = 0.0},
                    {.axis = 0, .offset = 4e-3, .tolerance = tol, .velocity = 2.0}};
  const Model model = jittered(problem);
  const SurfaceHolds holds = surfaceHolds(model);
  ASSERT_FALSE(holds.faces.empty());
  for (std::size_t r = 0; r < holds.faces.size(); ++r) {
    const CellFace& f = model.faces[static_cast<std::size_t>(holds.faces[r])];
    EXPECT_EQ(holds.held[r].axis, 0);
    EXPECT_LT(std::min(std::abs(f.centroid.x()), std::abs(f.centroid.x() - 4e-3)), tol);
  }
  // Every held particle has a cell face in a plane, and only those are held: the two end layers of
  // 3 x 3 elements, not the particles of the next layers, which a jitter brings within a spacing.
  long held = 0;
  for (LocalIndex p = 0; p < model.points.size(); ++p) {
    if (!(model.constrained[p] & held_at_surface)) continue;
    ++held;
    EXPECT_TRUE(model.constrained[p] & 1u);
    bool has_face = false;
    for (const HeldFace& f : holds.held) has_face = has_face || f.particle == p;
    EXPECT_TRUE(has_face) << "particle " << p;
  }
  EXPECT_EQ(held, 18);
  EXPECT_EQ(static_cast<std::size_t>(held), holds.faces.size());  // one face in a plane each

  std::vector<double> support;
  for (const double s : model.points.spacing0) support.push_back(problem.settings.rkpm.support * s);
  const std::vector<std::string> names{"block"};
  const Kernels k = buildKernels({model.reference, model.points.body, support, model.points.volume0, model.cell_volume,
                                  model.faces, names, mirrorBox(problem), holds.faces});
  std::mt19937 random(8);
  std::uniform_real_distribution<double> speed(-50.0, 50.0);
  std::vector<Vec3> v(model.reference.size());
  for (Vec3& c : v) c = Vec3(speed(random), speed(random), speed(random));
  std::vector<double> mass(v.size(), 1e-6);
  const VelocityCollocation collocation(k.psi, model.constrained, mass, k.at_faces, holds.held);
  collocation.impose(model.prescribed_v, v);
  for (std::size_t r = 0; r < holds.faces.size(); ++r) {
    double vx = 0.0;
    for (LocalIndex e = k.at_faces.offset[r]; e < k.at_faces.offset[r + 1]; ++e)
      vx += k.at_faces.value[static_cast<std::size_t>(e)] *
            v[static_cast<std::size_t>(k.at_faces.column[static_cast<std::size_t>(e)])].x();
    const double want = model.faces[static_cast<std::size_t>(holds.faces[r])].centroid.x() > 1e-3 ? 2.0 : 0.0;
    EXPECT_NEAR(vx, want, 1e-12 * 50.0) << "face row " << r;
  }
}

// A rigid wall meets the particles, not the coefficients: a jittered block moving at random velocities
// onto the wall z = 0 (its bottom particles a jitter from their gap, half a spacing), after the walls'
// impulses no particle ends the step closer to the wall than its gap (to round-off), the tangential
// velocities are untouched, and the momentum gained is the wall's push (normal, towards +z).
TEST(Rkpm, WallImpulsesKeepTheParticlesOutOfTheWall) {
  const Problem problem = latticeBlock({0});
  const Model model = jittered(problem);
  const Kernels k = kernelsOf(model, problem);
  const auto n = static_cast<std::size_t>(model.reference.size());
  std::vector<double> mass(n, 0.0), gap(n);
  for (std::size_t p = 0; p < n; ++p) {
    gap[p] = 0.5 * model.points.spacing0[p];
    for (LocalIndex e = k.psi.offset[p]; e < k.psi.offset[p + 1]; ++e)
      mass[static_cast<std::size_t>(k.psi.column[static_cast<std::size_t>(e)])] +=
          model.points.mass[p] * k.psi.value[static_cast<std::size_t>(e)];
  }
  std::mt19937 random(7);
  std::uniform_real_distribution<double> speed(-50.0, 50.0);
  std::vector<Vec3> v(n);
  for (Vec3& c : v) c = Vec3(speed(random), speed(random), speed(random) - 200.0);
  const std::vector<Vec3> before = v;
  const double dt = 1e-6;  // 0.2 mm at 200 m/s: the bottom two layers would cross
  const std::vector<RigidWall> walls{RigidWall{2, 0.0, 1}};
  const std::size_t pushed = imposeWalls(walls, k.psi, mass, model.reference, gap, dt, v);
  EXPECT_GT(pushed, 0u);
  std::vector<Vec3> at(n);
  interpolate(k.psi, v, at);
  double worst = 0.0;
  Vec3 momentum = Vec3::Zero();
  for (std::size_t p = 0; p < n; ++p) {
    worst = std::max(worst, gap[p] - (model.reference[p].z() + dt * at[p].z()));
    EXPECT_EQ(v[p].x(), before[p].x());
    EXPECT_EQ(v[p].y(), before[p].y());
    momentum += mass[p] * (v[p] - before[p]);
  }
  EXPECT_LT(worst, 1e-12 * h);
  EXPECT_GT(momentum.z(), 0.0);
}

// A free block with a linear velocity field: every particle's first deformation gradient is I + dt G
// (the patch test through the method), and with random velocities the forces, whose smoothed
// gradients sum to zero over each cell, keep the linear momentum to round-off.
TEST(Rkpm, FirstStepOfALinearFieldAndMomentum) {
  Mat3 G;
  G << 100.0, -30.0, 20.0, 50.0, -80.0, 10.0, -40.0, 60.0, 30.0;
  Problem problem = latticeBlock();
  problem.bodies[0].velocity_field = [&](const Vec3& x) { return Vec3(G * x + Vec3(1.0, 2.0, 3.0)); };
  {
    const std::unique_ptr<Method> method = makeMethod(problem);
    method->initialise();
    method->step();
    const double dt = method->clock().dt_last;
    const PointStore& points = method->state().points;
    double worst = 0.0;
    for (LocalIndex p = 0; p < points.owned; ++p)
      worst = std::max(worst, (points.F[p] - Mat3::Identity() - dt * G).norm() / (dt * G.norm()));
    EXPECT_LT(worst, 1e-9);
  }
  std::mt19937 random(9);
  std::uniform_real_distribution<double> speed(-50.0, 50.0);
  problem.bodies[0].velocity_field = [&](const Vec3&) { return Vec3(speed(random), speed(random), speed(random)); };
  problem.settings.solver.end_time = 2e-6;
  const std::unique_ptr<Method> method = makeMethod(problem);
  method->initialise();
  const Vec3 before = method->energies().momentum;
  while (!method->finished()) method->step();
  const Vec3 after = method->energies().momentum;
  EXPECT_GT(method->clock().steps, 10);
  const double scale = method->energies().kinetic > 0.0 ? std::sqrt(2.0 * 0.035 * method->energies().kinetic) : 1.0;
  EXPECT_LT((after - before).norm(), 1e-12 * scale)
      << "momentum before " << before.transpose() << ", after " << after.transpose();
}

// A box lattice's surface triangles close over its boundary particles: they span the box through the
// particle centres (half a spacing inside the box), each counter-clockwise seen from outside.
// A kernel update (docs/theory.md §12) carries a linear motion through exactly: with an update after
// every step, a block beside a symmetry plane, moving with a linear velocity field (a material too soft
// to bend it), has the particles' positions, velocities and deformation gradients of the run without
// updates, and their momentum along the plane.
TEST(Rkpm, KernelUpdatesCarryALinearMotionThrough) {
  Mat3 G;
  G << -300.0, 80.0, 0.0, 50.0, 200.0, 0.0, 0.0, 0.0, -150.0;  // v_z = 0 on the plane z = 0, and mirrored
  Problem problem = latticeBlock({2});
  NeoHookeanParameters soft;
  soft.density = 2700.0;
  soft.youngs_modulus = 1e-9;
  soft.poisson_ratio = 0.3;
  problem.bodies[0].material = std::make_shared<NeoHookean>("soft", soft);
  problem.bodies[0].velocity_field = [&](const Vec3& x) { return Vec3(G * x + Vec3(1.0, -2.0, 0.0)); };
  problem.settings.solver.end_time = 1.0;
  auto run = [&](double update_strain) {
    problem.settings.rkpm.update_strain = update_strain;
    std::unique_ptr<Method> method = makeMethod(problem);
    method->initialise();
    for (int s = 0; s < 20; ++s) method->step();
    return method;
  };
  const std::unique_ptr<Method> plain = run(0.0), updated = run(1e-12);
  const auto& rkpm = dynamic_cast<const RkpmMethod&>(*updated);
  EXPECT_EQ(rkpm.integrator().kernelUpdates().made, 20);
  const PointStore &a = plain->state().points, &b = updated->state().points;
  double strain = 0.0, dx = 0.0, dv = 0.0, dF = 0.0;
  Vec3 momentum_a = Vec3::Zero(), momentum_b = Vec3::Zero();  // the particles', along the plane
  for (LocalIndex p = 0; p < a.owned; ++p) {
    momentum_a += a.mass[p] * Vec3(a.v[p].x(), a.v[p].y(), 0.0);
    momentum_b += b.mass[p] * Vec3(b.v[p].x(), b.v[p].y(), 0.0);
    strain = std::max(strain, (a.F[p] - Mat3::Identity()).norm());
    dx = std::max(dx, (a.x[p] - b.x[p]).norm());
    dv = std::max(dv, (a.v[p] - b.v[p]).norm());
    dF = std::max(dF, (a.F[p] - b.F[p]).norm());
  }
  EXPECT_GT(strain, 0.05);  // the motion deformed the block
  EXPECT_LT(dx, 1e-12);     // m, in a 5 mm block
  EXPECT_LT(dv, 1e-9);      // m/s, of about 1
  EXPECT_LT(dF, 1e-9);
  EXPECT_LT((momentum_a - momentum_b).norm(), 1e-12 * momentum_a.norm());
}

// A particle that becomes debris leaves the kernels at the next update, at most 20 steps later, with
// no strain to ask for one: it stands alone (its row its own coefficient, in no other row) and flies
// on at the velocity it had, and the coefficients keep the particles' momentum (the block's stress
// conserves it too).
TEST(Rkpm, DebrisLeavesTheKernelsWithinTwentySteps) {
  Mat3 G;
  G << -300.0, 80.0, 0.0, 50.0, 200.0, 0.0, 0.0, 0.0, -150.0;
  Problem problem = latticeBlock();  // aluminium
  problem.bodies[0].velocity_field = [&](const Vec3& x) { return Vec3(G * x + Vec3(1.0, -2.0, 0.5)); };
  problem.settings.solver.end_time = 1.0;
  problem.settings.rkpm.update_strain = 1e9;  // no update for the strain's sake
  Model model = buildModel(problem);
  Integrator integrator(model, settingsFor(problem));
  integrator.initialise();
  for (int s = 0; s < 3; ++s) integrator.step();
  PointStore& points = model.points;
  LocalIndex p = 0;  // the particle nearest the block's middle
  for (LocalIndex k = 0; k < points.owned; ++k)
    if ((points.x[k] - Vec3(2.5e-3, 2e-3, 1.5e-3)).norm() < (points.x[p] - Vec3(2.5e-3, 2e-3, 1.5e-3)).norm()) p = k;
  points.broken[p] = 1;
  points.carrier[p] = -1;
  ASSERT_TRUE(points.debris(p));
  auto momentum = [&] {
    Vec3 sum = Vec3::Zero();
    for (LocalIndex k = 0; k < points.owned; ++k) sum += points.mass[k] * points.v[k];
    return sum;
  };
  const Vec3 before = momentum();
  int steps = 0;  // to the next update: debris updates come every 20 steps
  while (integrator.kernelUpdates().made == 0 && steps < 20) {
    integrator.step();
    ++steps;
  }
  EXPECT_EQ(integrator.kernelUpdates().made, 1);
  EXPECT_EQ(integrator.clock().steps % 20, 0);
  const Kernels& k = integrator.kernels();
  EXPECT_EQ(k.psi.offset[p + 1] - k.psi.offset[p], 1);
  EXPECT_EQ(k.psi.column[static_cast<std::size_t>(k.psi.offset[p])], p);
  EXPECT_EQ(k.psi.value[static_cast<std::size_t>(k.psi.offset[p])], 1.0);
  for (LocalIndex r = 0; r < points.owned; ++r) {
    if (r == p) continue;
    for (LocalIndex e = k.psi.offset[r]; e < k.psi.offset[r + 1]; ++e)
      EXPECT_NE(k.psi.column[static_cast<std::size_t>(e)], p) << "row " << r;
    for (LocalIndex e = k.gradient.offset[r]; e < k.gradient.offset[r + 1]; ++e)
      EXPECT_NE(k.gradient.column[static_cast<std::size_t>(e)], p) << "row " << r;
  }
  EXPECT_LT((momentum() - before).norm(), 1e-12 * before.norm());
  const Vec3 x0 = points.x[p], v0 = points.v[p];
  const double t0 = integrator.clock().time;
  for (int s = 0; s < 25; ++s) integrator.step();
  EXPECT_EQ(integrator.kernelUpdates().made, 1);  // none more: the debris is alone
  EXPECT_LT((points.v[p] - v0).norm(), 1e-12 * v0.norm());
  EXPECT_LT((points.x[p] - x0 - (integrator.clock().time - t0) * v0).norm(), 1e-15);
}

}  // namespace
}  // namespace kessler::rkpm
