// An intact point at the very edge of its nodes' hull (a point of a compressed gas pushed against a
// symmetry plane, say): its covariance is nearly singular and its gradients, -N_a J^-1 d_a, grow as
// the inverse. The neighbourhoods retry it with wider, smoother supports and keep the
// best-conditioned; its gradients are then smaller than its first support's (so the test fails
// without the retry), and still a partition of unity that reproduces a linear field.
#include "../blocks.hpp"
#include "approx/lme.hpp"
#include "core/error.hpp"
#include "solver/otm/neighbourhoods.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace kessler::otm {
namespace {

constexpr double h = 1e-3;

double largestGradient(std::span<const Vec3> dN) {
  double largest = 0.0;
  for (const Vec3& g : dN) largest = std::max(largest, g.norm());
  return largest * h;
}

// The point of the block nearest `target`.
LocalIndex nearestPoint(const PointStore& points, const Vec3& target) {
  LocalIndex p = 0;
  for (LocalIndex q = 1; q < points.owned; ++q)
    if ((points.x[q] - target).norm() < (points.x[p] - target).norm()) p = q;
  return p;
}

TEST(Conditioning, AnIntactPointAtTheEdgeOfItsHullTakesItsBestConditionedSupport) {
  Model model;
  testing::addBlock(model, "block", geometry::Box{Vec3::Zero(), Vec3(6 * h, 6 * h, 4 * h)}, {6, 6, 4});
  // The point nearest the middle of the bottom face, moved to 1e-4 h above it.
  PointStore& points = model.points;
  const LocalIndex p = nearestPoint(points, Vec3(3 * h, 3 * h, 0));
  points.x[p] = Vec3(points.x[p][0], points.x[p][1], 1e-4 * h);

  // Its first support, as the neighbourhoods build it: the nodes within the cut-off at gamma.
  const Settings settings;
  const double spacing = points.spacing(p);
  const double cutoff = lme::cutoffRadius(settings.lme_gamma, spacing, settings.lme_tolerance);
  std::vector<Vec3> d;
  for (LocalIndex a = 0; a < model.nodes.size(); ++a)
    if ((points.x[p] - model.nodes.x[a]).norm() <= cutoff) d.push_back(points.x[p] - model.nodes.x[a]);
  ASSERT_GE(static_cast<int>(d.size()), settings.min_neighbours);
  std::vector<double> N(d.size());
  std::vector<Vec3> dN(d.size());
  Vec3 lambda = Vec3::Zero();
  const lme::Result first =
      lme::shapeFunctions(d, lme::beta(settings.lme_gamma, spacing), spacing, lambda, N, dN, true);
  ASSERT_EQ(first.status, lme::Status::ill_conditioned);
  const double first_gradient = largestGradient(dN);

  Neighbourhoods(settings).update(model);
  const Connectivity& conn = model.connectivity;
  const auto row = static_cast<std::size_t>(conn.offset[p + 1] - conn.offset[p]);
  const std::span<const Vec3> gradients(conn.dN.data() + conn.offset[p], row);
  EXPECT_LT(largestGradient(gradients), 0.5 * first_gradient);
  double sum = 0.0;
  Vec3 position = Vec3::Zero();
  Mat3 identity = Mat3::Zero();
  for (Index k = conn.offset[p]; k < conn.offset[p + 1]; ++k) {
    sum += conn.N[k];
    position += conn.N[k] * model.nodes.x[conn.node[k]];
    identity += model.nodes.x[conn.node[k]] * conn.dN[k].transpose();
  }
  EXPECT_NEAR(sum, 1.0, 1e-9);
  EXPECT_LT((position - points.x[p]).norm(), 1e-9 * h);
  EXPECT_LT((identity - Mat3::Identity()).norm(), 1e-6);
}

// An intact point that no neighbourhood encloses, however wide (here half a spacing below the bottom
// face of its block: outside the hull of all its body's nodes), has torn from its body. It is
// released as debris with a zero row and no stress, and counted, instead of stopping the run.
TEST(Conditioning, AnIntactPointOutsideTheHullOfEveryNeighbourhoodIsTornAndReleased) {
  Model model;
  testing::addBlock(model, "block", geometry::Box{Vec3::Zero(), Vec3(4 * h, 4 * h, 4 * h)}, {4, 4, 4});
  PointStore& points = model.points;
  const LocalIndex p = nearestPoint(points, Vec3(2 * h, 2 * h, 0));
  points.x[p] = Vec3(points.x[p][0], points.x[p][1], -0.5 * h);
  points.stress[p] = -1e8 * Mat3::Identity();

  Neighbourhoods neighbourhoods{Settings{}};
  ASSERT_NO_THROW(neighbourhoods.update(model));
  EXPECT_TRUE(points.debris(p));
  EXPECT_EQ(points.stress[p], Mat3::Zero());
  const Connectivity& conn = model.connectivity;
  for (Index k = conn.offset[p]; k < conn.offset[p + 1]; ++k) EXPECT_EQ(conn.N[k], 0.0);
  EXPECT_EQ(neighbourhoods.tornPoints(), 1);
  EXPECT_DOUBLE_EQ(neighbourhoods.tornMass(), points.mass[p]);
  for (LocalIndex q = 0; q < points.owned; ++q)
    if (q != p) {
      EXPECT_FALSE(points.broken[q]) << "point " << q;
    }
}

// A point whose position is not finite (NaN from a numerical failure upstream) finds no nodes. An
// intact one stops the run with its name and what is wrong; a failed one is released, and the run's
// health check names it. Before, the shape-function solve never returned.
TEST(Conditioning, APointWithANonFinitePositionStopsTheRunInsteadOfHanging) {
  Model model;
  testing::addBlock(model, "block", geometry::Box{Vec3::Zero(), Vec3(4 * h, 4 * h, 4 * h)}, {4, 4, 4});
  PointStore& points = model.points;
  const LocalIndex p = nearestPoint(points, Vec3(2 * h, 2 * h, 2 * h));
  points.x[p][0] = std::nan("");
  Neighbourhoods neighbourhoods{Settings{}};
  try {
    neighbourhoods.update(model);
    ADD_FAILURE() << "no error for an intact point at a NaN position";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("non-finite position"), std::string::npos) << e.what();
  }
  points.fail(p);
  ASSERT_NO_THROW(neighbourhoods.update(model));
  EXPECT_TRUE(points.debris(p));
  EXPECT_EQ(neighbourhoods.tornPoints(), 0);
}

}  // namespace
}  // namespace kessler::otm
