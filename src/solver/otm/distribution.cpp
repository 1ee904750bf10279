#include "solver/otm/distribution.hpp"

#include "parallel/migrate.hpp"
#include "particles/store_fields.hpp"

#include <algorithm>
#include <cstring>
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

template <class Store>
std::size_t entryBytes(Store& store) {
  std::size_t bytes = 0;
  Store::fields(store, [&](const char*, const auto& values, const auto&) {
    bytes += sizeof(typename std::remove_reference_t<decltype(values)>::value_type);
  });
  return bytes;
}

std::size_t travellingBytes() {
  PointStore points;
  std::vector<Vec3> lambda;
  std::vector<double> rate;
  TravellingPoints t(points, lambda, rate);
  return entryBytes(t);
}

std::size_t nodeBytes() {
  NodeStore nodes;
  return entryBytes(nodes);
}

template <class Store>
std::vector<int> owners(const Store& store, const parallel::Partition& partition) {
  std::vector<int> rank(store.x.size());
  for (std::size_t i = 0; i < rank.size(); ++i) rank[i] = partition.owner(store.x[i]);
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
    const std::vector<int> rank_of = owners(store, partition_);
    std::vector<LocalIndex> keep;
    for (std::size_t i = 0; i < rank_of.size(); ++i)
      if (rank_of[i] == comm_.rank()) keep.push_back(static_cast<LocalIndex>(i));
    return keep;
  };
  model.lme_lambda.resize(n, Vec3::Zero());
  std::vector<double> no_rate(n, 0.0);
  TravellingPoints travelling(points, model.lme_lambda, no_rate);
  keepFields(travelling, mine(points));
  keepFields(model.nodes, mine(model.nodes));
  model.connectivity = Connectivity{};
}

void Distribution::rebuild(Model& model, std::vector<double>& volume_rate, double support, double erosion_radius,
                           double contact_reach) {
  PointStore& points = model.points;
  NodeStore& nodes = model.nodes;
  if (volume_rate.size() != points.x.size()) volume_rate.assign(points.x.size(), 0.0);
  model.lme_lambda.resize(points.x.size(), Vec3::Zero());
  TravellingPoints travelling(points, model.lme_lambda, volume_rate);
  points_.dropGhosts(travelling);
  nodes_.dropGhosts(nodes);
  // An impact moves its points, so the balance of the first cut drifts: past `rebalance_at` the
  // points are cut afresh where they are now.
  if (imbalance_ > rebalance_at) {
    partition_.balance(points.x, points.id, std::vector<double>(points.x.size(), 1.0));
    ++rebalances_;
  }
  parallel::migrate(travelling, owners(points, partition_), comm_);
  parallel::migrate(nodes, owners(nodes, partition_), comm_);
  own_points_ = points.owned;
  const double own = static_cast<double>(points.owned);
  const auto total = static_cast<double>(comm_.sum(static_cast<std::int64_t>(points.owned)));
  imbalance_ = comm_.max(own) / std::max(total / comm_.size(), 1.0);
  largest_imbalance_ = std::max(largest_imbalance_, imbalance_);

  double ball = 0.0;  // the largest erosion ball
  for (LocalIndex p = 0; p < points.owned; ++p) ball = std::max(ball, erosion_radius * points.spacing(p));
  support_ = support;
  ball = comm_.max(ball);
  // Points: a rank's own nodes gather from every point whose support holds them (one radius), the
  // volume averaging of its own points reads the points of their nodes' patches (two), the erosion
  // of an own point reads its ball, and debris strikes an own node, or a node an own debris point
  // strikes, whose share of the strike counts its other debris (two contact reaches).
  // Nodes: those of the rows of every point held (two radii and one more), and those an own debris
  // point may strike.
  const std::vector<double> point_reach(static_cast<std::size_t>(points.owned),
                                        std::max({2.0 * support_, ball, 2.0 * contact_reach}));
  const std::vector<double> node_reach(static_cast<std::size_t>(nodes.owned), std::max(3.0 * support_, contact_reach));
  points_.build(travelling, partition_, point_reach, comm_);
  nodes_.build(nodes, partition_, node_reach, comm_);
  model.connectivity = Connectivity{};
}

std::optional<Model> Distribution::gather(const Model& model) const {
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

  // Points with their multipliers, nodes, and each own point's row with node ids for indices.
  std::vector<Vec3> lambda = model.lme_lambda;
  lambda.resize(points.x.size(), Vec3::Zero());
  std::vector<double> no_rate(points.x.size(), 0.0);
  // (Packing only reads: the adaptor holds its arrays by plain reference for the writers too.)
  TravellingPoints travelling(const_cast<PointStore&>(points), lambda, no_rate);
  std::vector<std::byte> point_bytes, node_bytes, row_bytes;
  packFields(travelling, std::span<const LocalIndex>(own_points), point_bytes);
  packFields(nodes, std::span<const LocalIndex>(own_nodes), node_bytes);
  auto append = [&](const auto& value) {
    const std::size_t at = row_bytes.size();
    row_bytes.resize(at + sizeof value);
    std::memcpy(row_bytes.data() + at, &value, sizeof value);
  };
  for (const LocalIndex p : own_points) {
    append(static_cast<std::int64_t>(conn.offset[p + 1] - conn.offset[p]));
    for (Index e = conn.offset[p]; e < conn.offset[p + 1]; ++e) {
      append(nodes.id[conn.node[e]]);
      append(conn.N[e]);
      append(conn.dN[e]);
    }
  }
  const auto points_in = comm_.gather(point_bytes);
  const auto nodes_in = comm_.gather(node_bytes);
  const auto rows_in = comm_.gather(row_bytes);
  if (!comm_.root()) return std::nullopt;

  Model whole;
  static_cast<ParticleState&>(whole) = static_cast<const ParticleState&>(model);
  whole.points = PointStore{};
  std::vector<Vec3> whole_lambda;
  std::vector<double> whole_rate;
  TravellingPoints all(whole.points, whole_lambda, whole_rate);
  resizeFields(all, 0);
  resizeFields(whole.nodes, 0);
  for (std::size_t r = 0; r < points_in.size(); ++r) {
    const std::size_t point_count = points_in[r].size() / travellingBytes();
    unpackFields(all, points_in[r], 0, point_count);
    unpackFields(whole.nodes, nodes_in[r], 0, nodes_in[r].size() / nodeBytes());
  }
  whole.points.owned = whole.points.size();
  whole.nodes.owned = whole.nodes.size();
  // Rows in the order the points arrived, then everything in id order.
  std::vector<std::int64_t> count;
  std::vector<Index> row_ids;
  std::vector<double> row_N;
  std::vector<Vec3> row_dN;
  for (const std::vector<std::byte>& bytes : rows_in) {
    std::size_t at = 0;
    auto take = [&](auto& value) {
      KESSLER_VERIFY(at + sizeof value <= bytes.size(), "gathering rows: a message of {} bytes", bytes.size());
      std::memcpy(static_cast<void*>(&value), bytes.data() + at, sizeof value);
      at += sizeof value;
    };
    while (at < bytes.size()) {
      std::int64_t n = 0;
      take(n);
      count.push_back(n);
      for (std::int64_t k = 0; k < n; ++k) {
        Index id = 0;
        double N = 0.0;
        Vec3 dN;
        take(id);
        take(N);
        take(dN);
        row_ids.push_back(id);
        row_N.push_back(N);
        row_dN.push_back(dN);
      }
    }
  }
  KESSLER_VERIFY(count.size() == whole.points.x.size(), "gathered {} rows for {} points", count.size(),
                 whole.points.x.size());
  std::vector<std::size_t> start(count.size() + 1, 0);
  for (std::size_t i = 0; i < count.size(); ++i) start[i + 1] = start[i] + static_cast<std::size_t>(count[i]);
  const std::vector<LocalIndex> point_order = idOrder(whole.points);
  permuteFields(all, point_order);
  permuteFields(whole.nodes, idOrder(whole.nodes));
  const IdIndex node_index(whole.nodes.id);
  Connectivity& rows = whole.connectivity;
  rows.offset.assign(count.size() + 1, 0);
  for (std::size_t i = 0; i < count.size(); ++i)
    rows.offset[i + 1] = rows.offset[i] + static_cast<Index>(count[static_cast<std::size_t>(point_order[i])]);
  rows.resizeRows(static_cast<std::size_t>(rows.offset.back()));
  for (std::size_t i = 0; i < count.size(); ++i) {
    const std::size_t from = start[static_cast<std::size_t>(point_order[i])];
    for (Index k = 0; k < rows.offset[i + 1] - rows.offset[i]; ++k) {
      const auto e = static_cast<std::size_t>(rows.offset[i] + k), f = from + static_cast<std::size_t>(k);
      const LocalIndex a = node_index.find(row_ids[f]);
      KESSLER_VERIFY(a >= 0, "gathering rows: node {} is no rank's own", row_ids[f]);
      rows.node[e] = a;
      rows.N[e] = row_N[f];
      rows.dN[e] = row_dN[f];
    }
  }
  rows.buildTranspose(whole.nodes.size());
  whole.lme_lambda = std::move(whole_lambda);
  return whole;
}

}  // namespace kessler::otm
