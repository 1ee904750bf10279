#include "io/checkpoint.hpp"

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint_meta.hpp"
#include "io/hdf5_file.hpp"
#include "io/hdf5_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <span>

namespace kessler::io {
namespace {

// Bumped whenever the layout changes; an older or newer checkpoint is refused with a message.
constexpr std::int64_t format_version = 5;

// Vec3 and Mat3 are stored as runs of 3 and 9 doubles, straight from the store.
static_assert(sizeof(Vec3) == 3 * sizeof(double));
static_assert(sizeof(Mat3) == 9 * sizeof(double));
static_assert(sizeof(Connectivity) == 6 * sizeof(std::vector<double>),
              "Connectivity changed: check what io/checkpoint.cpp stores and rebuilds");

// Values per entry of a stored type, and the plain number type it is made of.
template <class T>
struct Layout {
  using Scalar = T;
  static constexpr hsize_t components = 1;
};
template <>
struct Layout<Vec3> {
  using Scalar = double;
  static constexpr hsize_t components = 3;
};
template <>
struct Layout<std::array<LocalIndex, 2>> {
  using Scalar = LocalIndex;
  static constexpr hsize_t components = 2;
};
template <>
struct Layout<Mat3> {
  using Scalar = double;
  static constexpr hsize_t components = 9;
};

template <class T>
void writeArray(Hdf5Writer& h5, const std::string& name, const std::vector<T>& values) {
  using Scalar = typename Layout<T>::Scalar;
  constexpr hsize_t c = Layout<T>::components;
  const std::span<const Scalar> flat(reinterpret_cast<const Scalar*>(values.data()), values.size() * c);
  if constexpr (c == 1)
    h5.writeDataset(name, flat, {values.size()});
  else
    h5.writeDataset(name, flat, {values.size(), c});
}

template <class T>
void readArray(const Hdf5Reader& h5, const std::string& name, std::vector<T>& values, std::size_t count) {
  using Scalar = typename Layout<T>::Scalar;
  constexpr hsize_t c = Layout<T>::components;
  const std::vector<hsize_t> shape = h5.shape(name);
  const std::vector<hsize_t> expected = c == 1 ? std::vector<hsize_t>{count} : std::vector<hsize_t>{count, c};
  if (shape != expected)
    h5.fail(fmt::format("use '{}': it has {} values, expected {} x {}", name, shape.empty() ? 0 : shape[0], count, c));
  const std::vector<Scalar> flat = h5.read<Scalar>(name);
  values.resize(count);
  std::copy(flat.begin(), flat.end(), reinterpret_cast<Scalar*>(values.data()));
}

// Per history row: time, dt, kinetic, internal and stabilisation energy, momentum.
constexpr std::size_t history_columns = 8;

void writeHistoryRows(Hdf5Writer& h5, const std::vector<HistoryRow>& history) {
  std::vector<std::int64_t> steps;
  std::vector<double> values;
  for (const HistoryRow& r : history) {
    steps.push_back(r.step);
    for (double v : {r.time, r.dt, r.energies.kinetic, r.energies.internal, r.energies.stabilisation,
                     r.energies.momentum[0], r.energies.momentum[1], r.energies.momentum[2]})
      values.push_back(v);
  }
  h5.writeDataset("/run/history_step", steps, {steps.size()});
  h5.writeDataset("/run/history_values", values, {steps.size(), history_columns});
}

std::vector<HistoryRow> readHistoryRows(const Hdf5Reader& h5) {
  const std::vector<std::int64_t> steps = h5.read<std::int64_t>("/run/history_step");
  const std::vector<double> values = h5.read<double>("/run/history_values");
  if (values.size() != history_columns * steps.size()) h5.fail("use the history: steps and values differ in length");
  std::vector<HistoryRow> history(steps.size());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const double* v = &values[history_columns * i];
    history[i].step = steps[i];
    history[i].time = v[0];
    history[i].dt = v[1];
    history[i].energies.kinetic = v[2];
    history[i].energies.internal = v[3];
    history[i].energies.stabilisation = v[4];
    history[i].energies.momentum = Vec3(v[5], v[6], v[7]);
  }
  return history;
}

// Checks what the integrator would otherwise index blindly: a damaged or mismatched file must
// be refused here, not crash the run later.
void checkConsistency(const Hdf5Reader& h5, const otm::Model& model) {
  const PointStore& points = model.points;
  const NodeStore& nodes = model.nodes;
  const Connectivity& conn = model.connectivity;
  const auto bodies = static_cast<std::int32_t>(model.bodies.size());
  for (const BodyInfo& b : model.bodies)
    if (b.point_begin < 0 || b.point_begin > b.point_end || b.point_end > points.size() || b.node_begin < 0 ||
        b.node_begin > b.node_end || b.node_end > nodes.size())
      h5.fail(fmt::format("use body '{}': its point or node range does not fit the stores", b.name));
  for (LocalIndex p = 0; p < points.size(); ++p)
    if (points.body[p] < 0 || points.body[p] >= bodies) h5.fail(fmt::format("use point {}: no such body", p));
  for (LocalIndex a = 0; a < nodes.size(); ++a)
    if (nodes.body[a] < 0 || nodes.body[a] >= bodies) h5.fail(fmt::format("use node {}: no such body", a));
  if (conn.offset.size() != static_cast<std::size_t>(points.size()) + 1 || conn.offset.front() != 0 ||
      static_cast<std::size_t>(conn.offset.back()) != conn.node.size() || conn.N.size() != conn.node.size() ||
      conn.dN.size() != conn.node.size())
    h5.fail("use the connectivity: its sizes do not match the points");
  for (std::size_t p = 1; p < conn.offset.size(); ++p)
    if (conn.offset[p] < conn.offset[p - 1]) h5.fail("use the connectivity: offsets decrease");
  for (LocalIndex a : conn.node)
    if (a < 0 || a >= nodes.size()) h5.fail(fmt::format("use the connectivity: node {} does not exist", a));
}

}  // namespace

std::filesystem::path checkpointPath(const std::filesystem::path& run_dir) {
  return run_dir / "checkpoint.h5";
}

void writeCheckpoint(const std::filesystem::path& file, const otm::Model& model, const Checkpoint& checkpoint) {
  AtomicFile target(file);
  Hdf5Writer h5(target.temporaryPath());
  h5.writeAttribute("kessler_checkpoint_format", format_version);
  const otm::IntegratorState& s = checkpoint.integrator;
  h5.writeAttribute("integrator_time", s.time);
  h5.writeAttribute("integrator_dt_last", s.dt_last);
  h5.writeAttribute("integrator_dt_next", s.dt_next);
  h5.writeAttribute("integrator_dt_initial", s.dt_initial);
  h5.writeAttribute("integrator_steps", static_cast<std::int64_t>(s.steps));
  h5.writeAttribute("integrator_stabilisation_energy", s.stabilisation_energy);
  const RunLoopState& loop = checkpoint.loop;
  h5.writeAttribute("run_next_output", loop.next_output);
  h5.writeAttribute("run_next_checkpoint", loop.next_checkpoint);
  h5.writeAttribute("run_wall_seconds", loop.wall_seconds);
  h5.writeAttribute("run_outputs", static_cast<std::int64_t>(loop.outputs));
  h5.writeAttribute("points_owned", static_cast<std::int64_t>(model.points.owned));
  h5.writeAttribute("nodes_owned", static_cast<std::int64_t>(model.nodes.owned));

  h5.createGroup("/points");
  PointStore::fields(model.points, [&](const char* name, const auto& values, const auto&) {
    KESSLER_VERIFY(values.size() == model.points.x.size(), "checkpoint: points.{} has {} values for {} points", name,
                   values.size(), model.points.x.size());
    writeArray(h5, fmt::format("/points/{}", name), values);
  });
  h5.createGroup("/nodes");
  NodeStore::fields(model.nodes, [&](const char* name, const auto& values, const auto&) {
    KESSLER_VERIFY(values.size() == model.nodes.x.size(), "checkpoint: nodes.{} has {} values for {} nodes", name,
                   values.size(), model.nodes.x.size());
    writeArray(h5, fmt::format("/nodes/{}", name), values);
  });
  // The transpose (node -> entries) is rebuilt on reading: it is a pure function of these.
  const Connectivity& conn = model.connectivity;
  h5.createGroup("/connectivity");
  writeArray(h5, "/connectivity/offset", conn.offset);
  writeArray(h5, "/connectivity/node", conn.node);
  writeArray(h5, "/connectivity/N", conn.N);
  writeArray(h5, "/connectivity/dN", conn.dN);

  // Fragment links (analysis): the initial mesh adjacency and its lengths, which a restarted run
  // could not rebuild from the deformed state.
  h5.createGroup("/adjacency");
  writeArray(h5, "/adjacency/pairs", model.adjacency);
  writeArray(h5, "/adjacency/length0", model.adjacency_length0);

  h5.createGroup("/run");
  writeHistoryRows(h5, loop.history);
  const std::string meta = checkpointMetaText(model, loop);
  h5.writeDataset("/run/meta", std::span(reinterpret_cast<const std::uint8_t*>(meta.data()), meta.size()),
                  {meta.size()});
  h5.close();
  target.commit();
}

Checkpoint readCheckpoint(const std::filesystem::path& file, otm::Model& model,
                          const std::vector<MaterialPtr>& materials) {
  const Hdf5Reader h5(file);
  std::int64_t version = 0;
  try {
    version = h5.readInt64Attribute("kessler_checkpoint_format");
  } catch (const Error&) {
    throw Error(fmt::format("'{}' is not a Kessler checkpoint", file.string()));
  }
  if (version != format_version)
    throw Error(fmt::format("'{}' is a checkpoint of format {}, this Kessler reads format {}", file.string(), version,
                            format_version));
  Checkpoint c;
  c.integrator.time = h5.readDoubleAttribute("integrator_time");
  c.integrator.dt_last = h5.readDoubleAttribute("integrator_dt_last");
  c.integrator.dt_next = h5.readDoubleAttribute("integrator_dt_next");
  c.integrator.dt_initial = h5.readDoubleAttribute("integrator_dt_initial");
  c.integrator.steps = h5.readInt64Attribute("integrator_steps");
  c.integrator.stabilisation_energy = h5.readDoubleAttribute("integrator_stabilisation_energy");
  c.loop.next_output = h5.readDoubleAttribute("run_next_output");
  c.loop.next_checkpoint = h5.readDoubleAttribute("run_next_checkpoint");
  c.loop.wall_seconds = h5.readDoubleAttribute("run_wall_seconds");
  c.loop.outputs = h5.readInt64Attribute("run_outputs");
  c.loop.history = readHistoryRows(h5);

  auto length = [&](const std::string& name) -> std::size_t {
    const std::vector<hsize_t> shape = h5.shape(name);
    if (shape.empty()) h5.fail(fmt::format("use '{}': it is not an array", name));
    return shape[0];
  };
  model = otm::Model{};
  const std::size_t np = length("/points/x"), nn = length("/nodes/x");
  PointStore::fields(model.points, [&](const char* name, auto& values, const auto&) {
    readArray(h5, fmt::format("/points/{}", name), values, np);
  });
  NodeStore::fields(model.nodes, [&](const char* name, auto& values, const auto&) {
    readArray(h5, fmt::format("/nodes/{}", name), values, nn);
  });
  model.points.owned = static_cast<LocalIndex>(h5.readInt64Attribute("points_owned"));
  model.nodes.owned = static_cast<LocalIndex>(h5.readInt64Attribute("nodes_owned"));
  if (model.points.owned != model.points.size() || model.nodes.owned != model.nodes.size())
    h5.fail("use the stores: owned counts differ from the stored sizes");
  Connectivity& conn = model.connectivity;
  readArray(h5, "/connectivity/offset", conn.offset, np + 1);
  const std::size_t entries = length("/connectivity/node");
  readArray(h5, "/connectivity/node", conn.node, entries);
  readArray(h5, "/connectivity/N", conn.N, entries);
  readArray(h5, "/connectivity/dN", conn.dN, entries);

  const std::size_t links = length("/adjacency/pairs");
  readArray(h5, "/adjacency/pairs", model.adjacency, links);
  readArray(h5, "/adjacency/length0", model.adjacency_length0, links);
  for (const auto& [i, j] : model.adjacency)
    if (i < 0 || i >= j || j >= model.points.size())
      h5.fail(fmt::format("use /adjacency/pairs: pair ({}, {}) is not two ordered points of {}", i, j,
                          model.points.size()));

  const std::vector<std::uint8_t> meta = h5.read<std::uint8_t>("/run/meta");
  readCheckpointMeta(std::string(meta.begin(), meta.end()), file, materials, model, c.loop);
  checkConsistency(h5, model);
  conn.buildTranspose(model.nodes.size());
  return c;
}

}  // namespace kessler::io
