// OTM seen through the method interface (solver/common/method.hpp): the run loop, the bench and
// the analysis drive it only through these calls, so each must agree with the integrator it wraps.
#include "../blocks.hpp"
#include "core/error.hpp"
#include "solver/common/method.hpp"
#include "solver/otm/integrator.hpp"
#include "solver/otm/otm_method.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <span>

namespace kessler::otm {
namespace {

Model cube() {
  Model model;
  testing::addBlock(model, "cube", geometry::Box{Vec3(0, 0, 0), Vec3(3e-3, 2e-3, 2e-3)}, {3, 2, 2},
                    testing::aluminium(), Vec3(0, 0, -100.0));
  return model;
}

Settings settings() {
  Settings s;
  s.end_time = 1e-5;
  return s;
}

// Bitwise equality of two arrays of trivially copyable values.
template <class T>
bool same(std::span<const T> a, std::span<const T> b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(OtmMethod, StepsExactlyAsItsIntegrator) {
  Model reference_model = cube();
  Integrator reference(reference_model, settings());
  reference.initialise();
  const std::unique_ptr<Method> method = std::make_unique<OtmMethod>(cube(), settings());
  method->initialise();
  EXPECT_STREQ(method->name(), "otm");
  EXPECT_EQ(method->clock().steps, 0);
  EXPECT_EQ(method->clock().dt_next, reference.nextStep());
  for (int s = 0; s < 5; ++s) {
    reference.step();
    method->step();
    method->check(reference.energies().total());
  }
  const Clock clock = method->clock();
  EXPECT_EQ(clock.steps, 5);
  EXPECT_EQ(clock.time, reference.time());
  EXPECT_EQ(clock.dt_last, reference.lastStep());
  EXPECT_EQ(clock.dt_next, reference.nextStep());
  EXPECT_EQ(clock.dt_initial, reference.initialStep());
  EXPECT_EQ(method->endTime(), settings().end_time);
  EXPECT_FALSE(method->finished());
  const Energies a = method->energies(), b = reference.energies();
  EXPECT_EQ(a.kinetic, b.kinetic);
  EXPECT_EQ(a.internal, b.internal);
  EXPECT_EQ(a.momentum, b.momentum);
  EXPECT_TRUE(same(std::span(method->state().points.x), std::span<const Vec3>(reference_model.points.x)));
  EXPECT_TRUE(same(std::span(method->state().points.stress), std::span<const Mat3>(reference_model.points.stress)));
  EXPECT_TRUE(same(method->nodes().x, std::span<const Vec3>(reference_model.nodes.x)));
  EXPECT_EQ(method->state().bodies.size(), 1u);
  EXPECT_EQ(method->timers().totals().size(), reference.timers().totals().size());
}

TEST(OtmMethod, ReportsItsNeighboursAndItsHealth) {
  OtmMethod method(cube(), settings());
  method.initialise();
  method.step();
  const auto sizes = method.sizes();
  ASSERT_EQ(sizes.size(), 1u);
  EXPECT_EQ(sizes[0].first, "mean_neighbours");
  const Model& model = method.model();
  EXPECT_DOUBLE_EQ(sizes[0].second, static_cast<double>(model.connectivity.node.size()) / model.points.owned);
  EXPECT_TRUE(method.notes().empty());  // nothing torn
  // A healthy state passes; energy grown far beyond the first total stops the run.
  EXPECT_NO_THROW(method.check(method.energies().total()));
  EXPECT_THROW(method.check(1e-3 * method.energies().total()), NumericalError);
}

}  // namespace
}  // namespace kessler::otm
