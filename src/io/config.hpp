#pragma once
// The typed configuration of a run, parsed from a YAML deck before any physics is built.
// Nothing reads the deck after parsing: the solver receives these structures.
#include "core/types.hpp"
#include "geometry/mesh.hpp"
#include "material/impact_material.hpp"
#include "material/neo_hookean.hpp"
#include "solver/common/settings.hpp"

#include <string>
#include <vector>

namespace kessler::io {

struct MaterialConfig {
  std::string name;
  // "neo-hookean": elastic, `neo_hookean` holds its parameters. "impact": equation of state,
  // strength, heat, viscosity and damage, `impact` holds them (from the library and/or the deck).
  std::string model = "neo-hookean";
  std::string library;  // library entry the material started from, if any
  NeoHookeanParameters neo_hookean;
  ImpactMaterialParameters impact;
};

struct BodyConfig {
  std::string name;
  int material = 0;              // index into RunConfig::materials
  geometry::MeshRequest mesh;    // shape, mesh size, refinement, symmetry planes
  Vec3 velocity = Vec3::Zero();  // initial velocity, m/s
  geometry::FixedNodes fixed = geometry::FixedNodes::none;
};

struct OutputConfig {
  double every = 0.0;  // simulated time between field outputs, s (0: only first and last)
  std::string dir = "out";
};

// Checkpoints (DIR/checkpoint.h5, docs/running.md): written every `every` of simulated time and
// every `wall_interval` of wall-clock time, whichever comes first; 0 switches either off.
struct CheckpointConfig {
  double every = 0.0;            // s of simulated time (deck default: end_time / 10)
  double wall_interval = 600.0;  // s of wall-clock time
};

// The end-of-run impact analysis (docs/analysis.md): which bodies are the projectile and the
// plates, and the options of the measurements. Without a deck `analysis:` block every field is
// inferred from the bodies (parseDeck fills them in, so the resolved deck shows what was used).
struct AnalysisConfig {
  bool enabled = true;                   // false: no analysis (also when the deck has no moving body)
  std::vector<int> projectiles;          // body indices
  std::vector<int> plates;               // box bodies in the order the shot line meets them; last: rear wall
  Vec3 shot_direction = -Vec3::UnitZ();  // unit, the projectile's direction of travel
  double impact_speed = 0.0;             // m/s
  int cloud_reference = 0;               // index into plates: the debris cloud is measured from its rear face
  double link_stretch = 2.5;             // fragments: a link breaks beyond this factor of its initial length
  bool plots = true;                     // run tools/plots/*.py at the end of the run
  // The rear wall's properties for the ballistic-limit equations (defaults: Al 6061-T6).
  double wall_yield_stress = 275.8e6;  // Pa
  double wall_brinell_hardness = 95.0;
  double wall_sound_speed = 5052.0;  // m/s
  bool wall_given = false;           // the deck gave analysis.rear_wall (else the defaults above)
};

struct RunConfig {
  std::string title;
  std::string deck_path;  // file the deck came from
  std::vector<MaterialConfig> materials;
  std::vector<BodyConfig> bodies;
  std::vector<int> symmetry_axes;  // 0 = x, 1 = y, 2 = z: planes through the origin
  std::string method = "otm";      // solver.method
  SolverSettings solver;           // the keys of `solver` every method reads
  OtmOptions otm;                  // `solver.otm`
  OutputConfig output;
  CheckpointConfig checkpoint;
  AnalysisConfig analysis;
};

}  // namespace kessler::io
