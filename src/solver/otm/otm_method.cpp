#include "solver/otm/otm_method.hpp"

#include "core/error.hpp"
#include "solver/otm/setup.hpp"
#include "solver/otm/volume_patch.hpp"

#include <fmt/format.h>

namespace kessler::otm {

OtmMethod::OtmMethod(Model model, const Problem& problem)
    : OtmMethod(std::move(model), settingsFor(problem.settings, problem.walls)) {
  for (const PlaneConstraint& plane : problem.planes) {
    if (!plane.history) continue;
    History h{plane.axis, plane.history, {}, {}};
    for (const LocalIndex a : nodesOnPlane(model_, plane.axis, plane.offset, plane.tolerance, plane.body))
      h.node_ids.push_back(model_.nodes.id[a]);
    histories_.push_back(std::move(h));
  }
}

void OtmMethod::locateHistories() {
  if (histories_.empty()) return;
  const IdIndex index(model_.nodes.id);
  for (History& h : histories_) {
    h.nodes.clear();
    for (const Index id : h.node_ids) {
      const LocalIndex a = index.find(id);
      KESSLER_VERIFY(a >= 0, "prescribed velocity history: node {} is not in the store", id);
      h.nodes.push_back(a);
    }
  }
}

void OtmMethod::initialise() {
  integrator_.initialise();
  locateHistories();
}

void OtmMethod::step() {
  // The histories at the middle of the step.
  for (const History& h : histories_) {
    const double v = h.velocity(integrator_.time() + 0.5 * integrator_.nextStep());
    for (const LocalIndex a : h.nodes) model_.nodes.prescribed_v[a][h.axis] = v;
  }
  integrator_.step();
}

double OtmMethod::addedPressure(LocalIndex p) const {
  const Settings& s = integrator_.settings();
  const double alpha = s.volume_averaging ? s.volume_stabilisation : 0.0;
  const BodyInfo& body = model_.bodies[static_cast<std::size_t>(model_.points.body[p])];
  return stabilisationPressure(model_.points, p, alpha,
                               model_.materials[static_cast<std::size_t>(body.material)]->tensileLimit());
}

void OtmMethod::check(double initial_total_energy) {
  const StepInfo at{integrator_.steps(), integrator_.time(), integrator_.nextStep(), integrator_.initialStep()};
  diagnostics_.check(model_, at, initial_total_energy);
}

Clock OtmMethod::clock() const {
  return {integrator_.time(), integrator_.steps(), integrator_.lastStep(), integrator_.nextStep(),
          integrator_.initialStep()};
}

std::vector<std::pair<std::string, double>> OtmMethod::sizes() const {
  const double points = model_.points.owned;
  return {{"mean_neighbours", points > 0 ? static_cast<double>(model_.connectivity.node.size()) / points : 0.0}};
}

std::vector<std::string> OtmMethod::notes() const {
  if (integrator_.tornPoints() == 0) return {};
  return {
      fmt::format("torn from their bodies: {} intact point(s), {:.3g} g, outside the hull of every neighbourhood of "
                  "their nodes, released as debris (docs/theory.md §8)",
                  integrator_.tornPoints(), 1e3 * integrator_.tornMass())};
}

// The names are those of the checkpoint format 5, so that its files and those of format 6 read alike.
void OtmMethod::save(StateWriter& out) const {
  const IntegratorState s = integrator_.state();
  out.scalar("integrator_time", s.time);
  out.scalar("integrator_dt_last", s.dt_last);
  out.scalar("integrator_dt_next", s.dt_next);
  out.scalar("integrator_dt_initial", s.dt_initial);
  out.scalar("integrator_steps", static_cast<std::int64_t>(s.steps));
  out.scalar("integrator_stabilisation_energy", s.stabilisation_energy);
  const NodeStore& nodes = model_.nodes;
  out.scalar("nodes_owned", static_cast<std::int64_t>(nodes.owned));
  out.group("/nodes");
  NodeStore::fields(nodes, [&](const char* name, const auto& values, const auto&) {
    KESSLER_VERIFY(values.size() == nodes.x.size(), "checkpoint: nodes.{} has {} values for {} nodes", name,
                   values.size(), nodes.x.size());
    out.array(fmt::format("/nodes/{}", name), values);
  });
  KESSLER_VERIFY(model_.lme_lambda.size() == model_.points.x.size(), "checkpoint: {} LME multipliers for {} points",
                 model_.lme_lambda.size(), model_.points.x.size());
  out.array("/points/lambda", model_.lme_lambda);
  // The transpose (node -> entries) is rebuilt on reading: it is a pure function of these.
  static_assert(sizeof(Connectivity) == 6 * sizeof(std::vector<double>),
                "Connectivity changed: check what OtmMethod::save stores and load rebuilds");
  const Connectivity& conn = model_.connectivity;
  out.group("/connectivity");
  out.array("/connectivity/offset", conn.offset);
  out.array("/connectivity/node", conn.node);
  out.array("/connectivity/N", conn.N);
  out.array("/connectivity/dN", conn.dN);
}

void OtmMethod::load(const StateReader& in) {
  NodeStore& nodes = model_.nodes;
  const std::size_t nn = in.length("/nodes/x");
  NodeStore::fields(nodes, [&](const char* name, auto& values, const auto&) {
    in.array(fmt::format("/nodes/{}", name), values, nn);
  });
  nodes.owned = static_cast<LocalIndex>(in.intScalar("nodes_owned"));
  if (nodes.owned != nodes.size()) in.fail("use the nodes: the owned count differs from the stored size");
  Connectivity& conn = model_.connectivity;
  const PointStore& points = model_.points;
  in.array("/points/lambda", model_.lme_lambda, static_cast<std::size_t>(points.size()));
  in.array("/connectivity/offset", conn.offset, static_cast<std::size_t>(points.size()) + 1);
  const std::size_t entries = in.length("/connectivity/node");
  in.array("/connectivity/node", conn.node, entries);
  in.array("/connectivity/N", conn.N, entries);
  in.array("/connectivity/dN", conn.dN, entries);

  // What the integrator would otherwise index blindly.
  const auto bodies = static_cast<std::int32_t>(model_.bodies.size());
  for (LocalIndex a = 0; a < nodes.size(); ++a)
    if (nodes.body[a] < 0 || nodes.body[a] >= bodies) in.fail(fmt::format("use node {}: no such body", a));
  if (conn.offset.front() != 0 || static_cast<std::size_t>(conn.offset.back()) != conn.node.size())
    in.fail("use the connectivity: its sizes do not match the points");
  for (std::size_t p = 1; p < conn.offset.size(); ++p)
    if (conn.offset[p] < conn.offset[p - 1]) in.fail("use the connectivity: offsets decrease");
  for (LocalIndex a : conn.node)
    if (a < 0 || a >= nodes.size()) in.fail(fmt::format("use the connectivity: node {} does not exist", a));
  conn.buildTranspose(nodes.size());

  integrator_.restore({in.doubleScalar("integrator_time"), in.doubleScalar("integrator_dt_last"),
                       in.doubleScalar("integrator_dt_next"), in.doubleScalar("integrator_dt_initial"),
                       in.intScalar("integrator_steps"), in.doubleScalar("integrator_stabilisation_energy")});
  locateHistories();
}

}  // namespace kessler::otm
