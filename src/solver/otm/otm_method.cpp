#include "solver/otm/otm_method.hpp"

#include "core/error.hpp"
#include "solver/otm/setup.hpp"
#include "solver/otm/volume_patch.hpp"

#include <fmt/format.h>

namespace kessler::otm {

namespace {

std::unique_ptr<Distribution> distributionFor(const parallel::Communicator* ranks) {
  return ranks && ranks->size() > 1 ? std::make_unique<Distribution>(*ranks) : nullptr;
}

}  // namespace

OtmMethod::OtmMethod(Model model, const Settings& settings, const parallel::Communicator* ranks)
    : model_(std::move(model)),
      distribution_(distributionFor(ranks)),
      integrator_(model_, settings, distribution_.get()),
      diagnostics_(settings) {}

OtmMethod::OtmMethod(Model model, const Problem& problem, const parallel::Communicator* ranks)
    : OtmMethod(std::move(model), settingsFor(problem.settings, problem.walls), ranks) {
  for (const PlaneConstraint& plane : problem.planes) {
    if (!plane.history) continue;
    std::vector<Index> ids;
    for (const LocalIndex a : nodesOnPlane(model_, plane.axis, plane.offset, plane.tolerance, plane.body))
      ids.push_back(model_.nodes.id[a]);
    histories_.add(plane, std::move(ids));
  }
}

void OtmMethod::locateHistories() {
  histories_.locate(model_.nodes.id, distribution_ != nullptr);  // a distributed run's rank holds some
}

void OtmMethod::initialise() {
  integrator_.initialise();
  locateHistories();
}

void OtmMethod::step() {
  // The histories at the middle of the step (a distributed run's nodes move between ranks and
  // places every step).
  if (distribution_) locateHistories();
  histories_.apply(integrator_.time() + 0.5 * integrator_.nextStep(), model_.nodes.prescribed_v);
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
  if (!distribution_) {
    diagnostics_.check(model_, at, initial_total_energy);
    return;
  }
  // Every rank stops if one does (the others would wait for it).
  const Share share = distribution_->pointShare();
  std::optional<NumericalError> failure;
  try {
    diagnostics_.check(model_, at, initial_total_energy, share);
  } catch (const NumericalError& e) {
    failure = e;
  }
  const std::string elsewhere = fmt::format("{}: another rank's health check failed", describeStep(at));
  share.stopTogether(
      failure.has_value(), [&] { throw *failure; }, elsewhere.c_str());
}

Clock OtmMethod::clock() const {
  return {integrator_.time(), integrator_.steps(), integrator_.lastStep(), integrator_.nextStep(),
          integrator_.initialStep()};
}

std::vector<std::pair<std::string, double>> OtmMethod::sizes() const {
  if (report_) return report_->sizes;
  // The mean neighbours of the whole run: a distributed run's own points on every rank (its ghosts
  // hold rows or not as the halo needs).
  std::int64_t counts[2] = {0, 0};  // entries, points
  const std::span<const std::uint8_t> ghost =
      distribution_ ? distribution_->ghostPoints() : std::span<const std::uint8_t>{};
  const Connectivity& conn = model_.connectivity;
  for (LocalIndex p = 0; p < model_.points.owned; ++p)
    if (ghost.empty() || !ghost[static_cast<std::size_t>(p)]) {
      counts[0] += conn.offset.empty() ? 0 : conn.offset[p + 1] - conn.offset[p];
      ++counts[1];
    }
  if (distribution_) distribution_->comm().sum(counts);
  std::vector<std::pair<std::string, double>> sizes{
      {"mean_neighbours", counts[1] > 0 ? static_cast<double>(counts[0]) / static_cast<double>(counts[1]) : 0.0}};
  const std::vector<std::pair<std::string, double>> ranks = rankSizes();
  sizes.insert(sizes.end(), ranks.begin(), ranks.end());
  return sizes;
}

// The ranks and their balance (docs/parallel.md).
std::vector<std::pair<std::string, double>> OtmMethod::rankSizes() const {
  if (!distribution_) return {};
  return {{"ranks", distribution_->comm().size()},
          {"imbalance", distribution_->imbalance()},
          {"largest_imbalance", distribution_->largestImbalance()},
          {"rebalances", distribution_->rebalances()},
          {"searches_repeated", static_cast<double>(integrator_.searchesRepeated())},
          {"halo_search_radius_m", integrator_.haloSupport()},
          {"rank0_own_points", static_cast<double>(distribution_->ownPoints())},
          {"rank0_ghost_points", static_cast<double>(distribution_->ghostPointCount())},
          {"rank0_ghost_nodes", static_cast<double>(distribution_->ghostNodeCount())},
          {"halo_fetches", static_cast<double>(distribution_->haloFetches())},
          {"halo_keeps", static_cast<double>(distribution_->haloKeeps())}};
}

std::vector<std::string> OtmMethod::notes() const {
  return report_ ? report_->notes : tornNotes(integrator_.tornPoints(), integrator_.tornMass());
}

std::vector<std::string> OtmMethod::tornNotes(LocalIndex torn, double mass) const {
  if (torn == 0) return {};
  return {
      fmt::format("torn from their bodies: {} intact point(s), {:.3g} g, outside the hull of every neighbourhood of "
                  "their nodes, released as debris (docs/theory.md §8)",
                  torn, 1e3 * mass)};
}

std::unique_ptr<Method> OtmMethod::gathered(bool for_checkpoint) const {
  if (!distribution_) return nullptr;
  const parallel::Communicator& comm = distribution_->comm();
  const std::int64_t torn = comm.sum(static_cast<std::int64_t>(integrator_.tornPoints()));
  ExactSum torn_mass;
  torn_mass.add(integrator_.tornMass());
  const double mass = comm.sum(torn_mass);
  // (A gathered method without its connectivity has no neighbours of its own: they are counted here.)
  std::vector<std::pair<std::string, double>> sizes = this->sizes();
  std::optional<Model> whole = distribution_->gather(model_, for_checkpoint);
  if (!whole) return nullptr;
  auto method = std::make_unique<OtmMethod>(std::move(*whole), integrator_.settings());
  method->integrator_.restore(integrator_.state());
  method->report_ =
      GatheredReport{integrator_.timers(), std::move(sizes), tornNotes(static_cast<LocalIndex>(torn), mass)};
  return method;
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
  if (!model_.faces.empty()) {
    std::vector<std::int64_t> faces;
    faces.reserve(5 * model_.faces.size());
    for (const ContactFace& f : model_.faces)
      faces.insert(faces.end(), {f.nodes[0], f.nodes[1], f.nodes[2], f.inner, f.outer});
    out.group("/contact");
    out.array("/contact/faces", faces);
  }
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
  if (!distribution_) conn.buildTranspose(nodes.size());  // a distributed run's, once it holds its part
  if (integrator_.settings().contact.sliding()) {
    std::vector<std::int64_t> faces;
    const std::size_t values = in.length("/contact/faces");
    if (values % 5 != 0) in.fail("use the contact faces: their count is not a multiple of 5");
    in.array("/contact/faces", faces, values);
    model_.faces.resize(values / 5);
    for (std::size_t f = 0; f < model_.faces.size(); ++f) {
      const std::int64_t* v = faces.data() + 5 * f;
      for (int i = 0; i < 3; ++i)
        if (v[i] < 0 || v[i] >= nodes.size())
          in.fail(fmt::format("use contact face {}: node {} does not exist", f, v[i]));
      for (int i = 3; i < 5; ++i)
        if (v[i] < -1 || v[i] >= points.size() || (i == 3 && v[i] < 0))
          in.fail(fmt::format("use contact face {}: point {} does not exist", f, v[i]));
      model_.faces[f] = ContactFace{{v[0], v[1], v[2]}, v[3], v[4]};
    }
  }

  integrator_.restore({in.doubleScalar("integrator_time"), in.doubleScalar("integrator_dt_last"),
                       in.doubleScalar("integrator_dt_next"), in.doubleScalar("integrator_dt_initial"),
                       in.intScalar("integrator_steps"), in.doubleScalar("integrator_stabilisation_energy")});
  locateHistories();
}

}  // namespace kessler::otm
