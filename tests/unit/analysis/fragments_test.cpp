// Fragments: connected components of intact material over the initial adjacency.
#include "analysis/fragments.hpp"
#include "analysis/breakup_model.hpp"
#include "analysis/union_find.hpp"
#include "synthetic.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <random>

namespace kessler::analysis {
namespace {

using testing::addBlock;
using testing::addCloud;

constexpr double mm = 1e-3;
constexpr double rho = 2700.0;

// Two structured blocks in one mesh (one body) that share no face.
geometry::TetMesh twoBlocks(const geometry::Box& a, const std::array<int, 3>& ca, const geometry::Box& b,
                            const std::array<int, 3>& cb) {
  geometry::TetMesh mesh = geometry::structuredBoxMesh(a, ca);
  const geometry::TetMesh second = geometry::structuredBoxMesh(b, cb);
  const auto offset = static_cast<LocalIndex>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), second.vertices.begin(), second.vertices.end());
  for (auto tet : second.tets) {
    for (LocalIndex& v : tet) v += offset;
    mesh.tets.push_back(tet);
  }
  return mesh;
}

// Kuhn blocks of cube a: point centres span L - a/2, and each point adds (a^3/6)^(1/3) = 0.55 a,
// so every extent is L + 0.05 a.
constexpr double a = 0.5 * mm;
constexpr double extent_bias = 0.0503 * a;

TEST(UnionFind, JoinsAndCountsSets) {
  UnionFind sets(6);
  EXPECT_TRUE(sets.unite(0, 1));
  EXPECT_TRUE(sets.unite(2, 3));
  EXPECT_TRUE(sets.unite(1, 3));
  EXPECT_FALSE(sets.unite(0, 2));
  EXPECT_EQ(sets.find(0), sets.find(3));
  EXPECT_NE(sets.find(0), sets.find(4));
  EXPECT_EQ(sets.setSize(2), 4);
  EXPECT_EQ(sets.setSize(5), 1);
}

TEST(Fragments, TwoSeparatedBlocksInOneBody) {
  otm::Model model;
  const geometry::Box big{Vec3(0, 0, 0), Vec3(6 * mm, 3 * mm, 1.5 * mm)};
  const geometry::Box small{Vec3(20 * mm, 0, 0), Vec3(24 * mm, 2 * mm, 2 * mm)};
  const auto d = geometry::discretise(twoBlocks(big, {12, 6, 3}, small, {8, 4, 4}));
  otm::addBody(model, "target", testing::aluminium(), d, Vec3(0, 0, -100.0));
  const FragmentSet set = findFragments(model, referenceLinkLengths(model), {});

  ASSERT_EQ(set.fragments.size(), 2u);
  EXPECT_EQ(set.count(), 2);
  const Fragment& first = set.fragments[0];
  const Fragment& second = set.fragments[1];
  EXPECT_NEAR(first.mass, rho * 6 * 3 * 1.5 * 1e-9, 1e-12 * first.mass);
  EXPECT_NEAR(second.mass, rho * 4 * 2 * 2 * 1e-9, 1e-12 * second.mass);
  EXPECT_EQ(first.points, 6 * 12 * 6 * 3);
  EXPECT_EQ(second.points, 6 * 8 * 4 * 4);
  EXPECT_NEAR(first.extents[0], 6 * mm + extent_bias, 0.01 * a);
  EXPECT_NEAR(first.extents[1], 3 * mm + extent_bias, 0.01 * a);
  EXPECT_NEAR(first.extents[2], 1.5 * mm + extent_bias, 0.01 * a);
  EXPECT_NEAR(first.lc, 3.5 * mm, 0.1 * a);
  EXPECT_NEAR(second.lc, 8.0 / 3.0 * mm, 0.1 * a);
  EXPECT_NEAR(std::abs(first.axis.dot(Vec3::UnitX())), 1.0, 1e-6);
  EXPECT_TRUE(first.centre.isApprox(Vec3(3 * mm, 1.5 * mm, 0.75 * mm), 1e-9));
  EXPECT_TRUE(second.velocity.isApprox(Vec3(0, 0, -100.0), 1e-12));
  EXPECT_NEAR(second.speed, 100.0, 1e-10);
  EXPECT_DOUBLE_EQ(first.area, nasaFragmentArea(first.lc));
  for (LocalIndex p = 0; p < model.points.size(); ++p) EXPECT_EQ(set.label[p], model.points.x[p][0] < 10 * mm ? 0 : 1);
}

// Five points 1 mm apart in a row, each linked to the next; returns their body.
int addChainOfFive(otm::Model& model) {
  std::vector<Vec3> chain;
  for (int i = 0; i < 5; ++i) chain.emplace_back(i * mm, 0, 0);
  const int body = addCloud(model, "chain", chain, 1e-9);
  for (LocalIndex i = 0; i < 4; ++i) model.adjacency.push_back({i, i + 1});
  return body;
}

TEST(Fragments, ChainBrokenByAnErodedPoint) {
  otm::Model model;
  const int body = addChainOfFive(model);
  model.points.broken[2] = 1;
  const FragmentSet set = findFragments(model, referenceLinkLengths(model), {});
  ASSERT_EQ(set.fragments.size(), 2u);
  const double m = rho * 1e-9;
  EXPECT_DOUBLE_EQ(set.fragments[0].mass, 2 * m);
  EXPECT_DOUBLE_EQ(set.fragments[1].mass, 2 * m);
  EXPECT_EQ(set.fragments[0].first_point, 0);  // equal masses: the first point decides
  EXPECT_EQ(set.label, (std::vector<LocalIndex>{0, 0, -1, 1, 1}));
  EXPECT_DOUBLE_EQ(set.eroded_mass[body], m);
  EXPECT_DOUBLE_EQ(set.body_mass[body], 5 * m);
  EXPECT_EQ(set.broken_links, 2);
}

// A loose point (an SPH element failed by its distortion, its material intact) cuts the chain as an
// eroded one does, and its mass is free mass.
TEST(Fragments, ChainCutByALoosePoint) {
  otm::Model model;
  const int body = addChainOfFive(model);
  model.points.loose[1] = 1;
  const FragmentSet set = findFragments(model, referenceLinkLengths(model), {});
  ASSERT_EQ(set.fragments.size(), 2u);
  EXPECT_EQ(set.label, (std::vector<LocalIndex>{1, -1, 0, 0, 0}));
  EXPECT_DOUBLE_EQ(set.eroded_mass[body], rho * 1e-9);
  EXPECT_EQ(set.broken_links, 2);
}

TEST(Fragments, SeparationWithoutErosionSplitsAndStretchDoesNot) {
  otm::Model model;
  addBlock(model, "plate", {Vec3(0, 0, 0), Vec3(6 * mm, 3 * mm, 1.5 * mm)}, {12, 6, 3});
  const std::vector<double> lengths = referenceLinkLengths(model);
  EXPECT_EQ(findFragments(model, lengths, {}).fragments.size(), 1u);

  otm::Model stretched = model;  // 1.5 times longer links everywhere: still one piece
  for (Vec3& x : stretched.points.x) x *= 1.5;
  EXPECT_EQ(findFragments(stretched, lengths, {}).fragments.size(), 1u);

  otm::Model spalled = model;  // a layer moved 1 mm off, no point eroded
  for (Vec3& x : spalled.points.x)
    if (x[2] > 1.0 * mm) x[2] += 1.0 * mm;
  const FragmentSet set = findFragments(spalled, lengths, {});
  ASSERT_EQ(set.fragments.size(), 2u);
  EXPECT_NEAR(set.fragments[1].mass, rho * 6 * 3 * 0.5 * 1e-9, 1e-9 * set.fragments[1].mass);
  // Without recorded lengths the estimate from the spacing gives the same split.
  EXPECT_EQ(findFragments(spalled, {}, {}).fragments.size(), 2u);
  EXPECT_EQ(findFragments(model, {}, {}).fragments.size(), 1u);
}

TEST(Fragments, HalfModelJoinsHalvesAndCountsMirrorCopies) {
  otm::Model model;
  // Half of a 4 x 2 x 1 mm block cut by the plane x = 0, and a block clear of it.
  addBlock(model, "cut", {Vec3(0, -1 * mm, 0), Vec3(2 * mm, 1 * mm, 1 * mm)}, {4, 4, 2});
  addBlock(model, "clear", {Vec3(5 * mm, 0, 0), Vec3(6 * mm, 1 * mm, 1 * mm)}, {2, 2, 2});
  FragmentOptions options;
  options.symmetry_axes = {0};
  const FragmentSet set = findFragments(model, referenceLinkLengths(model), options);
  ASSERT_EQ(set.fragments.size(), 2u);
  EXPECT_EQ(set.count(), 3);
  const Fragment& cut = set.fragments[0];
  EXPECT_EQ(cut.copies, 1);
  EXPECT_NEAR(cut.mass, rho * 4 * 2 * 1 * 1e-9, 1e-9 * cut.mass);
  EXPECT_NEAR(cut.extents[0], 4 * mm + extent_bias, 0.01 * a);
  EXPECT_NEAR(cut.centre[0], 0.0, 1e-12);
  EXPECT_EQ(set.fragments[1].copies, 2);
  EXPECT_NEAR(set.body_mass[0], rho * 8e-9, 1e-9 * set.body_mass[0]);
}

TEST(Fragments, SameResultForAnyThreadCount) {
  otm::Model model;
  addBlock(model, "plate", {Vec3(0, 0, 0), Vec3(10 * mm, 10 * mm, 2 * mm)}, {20, 20, 4});
  std::mt19937 random(7);
  for (LocalIndex p = 0; p < model.points.size(); ++p) model.points.broken[p] = random() % 3 == 0;
  const std::vector<double> lengths = referenceLinkLengths(model);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const FragmentSet one = findFragments(model, lengths, {});
  omp_set_num_threads(4);
  const FragmentSet four = findFragments(model, lengths, {});
  omp_set_num_threads(threads);
  ASSERT_GT(one.fragments.size(), 10u);
  ASSERT_EQ(one.fragments.size(), four.fragments.size());
  EXPECT_EQ(one.label, four.label);
  for (std::size_t f = 0; f < one.fragments.size(); ++f) {
    EXPECT_EQ(one.fragments[f].mass, four.fragments[f].mass);
    EXPECT_EQ(one.fragments[f].lc, four.fragments[f].lc);
    EXPECT_EQ(one.fragments[f].centre, four.fragments[f].centre);
  }
}

TEST(Fragments, CumulativeDistributionCountsCopies) {
  FragmentSet set;
  set.fragments.resize(3);
  set.fragments[0].lc = 1e-3;
  set.fragments[1].lc = 3e-3;
  set.fragments[1].copies = 2;
  set.fragments[2].lc = 2e-3;
  const auto n = cumulativeDistribution(set);
  ASSERT_EQ(n.size(), 3u);
  EXPECT_EQ(n[0].lc, 3e-3);
  EXPECT_EQ(n[0].count, 2);
  EXPECT_EQ(n[1].count, 3);
  EXPECT_EQ(n[2].count, 4);
  EXPECT_EQ(set.count(), 4);
}

TEST(Fragments, ModelAdjacencyIsOffsetPerBody) {
  otm::Model model;
  addBlock(model, "a", {Vec3(0, 0, 0), Vec3(1 * mm, 1 * mm, 1 * mm)}, {2, 2, 2});
  const std::size_t first_links = model.adjacency.size();
  addBlock(model, "b", {Vec3(5 * mm, 0, 0), Vec3(6 * mm, 1 * mm, 1 * mm)}, {2, 2, 2});
  ASSERT_EQ(model.adjacency.size(), 2 * first_links);
  const LocalIndex begin = bodyRanges(model.points.body, model.points.size(), model.bodies.size())[1].begin;
  for (std::size_t k = first_links; k < model.adjacency.size(); ++k) {
    EXPECT_GE(model.adjacency[k][0], begin);
    EXPECT_EQ(model.adjacency[k][0] - begin, model.adjacency[k - first_links][0]);
  }
  EXPECT_EQ(findFragments(model, referenceLinkLengths(model), {}).fragments.size(), 2u);
}

}  // namespace
}  // namespace kessler::analysis
