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
  // Per body, in point order (the sums of a body are those of its points in store order).
  const std::size_t nb = model.bodies.size();
  std::vector<double> mass(nb, 0.0), volume(nb, 0.0);
  std::vector<long> points(nb, 0), nodes(nb, 0);
  for (LocalIndex p = 0; p < model.points.owned; ++p) {
    const auto b = static_cast<std::size_t>(model.points.body[p]);
    mass[b] += model.points.mass[p];
    volume[b] += model.points.volume0[p];
    ++points[b];
  }
  const NodeCloud node_store = method.nodes();
  for (LocalIndex a = 0; a < node_store.owned; ++a) ++nodes[static_cast<std::size_t>(node_store.body[a])];
  nlohmann::json bodies = nlohmann::json::array();
  for (std::size_t b = 0; b < nb; ++b) {
    const BodyInfo& body = model.bodies[b];
    bodies.push_back({{"name", body.name},
                      {"material", model.materials[body.material]->name()},
                      {"points", points[b]},
                      {"nodes", nodes[b]},
                      {"mass_kg", mass[b]},
                      {"volume_m3", volume[b]}});
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
      {"ranks", record.ranks},
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
