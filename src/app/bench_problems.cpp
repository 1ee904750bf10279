#include "app/bench_problems.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kessler::app {

namespace {

// Gmsh's Delaunay tetrahedra of target edge h: about c / h^3 per unit volume, c = 6.4 at 2,250
// tetrahedra falling to 4.7 at 74,000 (fewer boundary layers, relatively): c = 6.4 (N / 2253)^-0.0886,
// fitted on hvi-100k at tiny and full size.
double tetsPerH3(double tets) {
  return 6.4 * std::pow(tets / 2253.0, -0.0886);
}

// hvi-*: an Al 6061-T6 sphere (radius 3 mm) onto a 2 mm Al 6061-T6 plate at 6.18 km/s, quarter
// model. Full physics: Mie-Gruneisen EOS, power-law strength with heating and melting, Johnson-Cook
// damage with erosion of failed points, seizing contact. The sphere starts 0.1 h above the plate.
constexpr double hvi_radius = 3e-3, hvi_half_width = 12e-3, hvi_thickness = 2e-3;

std::string hviDeck(double h, bool /*quarter: always*/) {
  return fmt::format(R"(title: bench hvi, Al sphere onto an Al plate at 6.18 km/s (quarter model)
materials:
  al: {{ library: Al6061-T6, failure: {{ model: johnson-cook }} }}
bodies:
  - name: projectile
    material: al
    shape: {{ sphere: {{ center: [0, 0, {:.9g}], radius: {:.9g} }} }}
    velocity: [0, 0, -6.18 km/s]
    mesh_size: {:.9g}
  - name: plate
    material: al
    shape: {{ box: {{ min: [{:.9g}, {:.9g}, {:.9g}], max: [{:.9g}, {:.9g}, 0] }} }}
    mesh_size: {:.9g}
    fixed: lateral-faces
symmetry: [x, y]
solver: {{ end_time: 20 us, cfl: 0.3 }}
)",
                     hvi_radius + 0.1 * h, hvi_radius, h, -hvi_half_width, -hvi_half_width, -hvi_thickness,
                     hvi_half_width, hvi_half_width, h);
}

// pysph-impact3d: PySPH's 3D solid-impact example (examples/solid_mech/impact3d.py): a steel
// sphere of radius 5 mm onto a 2 x 40 x 40 mm aluminium plate at 3.1 km/s, the whole model (no
// symmetry, as PySPH runs it; its 37k particles are a 0.5 mm lattice; the tiny CI size is a
// quarter model). Strength and EOS as in the library; JC damage on the plate.
constexpr double pysph_radius = 5e-3, pysph_half_width = 20e-3, pysph_thickness = 2e-3;

std::string pysphDeck(double h, bool quarter) {
  return fmt::format(R"(title: bench pysph-impact3d, steel sphere onto an Al plate at 3.1 km/s
materials:
  steel: {{ library: 4340-steel }}
  al: {{ library: Al6061-T6, failure: {{ model: johnson-cook }} }}
bodies:
  - name: projectile
    material: steel
    shape: {{ sphere: {{ center: [0, 0, {:.9g}], radius: {:.9g} }} }}
    velocity: [0, 0, -3.1 km/s]
    mesh_size: {:.9g}
  - name: plate
    material: al
    shape: {{ box: {{ min: [{:.9g}, {:.9g}, {:.9g}], max: [{:.9g}, {:.9g}, 0] }} }}
    mesh_size: {:.9g}
    fixed: lateral-faces
{}solver: {{ end_time: 20 us, cfl: 0.3 }}
)",
                     pysph_radius + 0.1 * h, pysph_radius, h, -pysph_half_width, -pysph_half_width, -pysph_thickness,
                     pysph_half_width, pysph_half_width, h, quarter ? "symmetry: [x, y]\n" : "");
}

constexpr double pi = std::numbers::pi;
const double hvi_volume =
    pi * hvi_radius * hvi_radius * hvi_radius / 3.0 + hvi_half_width * hvi_half_width * hvi_thickness;
const double pysph_volume = 4.0 / 3.0 * pi * pysph_radius * pysph_radius * pysph_radius +
                            4.0 * pysph_half_width * pysph_half_width * pysph_thickness;

}  // namespace

const std::vector<BenchProblem>& benchProblems() {
  static const std::vector<BenchProblem> problems = {
      {"hvi-100k", "Al sphere onto an Al plate at 6.18 km/s, ~100k material points, full physics", 1e5, 30, hvi_volume,
       hviDeck, true, true, hvi_thickness / 2},
      {"hvi-1m", "the same impact at ~1M material points", 1e6, 10, hvi_volume, hviDeck, true, true, hvi_thickness / 2},
      {"pysph-impact3d", "PySPH's 3D impact: 5 mm steel sphere onto a 2 x 40 x 40 mm Al plate at 3.1 km/s, ~37k points",
       3.7e4, 30, pysph_volume, pysphDeck, false, true, pysph_thickness / 2},
  };
  return problems;
}

const BenchProblem& benchProblem(const std::string& name) {
  for (const BenchProblem& p : benchProblems())
    if (p.name == name) return p;
  std::string known;
  for (const BenchProblem& p : benchProblems()) known += (known.empty() ? "" : ", ") + p.name;
  throw InputError(fmt::format("unknown benchmark problem '{}' (known: {})", name, known));
}

BenchSize parseBenchSize(const std::string& text) {
  if (text == "tiny") return BenchSize::tiny;
  if (text == "small") return BenchSize::small;
  if (text == "full") return BenchSize::full;
  throw InputError(fmt::format("--size {}: must be tiny, small or full", text));
}

const char* sizeName(BenchSize size) {
  switch (size) {
    case BenchSize::tiny:
      return "tiny";
    case BenchSize::small:
      return "small";
    case BenchSize::full:
      return "full";
  }
  return "full";
}

double targetPoints(const BenchProblem& problem, BenchSize size) {
  switch (size) {
    case BenchSize::tiny:
      return 3000.0;
    case BenchSize::small:
      return std::max(3000.0, problem.full_points / 10.0);
    case BenchSize::full:
      return problem.full_points;
  }
  return problem.full_points;
}

int defaultSteps(const BenchProblem& problem, BenchSize size) {
  return size == BenchSize::tiny ? 10 : problem.full_steps;
}

bool quarterModel(const BenchProblem& problem, BenchSize size) {
  return size == BenchSize::tiny ? problem.tiny_quarter : problem.quarter;
}

double meshSizeFor(const BenchProblem& problem, BenchSize size, double points) {
  // The volume is the problem's own model's; a quarter model of a whole one has a quarter of it.
  const double volume = problem.volume * (quarterModel(problem, size) && !problem.quarter ? 0.25 : 1.0);
  return std::min(std::cbrt(tetsPerH3(points) * volume / points), problem.max_mesh_size);
}

}  // namespace kessler::app
