#include "solver/sph/distribution.hpp"

#include "parallel/migrate.hpp"
#include "particles/store_fields.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace kessler::sph {

namespace {

// The particles with the integrator's arrays that travel with them. Their positions for the
// partition and the halo (`x`) are folded into the model's side of its mirror planes (Distribution).
struct Travelling {
  Particles particles;
  std::vector<double>& volume_rate;
  std::vector<double>& lattice_reach;
  std::vector<Vec3>& x;
  std::vector<Index>& id;
  LocalIndex& owned;

  Travelling(Model& model, Carried carried, std::vector<Vec3>& folded, const Mirrors& mirrors)
      : particles(model),
        volume_rate(carried.volume_rate),
        lattice_reach(carried.lattice_reach),
        x(folded),
        id(model.points.id),
        owned(model.points.owned) {
    const std::vector<Vec3>& position = model.points.x;
    volume_rate.resize(position.size(), 0.0);
    lattice_reach.resize(position.size(), 0.0);
    folded.resize(position.size());
    for (std::size_t p = 0; p < position.size(); ++p) folded[p] = mirrors.fold(position[p]);
  }

  template <class Store, class Visit>
  static void fields(Store& s, Visit&& visit) {
    Particles::fields(s.particles, visit);
    visit("volume_rate", s.volume_rate, 0.0);
    visit("lattice_reach", s.lattice_reach, 0.0);
    visit("folded", s.x, Vec3::Zero().eval());
  }
};

}  // namespace

Distribution::Distribution(const parallel::Communicator& comm, const MirrorBox& mirrors)
    : comm_(comm), partition_(comm), mirrors_(mirrors, 0.0) {}

void Distribution::split(Model& model, Carried carried) {
  PointStore& points = model.points;
  KESSLER_VERIFY(points.owned == points.size(), "a model split twice (it holds ghosts)");
  Travelling travelling(model, carried, folded_, mirrors_);
  // Each rank offers Zoltan a slice of the particles, so that every particle is cut once.
  const auto n = static_cast<std::size_t>(points.size());
  const auto ranks = static_cast<std::size_t>(comm_.size()), rank = static_cast<std::size_t>(comm_.rank());
  const std::size_t begin = n * rank / ranks, end = n * (rank + 1) / ranks;
  const std::vector<double> work(end - begin, 1.0);
  partition_.balance(std::span<const Vec3>(travelling.x).subspan(begin, end - begin),
                     std::span<const Index>(points.id).subspan(begin, end - begin), work);
  std::vector<LocalIndex> mine;
  for (std::size_t p = 0; p < n; ++p)
    if (partition_.owner(travelling.x[p]) == comm_.rank()) mine.push_back(static_cast<LocalIndex>(p));
  keepFields(travelling, mine);
  own_ = static_cast<LocalIndex>(mine.size());
  ++layout_;
}

bool Distribution::rebuild(Model& model, Carried carried, std::span<const double> work,
                           const std::function<double(LocalIndex)>& reach) {
  Travelling travelling(model, carried, folded_, mirrors_);
  const std::vector<LocalIndex> own = halo_.ownEntries(travelling);
  std::vector<double> own_work(own.size(), 1.0);
  if (work.size() == travelling.x.size())
    for (std::size_t k = 0; k < own.size(); ++k) own_work[k] = work[static_cast<std::size_t>(own[k])];
  const bool rebalance =
      balance_.due(comm_, std::accumulate(own_work.begin(), own_work.end(), 0.0));  // exact: integers
  std::vector<int> owner(own.size());
  bool leaving = false;
  if (!rebalance)
    for (std::size_t k = 0; k < own.size(); ++k) {
      owner[k] = partition_.owner(travelling.x[own[k]]);
      leaving = leaving || owner[k] != comm_.rank();
    }
  bool moved = false;
  if (rebalance || comm_.any(leaving)) {
    halo_.dropGhosts(travelling);  // the own particles stay, in order
    if (rebalance) {
      partition_.balance(travelling.x, travelling.id, own_work);  // the own particles, in the same order
      for (std::size_t k = 0; k < own.size(); ++k) owner[k] = partition_.owner(travelling.x[k]);
      balance_.cut(comm_, own_work, owner);
    }
    parallel::migrate(travelling, owner, comm_);
    moved = true;
  }
  const std::vector<LocalIndex> now = halo_.ownEntries(travelling);
  own_ = static_cast<LocalIndex>(now.size());
  std::vector<double> own_reach(now.size());
  for (std::size_t k = 0; k < now.size(); ++k) own_reach[k] = reach(now[k]);
  const long fetches = halo_.fetches();
  halo_.build(travelling, partition_, own_reach, comm_);
  if (moved || halo_.fetches() != fetches) ++layout_;
  return moved || halo_.fetches() != fetches;
}

void Distribution::refresh(Model& model) const {
  Particles particles(model);
  halo_.refreshFields(particles);
}

std::optional<Model> Distribution::gather(const Model& model) const {
  // (Packing only reads: the adaptor holds its arrays by plain reference for the writers too.)
  const Particles mine(const_cast<Model&>(model));
  const std::vector<LocalIndex> own = halo_.ownEntries(mine);
  Model whole;
  Particles all(whole);
  parallel::gatherById(mine, std::span<const LocalIndex>(own), all, comm_);
  if (!comm_.root()) return std::nullopt;
  whole.bodies = model.bodies;
  whole.materials = model.materials;
  whole.adjacency = model.adjacency;
  whole.adjacency_length0 = model.adjacency_length0;
  whole.lattices = model.lattices;
  return whole;
}

}  // namespace kessler::sph
