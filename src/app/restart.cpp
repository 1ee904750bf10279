// Continuing a run from its folder (`kessler run --restart DIR`, kessler.restart in Python).
#include "app/simulation.hpp"
#include "core/error.hpp"
#include "io/deck.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace kessler::app {

const std::vector<std::string>& restartKeys() {
  static const std::vector<std::string> keys = {
      "solver.end_time", "solver.max_steps", "solver.min_dt_fraction",  "solver.max_energy_growth",
      "output.every",    "checkpoint.every", "checkpoint.wall_interval"};
  return keys;
}

namespace {

void checkRestartOverride(const std::string& text) {
  std::string key = text.substr(0, text.find('='));
  key.erase(0, key.find_first_not_of(" \t"));
  key.erase(key.find_last_not_of(" \t") + 1);
  const std::vector<std::string>& keys = restartKeys();
  if (std::find(keys.begin(), keys.end(), key) == keys.end())
    throw InputError(
        fmt::format("restart setting '{}': a restart continues the model of its checkpoint; only these may change: {}",
                    text, fmt::join(keys, ", ")));
}

}  // namespace

io::RunConfig restartConfig(const std::filesystem::path& dir, const std::vector<std::string>& overrides) {
  if (!std::filesystem::is_directory(dir))
    throw InputError(fmt::format("restart {}: no such run folder", dir.string()));
  const std::filesystem::path deck = dir / "deck.resolved.yaml";
  if (!std::filesystem::is_regular_file(deck))
    throw InputError(
        fmt::format("restart {}: no deck.resolved.yaml, so this is not a Kessler run folder", dir.string()));
  for (const std::string& text : overrides) checkRestartOverride(text);
  io::RunConfig config = io::parseDeck(deck, overrides);
  config.output.dir = dir;  // the folder stays the run's folder
  return config;
}

}  // namespace kessler::app
