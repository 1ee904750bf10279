#include "io/fields_writer.hpp"

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <system_error>
#include <utility>

namespace kessler::io {
namespace {

// Positions and velocities are written straight from the store: Eigen keeps a Vec3 as three
// doubles without padding, so a run of Vec3 is a row-major n x 3 array.
static_assert(sizeof(Vec3) == 3 * sizeof(double));

template <class Values>
auto ownedPrefix(const Values& values, LocalIndex owned, const char* name) {
  using T = typename Values::value_type;
  KESSLER_VERIFY(owned >= 0 && static_cast<std::size_t>(owned) <= values.size(),
                 "field output: '{}' holds {} values, fewer than the {} owned", name, values.size(), owned);
  return std::span<const T>(values.data(), static_cast<std::size_t>(owned));
}

std::span<const double> flatten(std::span<const Vec3> vectors) {
  if (vectors.empty()) return {};
  return {vectors.front().data(), 3 * vectors.size()};
}

// Writes the datasets of one HDF5 group and records each in the XDMF grid at the same time,
// so that the XDMF can only name datasets that were written, with the shapes they have.
class GridWriter {
 public:
  GridWriter(Hdf5Writer& h5, const std::string& file, std::string group, std::size_t count, XdmfGrid& grid)
      : h5_(h5), file_(file), group_(std::move(group)), count_(count), grid_(grid) {
    h5_.createGroup(group_);
    grid_.vertices = static_cast<Index>(count_);
  }

  // The positions, and the vertex cells ParaView draws them with (XdmfGrid::topology).
  void geometry(std::span<const Vec3> x) {
    h5_.writeDataset(dataset("position"), flatten(x), {count_, 3});
    grid_.geometry = xdmfItem<double>({grid_.vertices, 3}, source("position"));
    KESSLER_VERIFY(count_ < (hsize_t{1} << 31), "{} vertices in one output: more than 32-bit cell indices hold",
                   count_);
    std::vector<std::int32_t> cells(count_);
    std::iota(cells.begin(), cells.end(), 0);
    h5_.writeDataset(dataset("vertex"), std::span<const std::int32_t>(cells), {count_});
    grid_.topology = xdmfItem<std::int32_t>({grid_.vertices}, source("vertex"));
  }

  void vector(const std::string& name, std::span<const Vec3> values) {
    h5_.writeDataset(dataset(name), flatten(values), {count_, 3});
    grid_.attributes.push_back({name, "Vector", xdmfItem<double>({grid_.vertices, 3}, source(name))});
  }

  template <class T>
  void scalar(const std::string& name, std::span<const T> values) {
    h5_.writeDataset(dataset(name), values, {count_});
    grid_.attributes.push_back({name, "Scalar", xdmfItem<T>({grid_.vertices}, source(name))});
  }

 private:
  std::string dataset(const std::string& name) const { return "/" + group_ + "/" + name; }
  std::string source(const std::string& name) const { return file_ + ":" + dataset(name); }

  Hdf5Writer& h5_;
  std::string file_;
  std::string group_;
  hsize_t count_;
  XdmfGrid& grid_;
};

struct DerivedPointFields {
  std::vector<double> density, pressure, von_mises;
};

DerivedPointFields derivedFields(const PointStore& points, std::size_t n) {
  const auto mass = ownedPrefix(points.mass, points.owned, "points.mass");
  const auto volume = ownedPrefix(points.volume, points.owned, "points.volume");
  const auto stress = ownedPrefix(points.stress, points.owned, "points.stress");
  DerivedPointFields derived{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n)};
#pragma omp parallel for schedule(static)
  for (std::size_t p = 0; p < n; ++p) {
    derived.density[p] = mass[p] / volume[p];
    const double mean = stress[p].trace() / 3.0;
    derived.pressure[p] = -mean;
    const Mat3 deviator = stress[p] - mean * Mat3::Identity();
    derived.von_mises[p] = std::sqrt(1.5 * deviator.squaredNorm());
  }
  return derived;
}

void writePoints(Hdf5Writer& h5, const std::string& file, const PointStore& points, XdmfGrid& grid) {
  const auto n = static_cast<std::size_t>(std::max(points.owned, LocalIndex{0}));
  const DerivedPointFields derived = derivedFields(points, n);
  GridWriter out(h5, file, "points", n, grid);
  out.geometry(ownedPrefix(points.x, points.owned, "points.x"));
  out.vector("velocity", ownedPrefix(points.v, points.owned, "points.v"));
  out.scalar<double>("density", derived.density);
  out.scalar<double>("pressure", derived.pressure);
  out.scalar<double>("von_mises", derived.von_mises);
  out.scalar("plastic_strain", ownedPrefix(points.plastic_strain, points.owned, "points.plastic_strain"));
  out.scalar("temperature", ownedPrefix(points.temperature, points.owned, "points.temperature"));
  out.scalar("volume", ownedPrefix(points.volume, points.owned, "points.volume"));
  out.scalar("eroded", ownedPrefix(points.broken, points.owned, "points.broken"));
  out.scalar("loose", ownedPrefix(points.loose, points.owned, "points.loose"));
  out.scalar("carrier", ownedPrefix(points.carrier, points.owned, "points.carrier"));
  out.scalar("body", ownedPrefix(points.body, points.owned, "points.body"));
  out.scalar("id", ownedPrefix(points.id, points.owned, "points.id"));
}

void writeNodes(Hdf5Writer& h5, const std::string& file, const NodeCloud& nodes, XdmfGrid& grid) {
  const auto n = static_cast<std::size_t>(std::max(nodes.owned, LocalIndex{0}));
  GridWriter out(h5, file, "nodes", n, grid);
  out.geometry(ownedPrefix(nodes.x, nodes.owned, "nodes.x"));
  out.vector("velocity", ownedPrefix(nodes.v, nodes.owned, "nodes.v"));
  out.scalar("mass", ownedPrefix(nodes.mass, nodes.owned, "nodes.mass"));
  out.scalar("body", ownedPrefix(nodes.body, nodes.owned, "nodes.body"));
  out.scalar("id", ownedPrefix(nodes.id, nodes.owned, "nodes.id"));
}

// Replaces the grid of the same name (a step written again) or appends a new one.
void record(std::vector<XdmfGrid>& grids, XdmfGrid grid) {
  auto same = std::find_if(grids.begin(), grids.end(), [&](const XdmfGrid& g) { return g.name == grid.name; });
  if (same != grids.end())
    *same = std::move(grid);
  else
    grids.push_back(std::move(grid));
}

}  // namespace

FieldWriter::FieldWriter(std::filesystem::path dir) : dir_(std::move(dir)) {
  std::error_code error;
  std::filesystem::create_directories(dir_ / "fields", error);
  if (error)
    throw Error(fmt::format("cannot create the output folder '{}': {}", (dir_ / "fields").string(), error.message()));
}

void FieldWriter::write(long step, double time, const NodeCloud& nodes, const PointStore& points) {
  KESSLER_VERIFY(step >= 0, "field output: negative step {}", step);
  // XDMF paths are relative to the XDMF files in dir_, with '/' on every platform.
  const std::string file = fmt::format("fields/fields_{:08d}.h5", step);
  XdmfGrid point_grid{.name = fmt::format("points_{:08d}", step), .time = time, .geometry = {}, .attributes = {}};
  XdmfGrid node_grid{.name = fmt::format("nodes_{:08d}", step), .time = time, .geometry = {}, .attributes = {}};

  AtomicFile h5_file(dir_ / file);
  Hdf5Writer h5(h5_file.temporaryPath());
  h5.writeAttribute("time", time);
  h5.writeAttribute("step", static_cast<std::int64_t>(step));
  writePoints(h5, file, points, point_grid);
  writeNodes(h5, file, nodes, node_grid);
  h5.close();
  h5_file.commit();

  // Update copies, so that a failed XDMF write leaves this writer as it was.
  std::vector<XdmfGrid> point_grids = point_grids_, node_grids = node_grids_;
  record(point_grids, std::move(point_grid));
  record(node_grids, std::move(node_grid));
  writeTextAtomically(dir_ / "points.xdmf", temporalPolyvertexXdmf("points", point_grids));
  writeTextAtomically(dir_ / "nodes.xdmf", temporalPolyvertexXdmf("nodes", node_grids));
  point_grids_ = std::move(point_grids);
  node_grids_ = std::move(node_grids);
}

void FieldWriter::restoreSeries(std::vector<XdmfGrid> point_grids, std::vector<XdmfGrid> node_grids) {
  writeTextAtomically(dir_ / "points.xdmf", temporalPolyvertexXdmf("points", point_grids));
  writeTextAtomically(dir_ / "nodes.xdmf", temporalPolyvertexXdmf("nodes", node_grids));
  point_grids_ = std::move(point_grids);
  node_grids_ = std::move(node_grids);
}

}  // namespace kessler::io
