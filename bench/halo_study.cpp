// Halo study (docs/parallel.md, "Scaling model"): what a rank of a distributed OTM step would fetch
// and send, on Zoltan's RCB subdomains of the hvi bench geometry (an Al sphere of radius 3 mm on a
// 2 mm plate 24 mm wide, quarter model). Run under mpirun; not a test:
//   mpirun -np P kessler_halo_study POINTS [POINTS...]
// For each target number of material points: nodes on a cubic lattice of spacing h filling the
// geometry, material points on one of spacing h / 4.9^(1/3) (OTM's tetrahedral meshes give 4.9
// points per node), each point's support a ball of 1.82 h (what holds hvi-100k's measured 25.2 nodes
// per point at this node density). The points are balanced by RCB with unit work; then, per rank:
// its points; its ghost points (other ranks' points whose support reaches its subdomain); its
// ghost nodes (other ranks' nodes within two support radii: the supports of its points and of its
// ghost points); and its neighbours (the ranks it exchanges with). Printed as the largest rank and
// the mean over ranks.
#include "parallel/communicator.hpp"
#include "parallel/halo.hpp"
#include "parallel/migrate.hpp"
#include "parallel/partition.hpp"
#include "particles/store.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

namespace {

using namespace kessler;
using namespace kessler::parallel;

constexpr double radius = 3e-3, half_width = 12e-3, thickness = 2e-3;
constexpr double points_per_node = 4.9, support_per_spacing = 1.82;

bool inside(const Vec3& x) {
  if (x[0] < 0.0 || x[1] < 0.0) return false;  // the quarter model
  const bool plate = x[0] <= half_width && x[1] <= half_width && x[2] >= -thickness && x[2] <= 0.0;
  const bool sphere = (x - Vec3(0, 0, radius)).norm() <= radius;
  return plate || sphere;
}

// A lattice of spacing s filling the geometry, cell-centred; every rank makes all of it and keeps
// every size()-th entry, so that the balance starts from scattered points.
PointStore lattice(double s, const Communicator& comm) {
  PointStore store;
  const int nx = static_cast<int>(std::ceil(half_width / s)),
            nz = static_cast<int>(std::ceil((2 * radius + thickness) / s));
  std::vector<Vec3> x;
  Index n = 0;
  std::vector<Index> ids;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < nx; ++j)
      for (int i = 0; i < nx; ++i) {
        const Vec3 p((i + 0.5) * s, (j + 0.5) * s, -thickness + (k + 0.5) * s);
        if (!inside(p)) continue;
        if (n % comm.size() == comm.rank()) {
          x.push_back(p);
          ids.push_back(n);
        }
        ++n;
      }
  resizeFields(store, x.size());
  for (std::size_t p = 0; p < x.size(); ++p) {
    store.x[p] = x[p];
    store.id[p] = ids[p];
  }
  return store;
}

struct Spread {
  double largest, mean;
};

Spread spread(const Communicator& comm, double value) {
  ExactSum sum;
  sum.add(value);
  return {comm.max(value), comm.sum(sum) / comm.size()};
}

void study(double target_points, const Communicator& comm) {
  const double volume = std::numbers::pi * radius * radius * radius / 3.0 + half_width * half_width * thickness;
  const double point_spacing = std::cbrt(volume / target_points);
  const double h = point_spacing * std::cbrt(points_per_node);
  const double support = support_per_spacing * h;
  PointStore points = lattice(point_spacing, comm), nodes = lattice(h, comm);
  const Index total_points = comm.sum(std::int64_t{points.owned}), total_nodes = comm.sum(std::int64_t{nodes.owned});

  Partition partition(comm);
  migrate(points, partition.balance(points.x, points.id, std::vector<double>(points.x.size(), 1.0)), comm);
  std::vector<int> node_owner(nodes.x.size());
  for (std::size_t a = 0; a < nodes.x.size(); ++a) node_owner[a] = partition.owner(nodes.x[a]);
  migrate(nodes, node_owner, comm);

  const LocalIndex own_points = points.owned, own_nodes = nodes.owned;  // build() merges the ghosts in
  Halo point_halo, node_halo;
  point_halo.build(points, partition, std::vector<double>(static_cast<std::size_t>(points.owned), support), comm);
  node_halo.build(nodes, partition, std::vector<double>(static_cast<std::size_t>(nodes.owned), 2.0 * support), comm);

  const Spread owned = spread(comm, own_points), ghosts = spread(comm, point_halo.ghosts());
  const Spread ghost_nodes = spread(comm, node_halo.ghosts()), owned_nodes = spread(comm, own_nodes);
  const Spread neighbours = spread(comm, std::max(point_halo.neighbours(), node_halo.neighbours()));
  if (comm.root())
    fmt::print(
        "{:>3} ranks {:>9} points {:>8} nodes (h {:.4g} mm, support {:.4g} mm): per rank, largest / mean: points "
        "{:.0f} / {:.0f}, ghost points {:.0f} / {:.0f} ({:.1f}% of the mean), nodes {:.0f} / {:.0f}, ghost nodes "
        "{:.0f} / {:.0f}, neighbours {:.0f} / {:.2f}\n",
        comm.size(), total_points, total_nodes, 1e3 * h, 1e3 * support, owned.largest, owned.mean, ghosts.largest,
        ghosts.mean, 100.0 * ghosts.mean / owned.mean, owned_nodes.largest, owned_nodes.mean, ghost_nodes.largest,
        ghost_nodes.mean, neighbours.largest, neighbours.mean);
}

}  // namespace

int main(int argc, char** argv) {
  Session session(argc, argv);
  const Communicator& comm = Communicator::world();
  try {
    for (int i = 1; i < argc; ++i) study(std::atof(argv[i]), comm);
  } catch (const std::exception& e) {
    fmt::print(stderr, "kessler_halo_study: {}\n", e.what());
    return 1;
  }
  return 0;
}
