#include "app/impact_analysis.hpp"

#include "analysis/report.hpp"
#include "app/scripts.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/timer.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace kessler::app {

namespace {

namespace fs = std::filesystem;

constexpr const char* system_python = "/usr/bin/python3";

// Where the projectile starts: the centre of its shape's bounding box.
Vec3 startOf(const io::BodyConfig& body) {
  const geometry::BoundingBox box = geometry::bounds(body.mesh.shape);
  return box.empty() ? Vec3::Zero() : Vec3(0.5 * (box.min + box.max));
}

analysis::ImpactGeometry impactGeometry(const io::RunConfig& config, const ParticleState& model) {
  const io::AnalysisConfig& a = config.analysis;
  KESSLER_VERIFY(model.bodies.size() == config.bodies.size(), "the model has {} bodies, the deck {}",
                 model.bodies.size(), config.bodies.size());
  for (std::size_t b = 0; b < config.bodies.size(); ++b)
    KESSLER_VERIFY(model.bodies[b].name == config.bodies[b].name, "model body {} is '{}', the deck's '{}'", b,
                   model.bodies[b].name, config.bodies[b].name);
  analysis::ImpactGeometry g;
  g.shot_direction = a.shot_direction;
  g.impact_speed = a.impact_speed;
  g.projectile_bodies = a.projectiles;
  for (const int b : a.plates) {
    const auto& box = std::get<geometry::Box>(config.bodies[static_cast<std::size_t>(b)].mesh.shape);
    g.plates.push_back(analysis::plateFromBox(b, box, a.shot_direction));
  }
  // Where the shot meets the first plate; a collision without plates has no such point.
  if (!g.plates.empty()) {
    const analysis::PlateSpec& first = g.plates.front();
    g.impact_point = analysis::shotLineHit(startOf(config.bodies[static_cast<std::size_t>(a.projectiles.front())]),
                                           a.shot_direction, first.normal, first.frontFace());
  }
  g.cloud_reference = a.cloud_reference;
  g.symmetry_axes = config.symmetry_axes;
  g.link_stretch = a.link_stretch;
  return g;
}

}  // namespace

nlohmann::json analyseImpact(const io::RunConfig& config, const ParticleState& model, const fs::path& dir,
                             const std::string& state) {
  if (!config.analysis.enabled) return nullptr;
  try {
    Stopwatch watch;
    const analysis::ImpactGeometry geometry = impactGeometry(config, model);
    const analysis::WallProperties wall{.yield_stress = config.analysis.wall_yield_stress,
                                        .brinell_hardness = config.analysis.wall_brinell_hardness,
                                        .sound_speed = config.analysis.wall_sound_speed,
                                        .defaults = !config.analysis.wall_given};
    const analysis::Report report = analysis::analyse(model, geometry, model.adjacency_length0, wall);
    analysis::writeFragmentFiles(dir, report);
    nlohmann::json j = analysis::toJson(report);
    j["state"] = state;
    j["seconds"] = watch.seconds();
    log::info("analysis of the {} (docs/analysis.md):\n{}", state == "final" ? "final state" : "state " + state,
              analysis::formatReport(report));
    return j;
  } catch (const std::exception& e) {
    warn(fmt::format("the impact analysis failed: {}", e.what()));
    return {{"state", state}, {"error", e.what()}};
  }
}

void drawPlots(const fs::path& dir, std::initializer_list<const char*> scripts_to_run) {
  const fs::path scripts = plotsDir();
  std::error_code error;
  if (!fs::exists(system_python, error)) {
    warn(fmt::format("no pictures: {} not found", system_python));
    return;
  }
  const std::string check = fmt::format("{} -c 'import matplotlib, numpy, h5py' >/dev/null 2>&1", system_python);
  if (runOutsideMpi(check) != 0) {
    warn(
        "no pictures: matplotlib, numpy or h5py is missing (Debian: apt-get install python3-matplotlib "
        "python3-numpy python3-h5py)");
    return;
  }
  fs::create_directories(dir / "plots", error);
  const fs::path log_file = dir / "plots" / "plots.log";
  std::vector<std::string> scripts_run;
  for (const char* script : scripts_to_run) {
    const fs::path path = scripts / script;
    if (!fs::exists(path, error)) {
      warn(fmt::format("no {} picture: {} not found (set KESSLER_PLOTS_DIR to the tools/plots folder)", script,
                       path.string()));
      continue;
    }
    // The fragment pictures need the fragment files, written only when the analysis ran.
    if (std::string(script) == "fragments.py" && !fs::exists(dir / "fragments.csv", error)) continue;
    if (std::string(script) == "back_projection.py" && !fs::exists(dir / "fragment_points.csv", error)) continue;
    const std::string command = fmt::format("{} {} {} >>{} 2>&1", system_python, shellQuoted(path.string()),
                                            shellQuoted(dir.string()), shellQuoted(log_file.string()));
    if (runOutsideMpi(command) != 0)
      warn(fmt::format("{} failed (see {})", script, log_file.string()));
    else
      scripts_run.push_back(script);
  }
  if (!scripts_run.empty()) log::info("pictures in {}/plots/", dir.string());
}

}  // namespace kessler::app
