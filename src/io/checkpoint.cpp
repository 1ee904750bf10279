#include "io/checkpoint.hpp"

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint_meta.hpp"
#include "io/hdf5_file.hpp"
#include "io/hdf5_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <optional>
#include <span>
#include <string_view>

namespace kessler::io {
namespace {

// Bumped whenever the layout changes; an older or newer checkpoint is refused with a message.
// 6: bodies are identified by their points' `body` alone (format 5 also stored each body's point and
// node ranges, which this reader ignores), and the links by point id (format 5: by index in the
// store, which this reader turns into ids). 7: the points' loose flags (PointStore::loose; read as
// none loose from older formats).
constexpr std::int64_t format_version = 7, oldest_format_read = 5;

// Vec3 and Mat3 are stored as runs of 3 and 9 doubles, straight from the store.
static_assert(sizeof(Vec3) == 3 * sizeof(double));
static_assert(sizeof(Mat3) == 9 * sizeof(double));
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
struct Layout<std::array<Index, 2>> {
  using Scalar = Index;
  static constexpr hsize_t components = 2;
};
template <>
struct Layout<Mat3> {
  using Scalar = double;
  static constexpr hsize_t components = 9;
};

// The first `count` values (all by default).
template <class T>
void writeArray(Hdf5Writer& h5, const std::string& name, const std::vector<T>& values,
                std::size_t count = static_cast<std::size_t>(-1)) {
  using Scalar = typename Layout<T>::Scalar;
  constexpr hsize_t c = Layout<T>::components;
  const std::size_t n = std::min(count, values.size());
  const std::span<const Scalar> flat(reinterpret_cast<const Scalar*>(values.data()), n * c);
  if constexpr (c == 1)
    h5.writeDataset(name, flat, {n});
  else
    h5.writeDataset(name, flat, {n, c});
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

// Checks what a method would otherwise index blindly: a damaged or mismatched file must be
// refused here, not crash the run later. (The method checks its own part in Method::load.)
void checkConsistency(const Hdf5Reader& h5, const ParticleState& state) {
  const PointStore& points = state.points;
  const auto bodies = static_cast<std::int32_t>(state.bodies.size());
  for (LocalIndex p = 0; p < points.size(); ++p)
    if (points.body[p] < 0 || points.body[p] >= bodies) h5.fail(fmt::format("use point {}: no such body", p));
}

// The method's part of the file, through the interface it sees (solver/common/state_archive.hpp).
class Hdf5StateWriter final : public StateWriter {
 public:
  explicit Hdf5StateWriter(Hdf5Writer& h5) : h5_(h5) {}
  void group(const std::string& name) override { h5_.createGroup(name); }
  void scalar(const std::string& name, double value) override { h5_.writeAttribute(name, value); }
  void scalar(const std::string& name, std::int64_t value) override { h5_.writeAttribute(name, value); }
  void array(const std::string& name, const std::vector<double>& values) override { writeArray(h5_, name, values); }
  void array(const std::string& name, const std::vector<std::int32_t>& values) override {
    writeArray(h5_, name, values);
  }
  void array(const std::string& name, const std::vector<std::int64_t>& values) override {
    writeArray(h5_, name, values);
  }
  void array(const std::string& name, const std::vector<std::uint8_t>& values) override {
    writeArray(h5_, name, values);
  }
  void array(const std::string& name, const std::vector<Vec3>& values) override { writeArray(h5_, name, values); }
  void array(const std::string& name, const std::vector<Mat3>& values) override { writeArray(h5_, name, values); }

 private:
  Hdf5Writer& h5_;
};

class Hdf5StateReader final : public StateReader {
 public:
  explicit Hdf5StateReader(const Hdf5Reader& h5) : h5_(h5) {}
  double doubleScalar(const std::string& name) const override { return h5_.readDoubleAttribute(name); }
  std::int64_t intScalar(const std::string& name) const override { return h5_.readInt64Attribute(name); }
  std::size_t length(const std::string& name) const override {
    const std::vector<hsize_t> shape = h5_.shape(name);
    if (shape.empty()) h5_.fail(fmt::format("use '{}': it is not an array", name));
    return shape[0];
  }
  bool has(const std::string& name) const override { return h5_.has(name); }
  void array(const std::string& name, std::vector<double>& values, std::size_t count) const override {
    readArray(h5_, name, values, count);
  }
  void array(const std::string& name, std::vector<std::int32_t>& values, std::size_t count) const override {
    readArray(h5_, name, values, count);
  }
  void array(const std::string& name, std::vector<std::int64_t>& values, std::size_t count) const override {
    readArray(h5_, name, values, count);
  }
  void array(const std::string& name, std::vector<std::uint8_t>& values, std::size_t count) const override {
    readArray(h5_, name, values, count);
  }
  void array(const std::string& name, std::vector<Vec3>& values, std::size_t count) const override {
    readArray(h5_, name, values, count);
  }
  void array(const std::string& name, std::vector<Mat3>& values, std::size_t count) const override {
    readArray(h5_, name, values, count);
  }
  [[noreturn]] void fail(const std::string& what) const override { h5_.fail(what); }

 private:
  const Hdf5Reader& h5_;
};

}  // namespace

std::filesystem::path checkpointPath(const std::filesystem::path& run_dir) {
  return run_dir / "checkpoint.h5";
}

void writeCheckpoint(const std::filesystem::path& file, const Method& method, const RunLoopState& loop) {
  const ParticleState& model = method.state();
  AtomicFile target(file);
  Hdf5Writer h5(target.temporaryPath());
  h5.writeAttribute("kessler_checkpoint_format", format_version);
  h5.writeAttribute("run_next_output", loop.next_output);
  h5.writeAttribute("run_next_checkpoint", loop.next_checkpoint);
  h5.writeAttribute("run_wall_seconds", loop.wall_seconds);
  h5.writeAttribute("run_outputs", static_cast<std::int64_t>(loop.outputs));
  h5.writeAttribute("points_owned", static_cast<std::int64_t>(model.points.owned));

  // The owned points: ghosts (copies of other processes' points) are the method's to rebuild.
  h5.createGroup("/points");
  PointStore::fields(model.points, [&](const char* name, const auto& values, const auto&) {
    KESSLER_VERIFY(values.size() == model.points.x.size(), "checkpoint: points.{} has {} values for {} points", name,
                   values.size(), model.points.x.size());
    writeArray(h5, fmt::format("/points/{}", name), values, static_cast<std::size_t>(model.points.owned));
  });
  // Fragment links (analysis): the initial mesh adjacency and its lengths, which a restarted run
  // could not rebuild from the deformed state.
  h5.createGroup("/adjacency");
  writeArray(h5, "/adjacency/pairs", model.adjacency);
  writeArray(h5, "/adjacency/length0", model.adjacency_length0);

  h5.createGroup("/run");
  writeHistoryRows(h5, loop.history);
  const std::string meta = checkpointMetaText(method.name(), model, loop);
  h5.writeDataset("/run/meta", std::span(reinterpret_cast<const std::uint8_t*>(meta.data()), meta.size()),
                  {meta.size()});
  Hdf5StateWriter own(h5);
  method.save(own);
  h5.close();
  target.commit();
}

Restored readCheckpoint(const std::filesystem::path& file, const std::vector<MaterialPtr>& materials,
                        const MethodFactory& make) {
  const Hdf5Reader h5(file);
  std::int64_t version = 0;
  try {
    version = h5.readInt64Attribute("kessler_checkpoint_format");
  } catch (const Error&) {
    throw Error(fmt::format("'{}' is not a Kessler checkpoint", file.string()));
  }
  if (version < oldest_format_read || version > format_version)
    throw Error(fmt::format("'{}' is a checkpoint of format {}, this Kessler reads formats {} to {}", file.string(),
                            version, oldest_format_read, format_version));
  const Hdf5StateReader own(h5);
  Restored r;
  RunLoopState& loop = r.loop;
  loop.next_output = h5.readDoubleAttribute("run_next_output");
  loop.next_checkpoint = h5.readDoubleAttribute("run_next_checkpoint");
  loop.wall_seconds = h5.readDoubleAttribute("run_wall_seconds");
  loop.outputs = h5.readInt64Attribute("run_outputs");
  loop.history = readHistoryRows(h5);

  ParticleState model;
  const std::size_t np = own.length("/points/x");
  PointStore::fields(model.points, [&](const char* name, auto& values, const auto& fresh) {
    // Formats before 7 had no loose points (PointStore::loose): none was.
    if (version < 7 && std::string_view(name) == "loose")
      values.assign(np, fresh);
    else
      readArray(h5, fmt::format("/points/{}", name), values, np);
  });
  model.points.owned = static_cast<LocalIndex>(h5.readInt64Attribute("points_owned"));
  if (model.points.owned != model.points.size())
    h5.fail("use the points: the owned count differs from the stored size");

  const std::size_t links = own.length("/adjacency/pairs");
  if (version == 5) {
    // Format 5 stored the links by index in the store: they become the points' ids.
    std::vector<std::array<LocalIndex, 2>> by_index;
    readArray(h5, "/adjacency/pairs", by_index, links);
    model.adjacency.reserve(links);
    for (const auto& [i, j] : by_index) {
      if (i < 0 || i >= j || j >= model.points.size())
        h5.fail(fmt::format("use /adjacency/pairs: pair ({}, {}) is not two ordered points of {}", i, j,
                            model.points.size()));
      const Index a = model.points.id[static_cast<std::size_t>(i)], b = model.points.id[static_cast<std::size_t>(j)];
      model.adjacency.push_back({std::min(a, b), std::max(a, b)});
    }
  } else {
    readArray(h5, "/adjacency/pairs", model.adjacency, links);
  }
  readArray(h5, "/adjacency/length0", model.adjacency_length0, links);
  std::optional<IdIndex> index;
  try {
    index.emplace(model.points.id);
  } catch (const Error& e) {
    h5.fail(fmt::format("use /points/id: {}", e.what()));
  }
  for (const auto& [i, j] : model.adjacency)
    if (i >= j || index->find(i) < 0 || index->find(j) < 0)
      h5.fail(fmt::format("use /adjacency/pairs: pair ({}, {}) is not two ordered ids of stored points", i, j));

  const std::vector<std::uint8_t> meta = h5.read<std::uint8_t>("/run/meta");
  const std::string written_by =
      readCheckpointMeta(std::string(meta.begin(), meta.end()), file, materials, model, loop);
  checkConsistency(h5, model);
  r.method = make(std::move(model));
  if (written_by != r.method->name())
    throw Error(fmt::format("checkpoint '{}' was written by solver.method {}; this run's deck gives {}", file.string(),
                            written_by, r.method->name()));
  r.method->load(own);
  return r;
}

}  // namespace kessler::io
