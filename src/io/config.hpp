#pragma once
// The typed configuration of a run, parsed from a YAML deck before any physics is built.
// Nothing reads the deck after parsing: the solver receives these structures.
#include "core/types.hpp"
#include "geometry/mesh.hpp"
#include "material/impact_material.hpp"
#include "material/neo_hookean.hpp"
#include "solver/otm/settings.hpp"

#include <string>
#include <vector>

namespace kessler::io {

struct MaterialConfig {
  std::string name;
  // "neo-hookean": elastic, `neo_hookean` holds its parameters. "impact": equation of state,
  // strength, heat, viscosity and damage, `impact` holds them (from the library and/or the deck).
  std::string model = "neo-hookean";
  std::string library;               // library entry the material started from, if any
  NeoHookeanParameters neo_hookean;
  ImpactMaterialParameters impact;
};

struct BodyConfig {
  std::string name;
  int material = 0;                      // index into RunConfig::materials
  geometry::MeshRequest mesh;            // shape, mesh size, refinement, symmetry planes
  Vec3 velocity = Vec3::Zero();          // initial velocity, m/s
  geometry::FixedNodes fixed = geometry::FixedNodes::none;
};

struct OutputConfig {
  double every = 0.0;        // simulated time between field outputs, s (0: only first and last)
  std::string dir = "out";
};

// Checkpoints (DIR/checkpoint.h5, docs/running.md): written every `every` of simulated time and
// every `wall_interval` of wall-clock time, whichever comes first; 0 switches either off.
struct CheckpointConfig {
  double every = 0.0;            // s of simulated time (deck default: end_time / 10)
  double wall_interval = 600.0;  // s of wall-clock time
};

struct RunConfig {
  std::string title;
  std::string deck_path;                 // file the deck came from
  std::vector<MaterialConfig> materials;
  std::vector<BodyConfig> bodies;
  std::vector<int> symmetry_axes;        // 0 = x, 1 = y, 2 = z: planes through the origin
  otm::Settings solver;
  OutputConfig output;
  CheckpointConfig checkpoint;
};

}  // namespace kessler::io
