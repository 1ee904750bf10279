// The nodal patch of the volume change (solver/otm/volume_patch.hpp, docs/theory.md §4-5): the
// limiter takes the quadratic viscosity off a smooth compression and leaves it on a shock; volume
// averaging with its stabilisation keeps a body at rest bitwise at rest, conserves momentum through
// a collision and books the stabilisation's stored energy, as the defect relaxes and as the
// stiffness changes; a cold gas gets a time step from the volume-change bound.
#include "core/error.hpp"
#include "geometry/structured_mesh.hpp"
#include "material/impact_material.hpp"
#include "material/library.hpp"
#include "solver/otm/integrator.hpp"
#include "solver/otm/setup.hpp"
#include "solver/otm/volume_patch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace kessler::otm {
namespace {

MaterialPtr aluminium() {
  ImpactMaterialParameters p = library::find("Al6061-T6").parameters;
  p.damage.reset();
  p.fracture_energy = 0.0;
  return std::make_shared<ImpactMaterial>("al", p);
}

geometry::Discretisation box(const Vec3& lo, const Vec3& hi, const std::array<int, 3>& cells) {
  return geometry::discretise(geometry::structuredBoxMesh(geometry::Box{lo, hi}, cells));
}

TEST(ChristensenLimiter, OneForALinearFieldZeroAtAnExtremum) {
  EXPECT_DOUBLE_EQ(christensenLimiter(1.0, 1.0), 1.0);   // uniform compression
  EXPECT_DOUBLE_EQ(christensenLimiter(1.0, 0.8), 1.0);   // linearly varying: the mean ratio is 1
  EXPECT_DOUBLE_EQ(christensenLimiter(0.6, 0.5), 0.6);   // a peak of compression
  EXPECT_DOUBLE_EQ(christensenLimiter(0.9, 0.2), 0.4);   // one side barely compressed: a shock's foot
  EXPECT_DOUBLE_EQ(christensenLimiter(0.3, -0.5), 0.0);  // a neighbour expands
}

// The stabilisation does not pull an intact point harder than its material can bear: with a large
// positive defect (own volume grown past its patch's) its tensile pressure stops where the point's mean
// stress, its own pressure plus the stabilisation's, reaches minus the tensile limit (Al 6061-T6: its
// spall strength); within the limit, and without one, it is -alpha rho c^2 d; a failed point's pushes
// only. Without the limit, a hot jetting point in a Johnson-Cook run was held at -40 GPa against
// +20 GPa of its own, and the work of its expansion came back as heat (docs/validation.md).
TEST(StabilisationPressure, PullsAnIntactPointNoHarderThanItsTensileLimit) {
  const double limit = aluminium()->tensileLimit();
  EXPECT_DOUBLE_EQ(limit, library::find("Al6061-T6").parameters.spall_strength);
  PointStore points;
  points.resize(1);
  points.mass[0] = 2.7e-6;
  points.volume[0] = points.volume0[0] = 1e-9;
  points.sound_speed[0] = 6000.0;
  points.body[0] = 0;
  const double own = 20e9;  // the point's pressure
  points.stress[0] = -own * Mat3::Identity();
  const double stiffness = points.density(0) * 6000.0 * 6000.0;

  points.volume_defect[0] = 0.4;  // -0.4 rho c^2 = -39 GPa: beyond the limit
  EXPECT_DOUBLE_EQ(stabilisationPressure(points, 0, 1.0, limit), -(own + limit));
  EXPECT_DOUBLE_EQ(stabilisationPressure(points, 0, 1.0), -0.4 * stiffness);
  points.volume_defect[0] = 0.1;  // -9.7 GPa: within it
  EXPECT_DOUBLE_EQ(stabilisationPressure(points, 0, 1.0, limit), -0.1 * stiffness);
  points.volume_defect[0] = -0.1;  // compression: never limited
  EXPECT_DOUBLE_EQ(stabilisationPressure(points, 0, 1.0, limit), 0.1 * stiffness);
  points.fail(0);
  points.volume_defect[0] = 0.4;
  EXPECT_DOUBLE_EQ(stabilisationPressure(points, 0, 1.0, limit), 0.0);
}

// An aluminium cube at rest, `cells` cells of 1 mm a side, as an integrator leaves it initialised
// (connectivity, sound speeds).
Model restingBlock(int cells) {
  Model model;
  const double edge = 1e-3 * cells;
  addBody(model, "block", aluminium(), box(Vec3::Zero(), Vec3(edge, edge, edge), {cells, cells, cells}), Vec3::Zero());
  Settings settings;
  settings.end_time = 1.0;
  Integrator integrator(model, settings);
  integrator.initialise();
  return model;
}

// The nodes of a block moved by a displacement field over one step of length dt; returns the
// points' limiter after the step.
std::vector<double> limiterAfter(const std::function<Vec3(const Vec3&)>& displacement) {
  Model model = restingBlock(8);
  const Connectivity& conn = model.connectivity;
  PointStore& points = model.points;
  std::vector<double> j(static_cast<std::size_t>(points.owned));
  for (LocalIndex p = 0; p < points.owned; ++p) {
    Mat3 dF = Mat3::Identity();
    for (Index e = conn.offset[p]; e < conn.offset[p + 1]; ++e)
      dF += displacement(model.nodes.x[conn.node[e]]) * conn.dN[e].transpose();
    points.dF[p] = dF;
    j[p] = dF.determinant();
  }
  VolumePatch patch;
  patch.apply(conn, model.nodes.owned, true, 1.0, 0.0, 0.0, points, j);
  std::vector<double> phi;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    const Vec3& x = points.x[p];
    // Interior points only: a boundary point's patch is one-sided.
    if ((x.array() > 2.5e-3).all() && (x.array() < 5.5e-3).all()) phi.push_back(points.viscosity_limiter[p]);
  }
  return phi;
}

TEST(VolumePatch, ASmoothCompressionIsNotViscous) {
  // Uniform and linearly varying compression along z: the limiter is 1 (no quadratic viscosity).
  for (const auto& field : {std::function<Vec3(const Vec3&)>([](const Vec3& x) { return Vec3(0, 0, -1e-3 * x[2]); }),
                            std::function<Vec3(const Vec3&)>(
                                [](const Vec3& x) { return Vec3(0, 0, -1e-3 * x[2] * (1.0 + 20.0 * x[2])); })}) {
    const std::vector<double> phi = limiterAfter(field);
    ASSERT_FALSE(phi.empty());
    for (double value : phi) EXPECT_GT(value, 0.99);
  }
}

TEST(VolumePatch, AShockIsViscous) {
  // A compression confined to a layer two cells thick (z in [3.5, 4.5] mm): the points inside it are
  // limited to well below 1.
  const std::vector<double> phi = limiterAfter([](const Vec3& x) {
    const double z = std::clamp(x[2], 3.5e-3, 4.5e-3);
    return Vec3(0, 0, -1e-2 * (z - 3.5e-3));
  });
  double smallest = 1.0;
  for (double value : phi) smallest = std::min(smallest, value);
  EXPECT_LT(smallest, 0.5);
}

TEST(VolumeStabilisation, ABodyAtRestStaysBitwiseAtRest) {
  Model model;
  addBody(model, "block", aluminium(), box(Vec3::Zero(), Vec3(4e-3, 4e-3, 4e-3), {4, 4, 4}), Vec3::Zero());
  std::vector<Vec3> x0(static_cast<std::size_t>(model.nodes.size()));  // by node id: the integrator reorders
  for (LocalIndex a = 0; a < model.nodes.size(); ++a)
    x0[static_cast<std::size_t>(model.nodes.id[a])] = model.nodes.x[a];
  Settings settings;
  settings.end_time = 1.0;
  Integrator integrator(model, settings);
  integrator.initialise();
  for (int k = 0; k < 20; ++k) integrator.step();
  for (LocalIndex a = 0; a < model.nodes.size(); ++a)
    EXPECT_EQ(model.nodes.x[a], x0[static_cast<std::size_t>(model.nodes.id[a])]);
  for (LocalIndex p = 0; p < model.points.owned; ++p) EXPECT_EQ(model.points.volume_defect[p], 0.0);
}

TEST(VolumeStabilisation, StoredEnergyFollowsTheRelaxationAndTheStiffness) {
  // A block at rest with a uniform defect d0 and no volume change over the step: after one step dt
  // with relaxation k, each point's defect is d0 exp(-dt c / (k h)), and the work booked is minus the
  // stored energy freed, alpha m c^2 (d0^2 - d^2) / 2 per point (S = -alpha rho c^2 d). A failed
  // point keeps its defect.
  Model model = restingBlock(4);
  PointStore& points = model.points;
  const double d0 = -2e-3, alpha = 1.0, k = 10.0, dt = 1e-8;
  std::vector<double> j(static_cast<std::size_t>(points.owned), 1.0);
  for (LocalIndex p = 0; p < points.owned; ++p) {
    points.volume_defect[p] = d0;
    points.dF[p].setIdentity();
  }
  const LocalIndex failed = points.owned / 2;
  points.fail(failed);
  VolumePatch patch;
  const double work = patch.apply(model.connectivity, model.nodes.owned, true, alpha, k, dt, points, j);
  EXPECT_EQ(points.volume_defect[failed], d0);
  double freed = 0.0;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (p == failed) continue;
    const double c = points.sound_speed[p], h = points.spacing(p);
    ASSERT_GT(c, 0.0);
    const double d = d0 * std::exp(-dt * c / (k * h));
    EXPECT_NEAR(points.volume_defect[p], d, 1e-12 * std::abs(d0));
    EXPECT_LT(std::abs(points.volume_defect[p]), std::abs(d0));
    freed += 0.5 * alpha * points.mass[p] * c * c * (d0 * d0 - d * d);
  }
  EXPECT_GT(freed, 0.0);
  EXPECT_NEAR(work, -freed, 1e-9 * freed);
  // The material update doubles every signal speed at the same defect: the stored energy
  // alpha m c^2 d^2 / 2 grows fourfold, and closeStep() books the growth (taken from the heat).
  double growth = 0.0;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    const double c = points.sound_speed[p], d = points.volume_defect[p];
    if (p != failed) growth += 0.5 * alpha * points.mass[p] * d * d * 3.0 * c * c;
    points.sound_speed[p] = 2.0 * c;
  }
  EXPECT_NEAR(patch.closeStep(points, alpha), growth, 1e-9 * growth);
}

// A block strikes a plate obliquely at 2 km/s for 0.5 us, with or without volume averaging, with
// stabilisation factor `alpha`, at the given cfl.
Energies collide(bool averaging, double alpha, double cfl, Energies& before) {
  Model model;
  const MaterialPtr al = aluminium();
  addBody(model, "block", al, box(Vec3(-1e-3, -1e-3, 0.2e-3), Vec3(1e-3, 1e-3, 2.2e-3), {4, 4, 4}),
          Vec3(500.0, 0, -2000.0));
  addBody(model, "plate", al, box(Vec3(-4e-3, -4e-3, -2e-3), Vec3(4e-3, 4e-3, 0), {16, 16, 4}), Vec3::Zero());
  Settings settings;
  settings.end_time = 0.5e-6;
  settings.cfl = cfl;
  settings.volume_averaging = averaging;
  settings.volume_stabilisation = alpha;
  Integrator integrator(model, settings);
  integrator.initialise();
  before = integrator.energies();
  while (!integrator.finished()) integrator.step();
  const Energies after = integrator.energies();
  EXPECT_LT((after.momentum - before.momentum).norm(), 1e-10 * before.momentum.norm())
      << "averaging " << averaging << ", alpha " << alpha << ", cfl " << cfl;
  return after;
}

// The relative change of the total energy (kinetic, internal and the stabilisation's stored energy).
double energyChange(bool averaging, double alpha, double cfl) {
  Energies before;
  const Energies after = collide(averaging, alpha, cfl, before);
  return after.total() / before.total() - 1.0;
}

TEST(VolumeStabilisation, ConservesMomentumAndBooksItsEnergy) {
  // Momentum stays exact. Kinetic, internal and the stabilisation's stored energy balance at any
  // step, with or without stabilisation: each intact point takes as internal energy the work its
  // forces did on the nodes (the compatible energy update, docs/theory.md §4 step 5). What is left is
  // the work of the few points that fail at the contact, which is not booked: measured 3.7e-5 and
  // 1.8e-5 of the energy (alpha 0, 1) and 1.2e-5 without averaging, at cfl 0.1 (with no failed point
  // the balance holds to 1e-15). Before that update (2026-11-26) the total changed by -1.13% at cfl
  // 0.1 with stabilisation and -0.48% without, first order in the step.
  for (double alpha : {0.0, 1.0}) {
    const double change = energyChange(true, alpha, 0.1);
    EXPECT_LT(std::abs(change), 1e-4) << "alpha " << alpha;
  }
  EXPECT_LT(std::abs(energyChange(false, 0.0, 0.1)), 1e-4) << "without averaging";
}

TEST(TimeStep, AColdGasStepsOnItsVolumeChange) {
  // An ideal gas at e = 0 has no sound speed: flowing inward at 1 m/s, the first step comes from the
  // volume-change bound |div v| dt <= cfl / 3; at rest there is no step at all, and it says so.
  const library::Entry& gas = library::find("ideal-gas-5/3");
  auto material = std::make_shared<ImpactMaterial>(gas.name, gas.parameters);
  auto build = [&](bool converging) {
    Model model;
    addBody(model, "gas", material, box(Vec3(-1, -1, -1), Vec3(1, 1, 1), {4, 4, 4}), Vec3::Zero());
    if (converging)
      for (LocalIndex a = 0; a < model.nodes.size(); ++a) model.nodes.v[a] = -model.nodes.x[a];
    return model;
  };
  Settings settings;
  settings.end_time = 1.0;
  Model converging = build(true);
  Integrator integrator(converging, settings);
  integrator.initialise();
  // v = -x: div v = -3 everywhere, so dt = cfl / 9.
  EXPECT_NEAR(integrator.nextStep(), settings.cfl / 9.0, 1e-9);
  Model still = build(false);
  Integrator at_rest(still, settings);
  EXPECT_THROW(at_rest.initialise(), Error);
}

}  // namespace
}  // namespace kessler::otm
