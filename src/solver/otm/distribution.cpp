#include "solver/otm/distribution.hpp"

#include "parallel/migrate.hpp"
#include "particles/store_fields.hpp"

#include <algorithm>

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

// Keeps the entries `keep` of a store (in their order), all owned.
template <class Store>
void keepEntries(Store& store, const std::vector<LocalIndex>& keep) {
  std::vector<std::byte> buffer;
  packFields(store, std::span<const LocalIndex>(keep), buffer);
  resizeFields(store, 0);
  unpackFields(store, buffer, 0, keep.size());
  store.owned = static_cast<LocalIndex>(keep.size());
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
  keepEntries(travelling, mine(points));
  keepEntries(model.nodes, mine(model.nodes));
  model.connectivity = Connectivity{};
}

void Distribution::rebuild(Model& model, std::vector<double>& volume_rate, double cutoff_per_spacing,
                           double erosion_radius, double contact_reach) {
  PointStore& points = model.points;
  NodeStore& nodes = model.nodes;
  if (volume_rate.size() != points.x.size()) volume_rate.assign(points.x.size(), 0.0);
  model.lme_lambda.resize(points.x.size(), Vec3::Zero());
  TravellingPoints travelling(points, model.lme_lambda, volume_rate);
  points_.dropGhosts(travelling);
  nodes_.dropGhosts(nodes);
  parallel::migrate(travelling, owners(points, partition_), comm_);
  parallel::migrate(nodes, owners(nodes, partition_), comm_);

  // The largest support of any point (a point's row holds the nodes within it), and erosion ball.
  double support = 0.0, ball = 0.0;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    ball = std::max(ball, erosion_radius * points.spacing(p));
    if (!points.debris(p)) support = std::max(support, cutoff_per_spacing * points.spacing(p));
  }
  support_ = comm_.max(support);
  ball = comm_.max(ball);
  // Points: a rank's own nodes gather from every point whose support holds them (one radius), the
  // volume averaging of its own points reads the points of their nodes' patches (two), the erosion
  // of an own point reads its ball, and debris strikes an own node, or a node an own debris point
  // strikes, whose share of the strike counts its other debris (two contact reaches).
  // Nodes: those of the rows of every point held (two radii and one more), those a search that
  // widens a support (Neighbourhoods::retryPoints, at most 3.375 times) finds around an own point,
  // and those an own debris point may strike.
  const std::vector<double> point_reach(static_cast<std::size_t>(points.owned),
                                        std::max({2.0 * support_, ball, 2.0 * contact_reach}));
  const std::vector<double> node_reach(static_cast<std::size_t>(nodes.owned), std::max(3.5 * support_, contact_reach));
  points_.build(travelling, partition_, point_reach, comm_);
  nodes_.build(nodes, partition_, node_reach, comm_);
  model.connectivity = Connectivity{};
}

}  // namespace kessler::otm
