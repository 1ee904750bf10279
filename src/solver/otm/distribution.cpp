#include "solver/otm/distribution.hpp"

#include "parallel/migrate.hpp"
#include "particles/store_fields.hpp"
#include "solver/common/debris_contact.hpp"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <type_traits>

namespace kessler::otm {

namespace {

// The point store with the per-point arrays that live beside it and must travel with each point:
// the LME multipliers (the next search's warm start) and the last step's volume rate (the time
// step's bound).
struct TravellingPoints {
  PointStore& points;
  std::vector<Vec3>& lambda;
  std::vector<double>& volume_rate;
  std::vector<Vec3>& x;
  std::vector<Index>& id;
  LocalIndex& owned;

  TravellingPoints(PointStore& p, std::vector<Vec3>& l, std::vector<double>& v)
      : points(p), lambda(l), volume_rate(v), x(p.x), id(p.id), owned(p.owned) {}

  template <class Store, class Visit>
  static void fields(Store& s, Visit&& visit) {
    PointStore::fields(s.points, visit);
    visit("lme_lambda", s.lambda, Vec3::Zero().eval());
    visit("volume_rate", s.volume_rate, 0.0);
  }
};

// The rank whose subdomain holds each of `entries` now.
template <class Store>
std::vector<int> owners(const Store& store, const std::vector<LocalIndex>& entries,
                        const parallel::Partition& partition) {
  std::vector<int> rank(entries.size());
  for (std::size_t k = 0; k < entries.size(); ++k) rank[k] = partition.owner(store.x[entries[k]]);
  return rank;
}

}  // namespace

Distribution::Distribution(const parallel::Communicator& comm) : comm_(comm), partition_(comm) {}

void Distribution::split(Model& model) {
  PointStore& points = model.points;
  KESSLER_VERIFY(points.owned == points.size() && model.nodes.owned == model.nodes.size(),
                 "a model split twice (it holds ghosts)");
  // Each rank offers Zoltan a slice of the points, so that every point is cut once.
  const auto n = static_cast<std::size_t>(points.size());
  const auto ranks = static_cast<std::size_t>(comm_.size()), rank = static_cast<std::size_t>(comm_.rank());
  const std::size_t begin = n * rank / ranks, end = n * (rank + 1) / ranks;
  const std::vector<double> work(end - begin, 1.0);
  partition_.balance(std::span<const Vec3>(points.x).subspan(begin, end - begin),
                     std::span<const Index>(points.id).subspan(begin, end - begin), work);
  auto mine = [&](const auto& store) {
    std::vector<LocalIndex> keep;
    for (std::size_t i = 0; i < store.x.size(); ++i)
      if (partition_.owner(store.x[i]) == comm_.rank()) keep.push_back(static_cast<LocalIndex>(i));
    return keep;
  };
  model.lme_lambda.resize(n, Vec3::Zero());
  std::vector<double> no_rate(n, 0.0);
  TravellingPoints travelling(points, model.lme_lambda, no_rate);
  keepFields(travelling, mine(points));
  keepFields(model.nodes, mine(model.nodes));
  model.connectivity = Connectivity{};
}

// A point's cost in a step, in row entries: its search, shape functions, assembly and point update
// go by the entries of its row (about 0.065 us each on hvi-100k), its material update, erosion and
// time step by the point (about 0.6 us, some 9 entries). Debris has no row.
std::vector<double> Distribution::ownWork(const Model& model, const std::vector<LocalIndex>& own) const {
  constexpr double entries_per_point = 9.0;
  const Connectivity& conn = model.connectivity;
  std::vector<double> work(own.size(), entries_per_point);
  // Before the first search (and after a restart's split) there are no rows: every point alike.
  if (conn.points() != model.points.owned) return work;
  for (std::size_t k = 0; k < own.size(); ++k)
    work[k] += static_cast<double>(conn.offset[own[k] + 1] - conn.offset[own[k]]);
  return work;
}

void Distribution::rebuild(Model& model, std::vector<double>& volume_rate, double support, double erosion_radius,
                           double contact_reach) {
  PointStore& points = model.points;
  NodeStore& nodes = model.nodes;
  if (volume_rate.size() != points.x.size()) volume_rate.assign(points.x.size(), 0.0);
  model.lme_lambda.resize(points.x.size(), Vec3::Zero());
  TravellingPoints travelling(points, model.lme_lambda, volume_rate);
  // Entries that left their subdomain move to its owner, and past the imbalance the points are cut
  // afresh (parallel::Rebalance). Either way the ghosts go first; most steps neither happens, and the
  // halos' build replaces the ghosts in place.
  const std::vector<LocalIndex> own = points_.ownEntries(points);
  const std::vector<double> work = ownWork(model, own);
  const bool rebalance = balance_.due(comm_, std::accumulate(work.begin(), work.end(), 0.0));  // exact: integers
  std::vector<int> point_owner, node_owner;
  bool leaving = false;
  if (!rebalance) {
    point_owner = owners(points, own, partition_);
    node_owner = owners(nodes, nodes_.ownEntries(nodes), partition_);
    for (const std::vector<int>* owner : {&point_owner, &node_owner})
      leaving = leaving || std::any_of(owner->begin(), owner->end(), [&](int r) { return r != comm_.rank(); });
  }
  if (rebalance || comm_.any(leaving)) {
    points_.dropGhosts(travelling);
    nodes_.dropGhosts(nodes);
    if (rebalance) {
      partition_.balance(points.x, points.id, work);  // the own points, in the same order
      point_owner = owners(points, points_.ownEntries(points), partition_);
      balance_.cut(comm_, work, point_owner);
      node_owner = owners(nodes, nodes_.ownEntries(nodes), partition_);
    }
    parallel::migrate(travelling, point_owner, comm_);
    parallel::migrate(nodes, node_owner, comm_);
  }
  const std::vector<LocalIndex> own_points = points_.ownEntries(points);
  own_points_ = static_cast<LocalIndex>(own_points.size());

  double ball = 0.0;  // the largest erosion ball (of the intact points, which alone erode and fill balls)
  for (const LocalIndex p : own_points)
    if (!points.broken[p]) ball = std::max(ball, erosion_radius * points.spacing(p));
  ball = comm_.max(ball);
  // Points: a rank's own nodes gather from every point whose support holds them (one radius), and
  // the erosion of an own point reads its ball; debris has no row, and strikes an own node (one
  // contact reach) if it may strike anything. (The volume averaging of an own point reads the means of its nodes, and
  // debris contact a node's count of strikes and their kick, which their owners send.) Nodes: those of the rows of the
  // points searched (two radii), and those an own debris point may strike.
  std::vector<double> point_reach(own_points.size());
  for (std::size_t k = 0; k < own_points.size(); ++k)
    point_reach[k] = points.debris(own_points[k])
                         ? (mayStrike(points, own_points[k], model.bodies.size()) ? contact_reach : 0.0)
                         : (points.broken[own_points[k]] ? support : std::max(support, ball));
  const std::vector<double> node_reach(static_cast<std::size_t>(nodes.size() - nodes_.ghosts()),
                                       std::max(2.0 * support, contact_reach));
  points_.build(travelling, partition_, point_reach, comm_);
  nodes_.build(nodes, partition_, node_reach, comm_);
  model.connectivity.clear();
  // The ghosts whose rows may hold own nodes (which lie in the region: any that left it moved).
  const parallel::Box region = partition_.region(comm_.rank());
  searched_.assign(points.x.size(), 1);
  for (std::size_t p = 0; p < points.x.size(); ++p) {
    if (!points_.ghost(static_cast<LocalIndex>(p))) continue;
    const Vec3 outside = (region.lo - points.x[p]).cwiseMax(points.x[p] - region.hi).cwiseMax(0.0);
    searched_[p] = outside.norm() <= support ? 1 : 0;
  }
}

std::optional<Model> Distribution::gather(const Model& model, bool rows) const {
  const PointStore& points = model.points;
  const NodeStore& nodes = model.nodes;
  const Connectivity& conn = model.connectivity;
  auto ownOf = [](std::span<const std::uint8_t> ghost, LocalIndex n) {
    std::vector<LocalIndex> own;
    for (LocalIndex i = 0; i < n; ++i)
      if (ghost.empty() || !ghost[static_cast<std::size_t>(i)]) own.push_back(i);
    return own;
  };
  const std::vector<LocalIndex> own_points = ownOf(ghostPoints(), points.owned);
  const std::vector<LocalIndex> own_nodes = ownOf(ghostNodes(), nodes.owned);

  // Points (with their multipliers, for a checkpoint), nodes, and for a checkpoint each own point's
  // row with node ids for indices: its length, then its ids, weights and gradients.
  std::vector<Vec3> lambda = model.lme_lambda;
  lambda.resize(points.x.size(), Vec3::Zero());
  std::vector<double> no_rate(points.x.size(), 0.0);
  // (Packing only reads: the adaptor holds its arrays by plain reference for the writers too.)
  TravellingPoints travelling(const_cast<PointStore&>(points), lambda, no_rate);
  // (Every rank takes part in each gather; the others return after the last.)
  Model whole;
  std::vector<Vec3> whole_lambda;
  std::vector<double> whole_rate;
  TravellingPoints all(whole.points, whole_lambda, whole_rate);
  const std::vector<parallel::MergeSource> point_from =
      rows ? parallel::gatherById(travelling, std::span<const LocalIndex>(own_points), all, comm_)
           : parallel::gatherById(points, std::span<const LocalIndex>(own_points), whole.points, comm_);
  parallel::gatherById(nodes, std::span<const LocalIndex>(own_nodes), whole.nodes, comm_);
  std::vector<std::byte> row_bytes;
  constexpr std::size_t entry_bytes = sizeof(Index) + sizeof(double) + sizeof(Vec3);
  if (rows) {
    std::size_t total = 0;
    for (const LocalIndex p : own_points)
      total += sizeof(std::int64_t) + static_cast<std::size_t>(conn.offset[p + 1] - conn.offset[p]) * entry_bytes;
    row_bytes.resize(total);
    std::byte* at = row_bytes.data();
    auto put = [&](const auto& value) {
      std::memcpy(at, &value, sizeof value);
      at += sizeof value;
    };
    for (const LocalIndex p : own_points) {
      put(static_cast<std::int64_t>(conn.offset[p + 1] - conn.offset[p]));
      for (Index e = conn.offset[p]; e < conn.offset[p + 1]; ++e) put(nodes.id[conn.node[e]]);
      for (Index e = conn.offset[p]; e < conn.offset[p + 1]; ++e) put(conn.N[e]);
      for (Index e = conn.offset[p]; e < conn.offset[p + 1]; ++e) put(conn.dN[e]);
    }
  }
  const auto rows_in = comm_.gather(std::move(row_bytes));
  if (!comm_.root()) return std::nullopt;

  whole.bodies = model.bodies;
  whole.materials = model.materials;
  whole.adjacency = model.adjacency;
  whole.adjacency_length0 = model.adjacency_length0;
  whole.lme_lambda = rows ? std::move(whole_lambda) : std::vector<Vec3>(whole.points.x.size(), Vec3::Zero());
  if (!rows) return whole;

  // Where each point's row starts in the messages, in the order the points arrived.
  struct Row {
    const std::byte* at = nullptr;
    std::int64_t length = 0;
  };
  std::vector<std::vector<Row>> arrived(rows_in.size());  // per rank
  for (std::size_t r = 0; r < rows_in.size(); ++r) {
    const std::vector<std::byte>& bytes = rows_in[r];
    for (const std::byte* at = bytes.data(); at < bytes.data() + bytes.size();) {
      Row row;
      std::memcpy(&row.length, at, sizeof row.length);
      row.at = at + sizeof row.length;
      at = row.at + static_cast<std::size_t>(row.length) * entry_bytes;
      KESSLER_VERIFY(at <= bytes.data() + bytes.size(), "gathering rows: a message of {} bytes", bytes.size());
      arrived[r].push_back(row);
    }
  }
  auto rowOf = [&](std::size_t i) -> const Row& {
    const parallel::MergeSource& f = point_from[i];
    KESSLER_VERIFY(f.list >= 0 && f.k < arrived[static_cast<std::size_t>(f.list)].size(),
                   "gathering rows: no row for point {}", whole.points.id[i]);
    return arrived[static_cast<std::size_t>(f.list)][f.k];
  };
  const IdIndex node_index(whole.nodes.id);
  Connectivity& out = whole.connectivity;
  const std::size_t whole_points = point_from.size();
  out.offset.assign(whole_points + 1, 0);
  for (std::size_t i = 0; i < whole_points; ++i)
    out.offset[i + 1] = out.offset[i] + static_cast<Index>(rowOf(i).length);
  out.resizeRows(static_cast<std::size_t>(out.offset.back()));
  for (std::size_t i = 0; i < whole_points; ++i) {
    const Row& row = rowOf(i);
    const auto n = static_cast<std::size_t>(row.length);
    const auto e = static_cast<std::size_t>(out.offset[i]);
    const std::byte* ids = row.at;
    for (std::size_t k = 0; k < n; ++k) {
      Index id = 0;
      std::memcpy(&id, ids + k * sizeof(Index), sizeof id);
      const LocalIndex a = node_index.find(id);
      KESSLER_VERIFY(a >= 0, "gathering rows: node {} is no rank's own", id);
      out.node[e + k] = a;
    }
    std::memcpy(static_cast<void*>(out.N.data() + e), ids + n * sizeof(Index), n * sizeof(double));
    std::memcpy(static_cast<void*>(out.dN.data() + e), ids + n * (sizeof(Index) + sizeof(double)), n * sizeof(Vec3));
  }
  out.buildTranspose(whole.nodes.size());
  return whole;
}

}  // namespace kessler::otm
