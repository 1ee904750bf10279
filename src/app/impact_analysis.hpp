#pragma once
// The end of an impact run (docs/analysis.md): the measurements of analysis::analyse on the
// model's final state, printed, returned for summary.json and written as fragments.csv, then the
// pictures of tools/plots. Neither step can fail the run: a problem is logged and recorded.
#include "io/config.hpp"
#include "solver/common/particle_state.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <initializer_list>

namespace kessler::app {

// The deck's impact geometry turned into analysis::ImpactGeometry, the measurements taken, printed
// and the fragment files written in `dir`. Returns the "analysis" object of summary.json: null when
// the deck's analysis is off, {"error": why} when it could not be done. `state` says which state was
// measured ("final", or "at the failure").
nlohmann::json analyseImpact(const io::RunConfig& config, const ParticleState& model, const std::filesystem::path& dir,
                             const std::string& state);

// Runs tools/plots scripts (by default debris_cloud.py, fragments.py and back_projection.py) on `dir` with
// /usr/bin/python3 (output in dir/plots/, log in dir/plots/plots.log). Missing Python or
// matplotlib, or a failing script, is a warning. The scripts are looked for in $KESSLER_PLOTS_DIR,
// else the source tree's tools/plots.
void drawPlots(const std::filesystem::path& dir,
               std::initializer_list<const char*> scripts = {"debris_cloud.py", "fragments.py", "back_projection.py"});

}  // namespace kessler::app
