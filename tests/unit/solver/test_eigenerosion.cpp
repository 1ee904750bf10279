// Eigenerosion (solver/common/eigenerosion.hpp): the cell-bounded pass erodes exactly the points
// that the plain definition G_p = C_eps sum_B m_q W_q / sum_B m_q >= G_c erodes, evaluated by
// brute force over all pairs, for two bodies with scattered energies (some near the threshold).
#include "geometry/structured_mesh.hpp"
#include "material/neo_hookean.hpp"
#include "solver/common/eigenerosion.hpp"
#include "solver/common/release.hpp"
#include "solver/otm/settings.hpp"
#include "solver/otm/setup.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace kessler::otm {
namespace {

// Three bodies (two eroding, one not) with W scattered around the threshold: a hot spot at 1.5
// times G_c / C_eps of a typical point, decaying over 2 mm, with a random factor per point, so the
// ball averages land on both sides of the threshold; every tenth point is already eroded.
Model hotSpotModel(const Settings& settings, double nu) {
  NeoHookeanParameters p;
  p.density = 2700.0;
  p.youngs_modulus = 70e9;
  p.poisson_ratio = nu;
  p.fracture_energy = 100.0;
  auto brittle = std::make_shared<NeoHookean>("brittle", p);
  p.fracture_energy = 0.0;
  auto tough = std::make_shared<NeoHookean>("never erodes", p);
  Model model;
  auto box = [](const Vec3& lo, const Vec3& hi, const std::array<int, 3>& cells) {
    return geometry::discretise(geometry::structuredBoxMesh(geometry::Box{lo, hi}, cells));
  };
  addBody(model, "a", brittle, box(Vec3(0, 0, 0), Vec3(8e-3, 6e-3, 3e-3), {8, 6, 3}), Vec3::Zero());
  addBody(model, "b", brittle, box(Vec3(8.5e-3, 0, 0), Vec3(12e-3, 6e-3, 3e-3), {4, 6, 3}), Vec3::Zero());
  addBody(model, "c", tough, box(Vec3(0, 7e-3, 0), Vec3(4e-3, 10e-3, 3e-3), {4, 3, 3}), Vec3::Zero());
  PointStore& points = model.points;
  const double threshold = 100.0 / erosionCalibration(settings.erosion_radius * points.spacing(0), nu);
  const Vec3 hot(6e-3, 3e-3, 1.5e-3);
  std::mt19937 random(7);
  std::lognormal_distribution<double> spread(0.0, 0.1);
  for (LocalIndex q = 0; q < points.size(); ++q) {
    const double r2 = (points.x[q] - hot).squaredNorm() / (2e-3 * 2e-3);
    points.strain_energy[q] = 1.5 * threshold * std::exp(-0.5 * r2) * spread(random);
    points.broken[q] = random() % 10 == 0;  // some already eroded: they take no part
  }
  return model;
}

TEST(Eigenerosion, ErodesExactlyThePointsOfTheDefinition) {
  const Settings settings;
  const double nu = 0.33;
  Model model = hotSpotModel(settings, nu);
  PointStore& points = model.points;
  std::vector<std::uint8_t> expected(points.size(), 0);
  for (LocalIndex a = 0; a < points.size(); ++a) {
    const double gc = model.materials[model.bodies[points.body[a]].material]->fractureEnergy();
    if (points.broken[a] || gc <= 0.0) continue;
    const double eps = settings.erosion_radius * points.spacing(a);
    double mass = 0.0, energy = 0.0;
    for (LocalIndex q = 0; q < points.size(); ++q) {
      if (points.broken[q] || points.body[q] != points.body[a] || (points.x[q] - points.x[a]).norm() > eps) continue;
      mass += points.mass[q];
      energy += points.mass[q] * points.strain_energy[q];
    }
    expected[a] = erosionCalibration(eps, nu) * energy / mass >= gc;
  }
  const std::vector<std::uint8_t> before = points.broken;
  Eigenerosion erosion(settings.erosion_radius);
  const LocalIndex count = erosion.apply(model);

  LocalIndex newly = 0, mismatches = 0;
  for (LocalIndex a = 0; a < points.size(); ++a) {
    if (before[a]) {
      EXPECT_TRUE(points.broken[a]) << "point " << a << " was eroded and must stay so";
      continue;
    }
    newly += expected[a];
    mismatches += points.broken[a] != expected[a];
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(count, newly);
  // The problem must exercise both outcomes, or it proves nothing.
  EXPECT_GT(newly, 10);
  EXPECT_LT(newly, points.size() / 2);
}

// Debris leaves with the mass-weighted mean velocity of its ball, and the difference goes to the
// ball's points that stay in the body: each body's momentum and the total energy are unchanged, and the first point
// released (whose ball nobody has touched yet) moves exactly with the brute-force ball mean.
TEST(Eigenerosion, DebrisTakesTheBallVelocityAndMomentumAndEnergyAreExact) {
  const Settings settings;
  const double nu = 0.33;
  Model model = hotSpotModel(settings, nu);
  PointStore& points = model.points;
  std::mt19937 random(11);
  std::normal_distribution<double> noise(0.0, 500.0);
  for (LocalIndex q = 0; q < points.size(); ++q)
    points.v[q] = Vec3(1000.0 + noise(random), noise(random), noise(random));
  auto momentum = [&](int body) {
    Vec3 sum = Vec3::Zero();
    for (LocalIndex q = 0; q < points.size(); ++q)
      if (points.body[q] == body) sum += points.mass[q] * points.v[q];
    return sum;
  };
  auto energy = [&] {
    double sum = 0.0;
    for (LocalIndex q = 0; q < points.size(); ++q)
      sum += points.mass[q] * (0.5 * points.v[q].squaredNorm() + points.energy[q]);
    return sum;
  };
  const Vec3 before_a = momentum(0), before_b = momentum(1);
  const double energy_before = energy();
  const std::vector<std::uint8_t> eroded_before = points.broken;
  const std::vector<Vec3> v_before = points.v;

  // The points fail free of stress (the model is at rest), so they are released at once.
  Eigenerosion erosion(settings.erosion_radius);
  const LocalIndex failed = erosion.apply(model);
  ASSERT_GT(failed, 10);
  ASSERT_EQ(DebrisRelease(settings.erosion_radius).apply(model), failed);
  EXPECT_LT((momentum(0) - before_a).norm(), 1e-12 * before_a.norm());
  EXPECT_LT((momentum(1) - before_b).norm(), 1e-12 * before_b.norm());
  // The kinetic energy the exchange takes stays in the debris as internal energy.
  EXPECT_NEAR(energy(), energy_before, 1e-12 * energy_before);

  LocalIndex first = 0;
  while (!points.broken[first] || eroded_before[first]) ++first;
  const double eps = settings.erosion_radius * points.spacing(first);
  double mass = 0.0;
  Vec3 sum = Vec3::Zero();
  for (LocalIndex q = 0; q < points.size(); ++q) {
    if (eroded_before[q] || points.body[q] != points.body[first] || (points.x[q] - points.x[first]).norm() > eps)
      continue;
    mass += points.mass[q];
    sum += points.mass[q] * v_before[q];
  }
  EXPECT_LT((points.v[first] - sum / mass).norm(), 1e-9 * (sum / mass).norm());
  // The noise (500 m/s per component) must not survive in the debris that left.
  EXPECT_GT((v_before[first] - points.v[first]).norm(), 10.0);
}

// A whole region erodes in one step, so no ball keeps an intact point: each point then takes the
// mean over its ball's debris too (earlier debris moving at v0, the velocity the region's noisy
// points scatter around), and the noise does not fly off with the debris. Momentum and energy stay
// exact.
TEST(Eigenerosion, TheLastOfAnErodingRegionTakesTheMeanOfItsDebris) {
  const Settings settings;
  Model model = hotSpotModel(settings, 0.33);
  PointStore& points = model.points;
  const Vec3 v0(1000.0, 0.0, 0.0);
  std::mt19937 random(5);
  std::normal_distribution<double> noise(0.0, 500.0);
  for (LocalIndex q = 0; q < points.size(); ++q) {
    points.v[q] = v0;
    if (points.body[q] != 0) continue;
    points.strain_energy[q] = 1e12;  // body a erodes entirely
    if (!points.broken[q]) points.v[q] += Vec3(noise(random), noise(random), noise(random));
  }
  auto total = [&] {
    Vec3 momentum = Vec3::Zero();
    double energy = 0.0;
    for (LocalIndex q = 0; q < points.size(); ++q) {
      momentum += points.mass[q] * points.v[q];
      energy += points.mass[q] * (0.5 * points.v[q].squaredNorm() + points.energy[q]);
    }
    return std::pair{momentum, energy};
  };
  auto scatter = [&](const std::vector<std::uint8_t>& which) {
    double sum = 0.0;
    long n = 0;
    for (LocalIndex q = 0; q < points.size(); ++q)
      if (which[q] && points.body[q] == 0) {
        sum += (points.v[q] - v0).squaredNorm();
        ++n;
      }
    return std::sqrt(sum / static_cast<double>(n));
  };
  std::vector<std::uint8_t> intact(points.size());
  for (LocalIndex q = 0; q < points.size(); ++q) intact[q] = !points.broken[q];
  const auto [momentum_before, energy_before] = total();
  const double scatter_before = scatter(intact);

  Eigenerosion erosion(settings.erosion_radius);
  erosion.apply(model);
  DebrisRelease(settings.erosion_radius).apply(model);
  for (LocalIndex q = 0; q < points.size(); ++q)
    if (points.body[q] == 0) {
      ASSERT_TRUE(points.debris(q));
    }
  const auto [momentum_after, energy_after] = total();
  EXPECT_LT((momentum_after - momentum_before).norm(), 1e-12 * momentum_before.norm());
  EXPECT_NEAR(energy_after, energy_before, 1e-12 * energy_before);
  // Without the debris in the mean every point would keep its own velocity: the same scatter.
  EXPECT_LT(scatter(intact), 0.5 * scatter_before);
}

}  // namespace
}  // namespace kessler::otm
