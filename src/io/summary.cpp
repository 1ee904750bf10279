#include "io/summary.hpp"

#include "io/atomic_file.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace kessler::io {

namespace {

nlohmann::json vec(const Vec3& v) {
  return nlohmann::json::array({v[0], v[1], v[2]});
}

nlohmann::json energiesJson(const Energies& e) {
  return {{"kinetic_J", e.kinetic},
          {"internal_J", e.internal},
          {"stabilisation_J", e.stabilisation},
          {"total_J", e.total()},
          {"momentum_kg_m_s", vec(e.momentum)}};
}

}  // namespace

void writeSummary(const std::filesystem::path& file, const RunRecord& record, const Method& method) {
  const ParticleState& model = method.state();
  const Clock clock = method.clock();
  nlohmann::json bodies = nlohmann::json::array();
  for (const BodyInfo& body : model.bodies) {
    double mass = 0.0, volume = 0.0;
    for (LocalIndex p = body.point_begin; p < body.point_end; ++p) {
      mass += model.points.mass[p];
      volume += model.points.volume0[p];
    }
    bodies.push_back({{"name", body.name},
                      {"material", model.materials[body.material]->name()},
                      {"points", body.point_end - body.point_begin},
                      {"nodes", body.node_end - body.node_begin},
                      {"mass_kg", mass},
                      {"volume_m3", volume}});
  }
  const double point_steps = static_cast<double>(clock.steps) * model.points.owned;
  nlohmann::json timings = nlohmann::json::object();
  for (const auto& [phase, seconds] : method.timers().totals()) timings[phase] = seconds;
  nlohmann::json problem = {{"points", model.points.owned}, {"nodes", method.nodes().owned}, {"bodies", bodies}};
  for (const auto& [name, value] : method.sizes()) problem[name] = value;
  for (const auto& [phase, seconds] : record.extra_timings) timings[phase] = seconds;

  nlohmann::json j = {
      {"title", record.title},
      {"deck", record.deck},
      {"status", record.status},
      {"problem", problem},
      {"threads", record.threads},
      {"steps", clock.steps},
      {"simulated_time_s", clock.time},
      {"end_time_s", method.endTime()},
      {"time_step_s", {{"initial", clock.dt_initial}, {"last", clock.dt_last}}},
      {"wall_time_s", record.wall_seconds},
      {"us_per_point_step", point_steps > 0 ? 1e6 * record.wall_seconds / point_steps : 0.0},
      {"outputs", record.outputs},
      {"timings_s", timings},
  };
  if (!record.history.empty()) {
    j["energy"] = {{"initial", energiesJson(record.history.front().energies)},
                   {"final", energiesJson(record.history.back().energies)}};
  }
  if (!record.message.empty()) j["message"] = record.message;
  if (!record.analysis.is_null()) j["analysis"] = record.analysis;
  writeTextAtomically(file, j.dump(2) + "\n");
}

void writeHistory(const std::filesystem::path& file, const std::vector<HistoryRow>& history) {
  std::string text = "step,time_s,dt_s,kinetic_J,internal_J,stabilisation_J,total_J,momentum_x,momentum_y,momentum_z\n";
  for (const HistoryRow& r : history)
    text += fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", r.step, r.time, r.dt,
                        r.energies.kinetic, r.energies.internal, r.energies.stabilisation, r.energies.total(),
                        r.energies.momentum[0], r.energies.momentum[1], r.energies.momentum[2]);
  writeTextAtomically(file, text);
}

}  // namespace kessler::io
