#pragma once
// Everything the analysis layer measures after a run, in one record: fragments and the NASA
// breakup model, holes, debris clouds, back-splash, rear-wall damage, and the engineering
// ballistic limit beside the simulated outcome. The run calls analyse() once at the end, puts
// toJson() into summary.json, prints formatReport() and writes the fragment files.
#include "analysis/ballistic_limit.hpp"
#include "analysis/breakup_model.hpp"
#include "analysis/fragments.hpp"
#include "analysis/measurements.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace kessler::analysis {

// Rear-wall data the ballistic-limit equations need and the material laws do not expose. The
// defaults are Al 6061-T6: 40 ksi yield (the normalisation of Christiansen's fit), Brinell
// hardness 95, bar sound speed sqrt(E/rho) = sqrt(68.9 GPa / 2700 kg/m^3).
struct WallProperties {
  double yield_stress = 275.8e6;  // Pa
  double brinell_hardness = 95.0;
  double sound_speed = 5052.0;  // m/s
  bool defaults = true;         // these are the Al 6061-T6 values, not the deck's own
};

struct ShieldComparison {
  std::string model;      // christiansen_whipple | cour_palais_single_wall
  Projectile projectile;  // equivalent-sphere diameter of the projectile's mass
  WallProperties wall;
  double spacing = 0.0;            // m, bumper rear face to rear-wall front face (Whipple)
  double critical_diameter = 0.0;  // m: a larger projectile perforates the (rear) wall
  std::string regime;              // Christiansen regime, or the Cour-Palais damage class
  double penetration_depth = 0.0;  // m (Cour-Palais)
  bool predicts_perforation = false;
  std::string simulated;  // the rear-wall classification of the run
  // Why the equation may not describe this wall: its properties are Al 6061-T6's defaults but its
  // material is not aluminium-like (density more than 10% from 2700 kg/m^3). Empty otherwise.
  std::string caveat;
};

struct Report {
  // False when nothing broke: every body is still one piece and no point failed or came loose.
  // Then there is no hole, debris cloud, back-splash or ballistic-limit verdict to report, and
  // holes, clouds, ejecta and shield stay empty.
  bool debris = true;
  std::vector<std::string> body_names;
  std::vector<std::string> material_names;
  ImpactGeometry geometry;
  FragmentSet fragments;
  std::optional<BreakupEvent> event;
  std::optional<BreakupPrediction> breakup;
  std::vector<HoleMeasurement> holes;
  std::vector<CloudMeasurement> clouds;
  EjectaMeasurement ejecta;
  std::optional<RearWallDamage> rear_wall;
  std::optional<ShieldComparison> shield;
};

// `reference_lengths`: referenceLinkLengths(model) taken before the first step (may be empty,
// see findFragments). Throws kessler::InputError for an inconsistent geometry.
Report analyse(const ParticleState& model, const ImpactGeometry& geometry, const std::vector<double>& reference_lengths,
               const WallProperties& wall = {});

// The "analysis" object of summary.json (SI, units in the key names; see docs/analysis.md).
nlohmann::json toJson(const Report& report);

// A few lines for the terminal, in mm, g, km/s and degrees.
std::string formatReport(const Report& report);

// Writes dir/fragments.csv (one row per fragment, largest mass first) and
// dir/fragments_cumulative.csv (N(>=Lc) with the NASA model's count) and dir/fragment_points.csv
// (each point's id and fragment rank, 0 for broken), each atomically.
void writeFragmentFiles(const std::filesystem::path& dir, const Report& report);

}  // namespace kessler::analysis
