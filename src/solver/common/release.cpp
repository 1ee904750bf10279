#include "solver/common/release.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cstring>
#include <limits>

namespace kessler {

namespace {

bool byId(const DebrisRelease::Member& a, const DebrisRelease::Member& b) {
  return a.id < b.id;
}

// Every rank's `mine` (one process: itself), in id order.
std::vector<DebrisRelease::Member> everyRanks(const std::vector<DebrisRelease::Member>& mine, const Share& share) {
  using Member = DebrisRelease::Member;
  if (!share.comm || share.comm->size() == 1) return mine;
  std::vector<Member> all;
  const auto bytes = std::as_bytes(std::span<const Member>(mine));
  for (const std::vector<std::byte>& theirs : share.comm->allGather(bytes)) {
    KESSLER_VERIFY(theirs.size() % sizeof(Member) == 0, "release: a message of {} bytes", theirs.size());
    const std::size_t at = all.size();
    all.resize(at + theirs.size() / sizeof(Member));
    if (!theirs.empty()) std::memcpy(static_cast<void*>(all.data() + at), theirs.data(), theirs.size());
  }
  std::sort(all.begin(), all.end(), byId);
  return all;
}

}  // namespace

LocalIndex DebrisRelease::apply(ParticleState& model, const Share& share) {
  PointStore& points = model.points;
  const LocalIndex np = points.owned;
  std::vector<Member> mine;
  LocalIndex released = 0;
  for (LocalIndex p = 0; p < np; ++p)
    if (share.own(p) && points.failed(p) && points.stress[p].trace() == 0.0) {
      if (!exchange_) {  // released where it is, with the velocity its method gives it
        points.carrier[p] = -1;
        points.stress[p].setZero();
        points.viscous_pressure[p] = 0.0;
        ++released;
        continue;
      }
      Member m;
      m.id = points.id[p];
      m.x = points.x[p];
      m.eps = erosion_radius_ * points.spacing(p);
      m.body = points.body[p];
      mine.push_back(m);
    }
  if (!exchange_) return released;
  const std::vector<Member> releases = everyRanks(mine, share);
  if (releases.empty()) return 0;
  std::vector<Member> members;
  std::vector<LocalIndex> local;
  collect(points, share, releases, members, local);
  members_ = everyRanks(members, share);

  x_.resize(members_.size());
  double reach = 0.0;
  for (std::size_t k = 0; k < members_.size(); ++k) {
    x_[k] = members_[k].x;
    reach = std::max(reach, members_[k].eps);
  }
  cells_.build(x_, static_cast<LocalIndex>(x_.size()), reach);
  for (std::size_t k = 0; k < members_.size(); ++k)
    if (members_[k].releasing) release(k);

  for (const LocalIndex p : local) {
    Member key;
    key.id = points.id[p];
    const auto m = std::lower_bound(members_.begin(), members_.end(), key, byId);
    KESSLER_VERIFY(m != members_.end() && m->id == key.id, "release: point {} left its ball's copy", key.id);
    points.v[p] = m->v;
    points.energy[p] = m->energy;
    if (!m->releasing) continue;
    points.carrier[p] = -1;
    points.stress[p].setZero();
    points.viscous_pressure[p] = 0.0;
  }
  return static_cast<LocalIndex>(mine.size());
}

void DebrisRelease::collect(const PointStore& points, const Share& share, const std::vector<Member>& releases,
                            std::vector<Member>& members, std::vector<LocalIndex>& local) {
  std::vector<std::uint8_t> body_releases(
      static_cast<std::size_t>(std::max_element(releases.begin(), releases.end(),
                                                [](const Member& a, const Member& b) { return a.body < b.body; })
                                   ->body) +
          1,
      0);
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  double reach = 0.0;
  std::vector<Vec3> x(releases.size());
  for (std::size_t r = 0; r < releases.size(); ++r) {
    x[r] = releases[r].x;
    lo = lo.cwiseMin(x[r]);
    hi = hi.cwiseMax(x[r]);
    reach = std::max(reach, releases[r].eps);
    body_releases[static_cast<std::size_t>(releases[r].body)] = 1;
  }
  lo.array() -= reach;
  hi.array() += reach;
  CellList near;
  near.build(x, static_cast<LocalIndex>(x.size()), reach);
  members.clear();
  local.clear();
  for (LocalIndex q = 0; q < points.owned; ++q) {
    const Vec3& xq = points.x[q];
    const auto body = static_cast<std::size_t>(points.body[q]);
    if (!share.own(q) || body >= body_releases.size() || !body_releases[body] || (xq.array() < lo.array()).any() ||
        (xq.array() > hi.array()).any())
      continue;
    // In the ball of a releasing point of its body (a margin over the ball's own test: a superset).
    bool in_ball = false;
    near.forEachWithin(xq, reach, [&](LocalIndex r, double d2) {
      const Member& release = releases[static_cast<std::size_t>(r)];
      in_ball = in_ball || (release.body == points.body[q] && d2 <= release.eps * release.eps * (1.0 + 1e-9));
    });
    if (!in_ball) continue;
    Member m;
    m.id = points.id[q];
    m.x = xq;
    m.v = points.v[q];
    m.mass = points.mass[q];
    m.energy = points.energy[q];
    m.body = points.body[q];
    m.debris = points.debris(q) ? 1 : 0;
    m.releasing = !m.debris && points.failed(q) && points.stress[q].trace() == 0.0;
    m.eps = erosion_radius_ * points.spacing(q);
    members.push_back(m);
    local.push_back(q);
  }
}

void DebrisRelease::release(std::size_t k) {
  Member& p = members_[k];
  ball_.clear();
  cells_.forEachWithin(p.x, p.eps, [&](LocalIndex i, double) {
    if (members_[static_cast<std::size_t>(i)].body == p.body) ball_.push_back(static_cast<std::size_t>(i));
  });
  std::sort(ball_.begin(), ball_.end());  // id order: the same sums on every rank
  struct Sum {
    double mass = 0.0;
    Vec3 momentum = Vec3::Zero();
  };
  auto add = [](Sum& sum, const Member& q, double sign = 1.0) {
    sum.mass += sign * q.mass;
    sum.momentum += sign * q.mass * q.v;
  };
  Sum ball, left;  // the points of the ball still in the body (before this call), and those that stay
  for (const std::size_t i : ball_) {
    const Member& q = members_[i];
    if (q.debris) continue;
    add(ball, q);
    if (!q.releasing) add(left, q);
  }
  // Who takes the difference: the points that stay; if none does (the last of a region released
  // at once), the ball's other points, released now or debris already, with the debris in the mean.
  const bool lone = left.mass <= 0.0;
  Sum receivers = left;
  if (lone) {
    for (const std::size_t i : ball_)
      if (members_[i].debris) add(ball, members_[i]);
    receivers = ball;
    add(receivers, p, -1.0);
    if (!(receivers.mass > 1e-12 * p.mass)) return;  // nothing near: keep v_p
  }
  const Vec3 mean = ball.momentum / ball.mass;
  const Vec3 dv = p.mass * (p.v - mean) / receivers.mass;
  // The kinetic energy this exchange takes (or gives) stays in the debris as internal energy, so
  // the release conserves the total energy as well as the momentum.
  const double heat = 0.5 * p.mass * (p.v.squaredNorm() - mean.squaredNorm()) - receivers.momentum.dot(dv) -
                      0.5 * receivers.mass * dv.squaredNorm();
  p.energy += heat / p.mass;
  p.v = mean;
  for (const std::size_t i : ball_) {
    Member& q = members_[i];
    if (q.debris ? lone : (lone ? i != k : !q.releasing)) q.v += dv;
  }
}

}  // namespace kessler
