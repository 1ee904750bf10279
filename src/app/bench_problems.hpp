#pragma once
// The problems of `kessler bench` (docs/performance.md): impact decks generated at a requested
// number of material points, so that one problem runs at CI size, at a development size and at
// its full size with the same physics.
#include <string>
#include <vector>

namespace kessler::app {

enum class BenchSize { tiny, small, full };

struct BenchProblem {
  std::string name;
  std::string description;
  double full_points = 0.0;  // target number of material points at full size
  int full_steps = 0;        // default number of steps at full size
  // The modelled volume (after symmetry), m^3, for the mesh size of a target point count.
  double volume = 0.0;
  // The deck (YAML) for a mesh size h, m; `quarter`: the quarter model (symmetry planes x and y).
  std::string (*deck)(double h, bool quarter) = nullptr;
  bool quarter = true;           // the problem's own model is a quarter model
  bool tiny_quarter = true;      // at tiny size (a whole model at a few thousand points would be too coarse)
  double max_mesh_size = 1e300;  // at least two cells through the thinnest body
};

const std::vector<BenchProblem>& benchProblems();
const BenchProblem& benchProblem(const std::string& name);  // throws InputError naming the known ones

BenchSize parseBenchSize(const std::string& text);
const char* sizeName(BenchSize size);

// Target point count and default step count of a problem at a size: tiny is a few thousand
// points and 10 steps (CI), small a tenth of the full size.
double targetPoints(const BenchProblem& problem, BenchSize size);
int defaultSteps(const BenchProblem& problem, BenchSize size);

// Whether the problem runs as a quarter model at that size.
bool quarterModel(const BenchProblem& problem, BenchSize size);

// Mesh size for about `points` material points: Gmsh's tetrahedra of edge h fill a volume with
// about tets_per_h3 / h^3 of them (measured on these decks).
double meshSizeFor(const BenchProblem& problem, BenchSize size, double points);

}  // namespace kessler::app
