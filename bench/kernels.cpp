// Google Benchmark kernels of the OTM step (docs/performance.md): LME shape functions at one
// point, the cell-list neighbour search, the nodal assembly gather and the constitutive update
// of a block of points. The model is a structured Kuhn-triangulated aluminium box (6 points per
// cube) with the library's Al6061-T6, initialised as a run is, so each kernel sees the data
// layout and neighbour counts of a real step.
#include "approx/lme.hpp"
#include "geometry/structured_mesh.hpp"
#include "material/impact_material.hpp"
#include "material/library.hpp"
#include "search/cell_list.hpp"
#include "solver/otm/integrator.hpp"
#include "solver/otm/integrator_assembly.hpp"
#include "solver/otm/setup.hpp"

#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <vector>

namespace {

using namespace kessler;

constexpr double cell = 1e-3;

struct Fixture {
  otm::Model model;
  otm::Settings settings;
  std::unique_ptr<otm::Integrator> integrator;

  explicit Fixture(int cubes) {
    const library::Entry& al = library::find("Al6061-T6");
    auto material = std::make_shared<ImpactMaterial>(al.name, al.parameters);
    otm::addBody(model, "block", material,
                 geometry::discretise(
                     geometry::structuredBoxMesh({Vec3::Zero(), Vec3::Constant(cubes * cell)}, {cubes, cubes, cubes})),
                 Vec3(0, 0, -100.0));
    settings.end_time = 1.0;
    integrator = std::make_unique<otm::Integrator>(model, settings);
    integrator->initialise();
  }
};

Fixture& fixture(int cubes) {
  static std::map<int, std::unique_ptr<Fixture>> fixtures;
  auto& f = fixtures[cubes];
  if (!f) f = std::make_unique<Fixture>(cubes);
  return *f;
}

// LME at one interior point, warm-started from its converged lambda (as in a step) or cold.
void lmeOnePoint(benchmark::State& state, bool warm) {
  Fixture& f = fixture(12);
  const PointStore& points = f.model.points;
  const otm::Connectivity& conn = f.model.connectivity;
  const LocalIndex p = points.owned / 2;
  std::vector<Vec3> d;
  for (Index e = conn.offset[p]; e < conn.offset[p + 1]; ++e) d.push_back(points.x[p] - f.model.nodes.x[conn.node[e]]);
  std::vector<double> N(d.size());
  std::vector<Vec3> dN(d.size());
  const double h = points.spacing(p);
  const double beta = lme::beta(f.settings.lme_gamma, h);
  for (auto _ : state) {
    Vec3 lambda = warm ? f.model.lme_lambda[p] : Vec3::Zero();
    const lme::Result r = lme::shapeFunctions(d, beta, h, lambda, N, dN);
    benchmark::DoNotOptimize(r);
    benchmark::DoNotOptimize(dN.data());
  }
  state.counters["neighbours"] = static_cast<double>(d.size());
  state.SetItemsProcessed(state.iterations());
}
void BM_LmeOnePointWarm(benchmark::State& state) {
  lmeOnePoint(state, true);
}
void BM_LmeOnePointCold(benchmark::State& state) {
  lmeOnePoint(state, false);
}
BENCHMARK(BM_LmeOnePointWarm);
BENCHMARK(BM_LmeOnePointCold);

// Cell-list build over the nodes and the fixed-radius query of every point (no LME).
void BM_NeighbourSearch(benchmark::State& state) {
  Fixture& f = fixture(static_cast<int>(state.range(0)));
  const PointStore& points = f.model.points;
  const double radius = lme::cutoffRadius(f.settings.lme_gamma, points.spacing0[0], f.settings.lme_tolerance);
  CellList cells;
  long found = 0;
  for (auto _ : state) {
    cells.build(f.model.nodes.x, f.model.nodes.owned, radius);
    found = 0;
    for (LocalIndex p = 0; p < points.owned; ++p)
      cells.forEachWithin(points.x[p], radius, [&](LocalIndex, double) { ++found; });
    benchmark::DoNotOptimize(found);
  }
  state.counters["neighbours"] = static_cast<double>(found) / points.owned;
  state.SetItemsProcessed(state.iterations() * points.owned);
}
BENCHMARK(BM_NeighbourSearch)->Arg(12)->Arg(24)->Unit(benchmark::kMillisecond);

// The nodal gather of mass, momentum and force (Integrator's assembly phase), per point.
void BM_AssemblyGather(benchmark::State& state) {
  Fixture& f = fixture(static_cast<int>(state.range(0)));
  std::vector<otm::PointLoad> loads;
  for (auto _ : state) {
    otm::assembleNodes(f.model.connectivity, f.model.points, f.model.nodes, loads);
    benchmark::DoNotOptimize(f.model.nodes.force.data());
  }
  state.counters["entries_per_point"] = static_cast<double>(f.model.connectivity.node.size()) / f.model.points.owned;
  state.SetItemsProcessed(state.iterations() * f.model.points.owned);
}
BENCHMARK(BM_AssemblyGather)->Arg(12)->Arg(24)->Unit(benchmark::kMillisecond);

// Constitutive update (EOS, power-law strength with radial return, heating) of all points,
// alternately compressed and released by 0.1% so that the state stays bounded and plastic.
void BM_ConstitutiveBlock(benchmark::State& state) {
  Fixture& f = fixture(12);
  PointStore& points = f.model.points;
  const Material& material = *f.model.materials.front();
  double sign = 1.0;
  for (auto _ : state) {
    for (LocalIndex p = 0; p < points.owned; ++p) {
      points.dF[p] = Mat3::Identity();
      points.dF[p](2, 2) -= sign * 2e-3;
      points.dF[p](0, 1) += sign * 1e-3;
      points.F[p] = points.dF[p] * points.F[p];
    }
    sign = -sign;
    material.update(points, 0, points.owned, 1e-9);
    benchmark::DoNotOptimize(points.stress.data());
  }
  state.SetItemsProcessed(state.iterations() * points.owned);
}
BENCHMARK(BM_ConstitutiveBlock)->Unit(benchmark::kMillisecond);

// The whole neighbourhood update of a step: search, contact policy, LME, transpose.
void BM_NeighbourhoodUpdate(benchmark::State& state) {
  Fixture& f = fixture(static_cast<int>(state.range(0)));
  otm::Neighbourhoods neighbourhoods(f.settings);
  for (auto _ : state) neighbourhoods.update(f.model);
  state.SetItemsProcessed(state.iterations() * f.model.points.owned);
}
BENCHMARK(BM_NeighbourhoodUpdate)->Arg(12)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
