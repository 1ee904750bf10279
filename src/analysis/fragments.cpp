#include "analysis/fragments.hpp"

#include "analysis/breakup_model.hpp"
#include "analysis/union_find.hpp"
#include "core/error.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace kessler::analysis {
namespace {

// Estimated initial link length when none was recorded: two face-adjacent regular tets of edge
// h have their barycentres 0.408 h apart.
constexpr double estimated_link_per_spacing = 0.4;

// A point "touches" a symmetry plane when it lies within half its size of it: the tets with a
// face on the plane have their barycentres a quarter of their height (about 0.2 h) from it, so
// their material continues into the mirror image.
int touchMask(const PointStore& points, LocalIndex p, const Mirror& mirror) {
  int mask = 0;
  const double half = 0.5 * points.spacing(p);
  for (int i = 0; i < mirror.planes(); ++i)
    if (std::abs(points.x[p][mirror.axis(i)]) < half) mask |= 1 << i;
  return mask;
}

std::array<double, 3> extentsAlong(const std::vector<Vec3>& positions, const Mat3& frame) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (const Vec3& x : positions) {
    const Vec3 s = frame.transpose() * x;
    lo = lo.cwiseMin(s);
    hi = hi.cwiseMax(s);
  }
  return {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
}

// The statistics of one fragment, from its points (grouped) and their mirror images.
Fragment measureFragment(const ParticleState& model, const std::vector<LocalIndex>& members, const Mirror& mirror) {
  const PointStore& points = model.points;
  int touching = 0;
  for (const LocalIndex p : members) touching |= touchMask(points, p, mirror);
  std::vector<int> images;
  for (int mask = 0; mask < mirror.images(); ++mask)
    if ((mask & ~touching) == 0) images.push_back(mask);

  Fragment f;
  f.body = points.body[members.front()];
  f.material = model.bodies[f.body].material;
  f.points = static_cast<LocalIndex>(members.size());
  f.first_point = members.front();
  f.copies = mirror.images() / static_cast<int>(images.size());
  std::vector<Vec3> positions;
  std::vector<double> weights;
  positions.reserve(members.size() * images.size());
  weights.reserve(members.size() * images.size());
  Vec3 momentum = Vec3::Zero();
  for (const int mask : images) {
    for (const LocalIndex p : members) {
      positions.push_back(mirror.image(points.x[p], mask));
      weights.push_back(points.mass[p]);
      f.mass += points.mass[p];
      f.volume += points.volume[p];
      momentum += points.mass[p] * mirror.image(points.v[p], mask);
    }
  }
  Vec3 first_moment = Vec3::Zero();
  for (std::size_t k = 0; k < positions.size(); ++k) first_moment += weights[k] * positions[k];
  f.centre = first_moment / f.mass;
  f.velocity = momentum / f.mass;
  f.speed = f.velocity.norm();
  const Shape3 shape = characteristicLength(positions, weights, f.volume, static_cast<long>(positions.size()));
  f.extents = shape.extents;
  f.axis = shape.axis;
  f.lc = shape.lc;
  return f;
}

}  // namespace

long FragmentSet::count() const {
  long n = 0;
  for (const Fragment& f : fragments) n += f.copies;
  return n;
}

Shape3 characteristicLength(const std::vector<Vec3>& positions, const std::vector<double>& weights, double volume,
                            long count) {
  KESSLER_VERIFY(!positions.empty() && positions.size() == weights.size() && count > 0,
                 "characteristic length of {} positions with {} weights", positions.size(), weights.size());
  double total = 0.0;
  Vec3 centre = Vec3::Zero();
  for (std::size_t k = 0; k < positions.size(); ++k) {
    total += weights[k];
    centre += weights[k] * positions[k];
  }
  centre /= total;
  Mat3 moments = Mat3::Zero();
  for (std::size_t k = 0; k < positions.size(); ++k) {
    const Vec3 d = positions[k] - centre;
    moments += weights[k] * d * d.transpose();
  }
  // Principal axes suit irregular debris (the NASA caliper measure takes the largest dimension
  // first); where two moments are equal (a cube, a square plate) the principal axes in that
  // plane are arbitrary, and the axis-aligned box is the tighter, meaningful one.
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(moments / total);
  const auto principal = extentsAlong(positions, solver.eigenvectors());
  const auto aligned = extentsAlong(positions, Mat3::Identity());
  const double sum_principal = principal[0] + principal[1] + principal[2];
  const double sum_aligned = aligned[0] + aligned[1] + aligned[2];
  const bool use_principal = sum_principal < sum_aligned;
  const auto& chosen = use_principal ? principal : aligned;
  const Mat3 frame = use_principal ? Mat3(solver.eigenvectors()) : Mat3::Identity();

  // Positions are point centres: each point adds about its own size to the extent.
  const double point_size = std::cbrt(volume / static_cast<double>(count));
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return chosen[a] > chosen[b]; });
  Shape3 shape;
  for (int k = 0; k < 3; ++k) shape.extents[k] = chosen[order[k]] + point_size;
  shape.axis = frame.col(order[0]);
  shape.lc = (shape.extents[0] + shape.extents[1] + shape.extents[2]) / 3.0;
  return shape;
}

namespace {

// The links between the store's points (model.adjacency holds ids), each pair ordered; a link to
// a point the store does not hold has -1 at that end.
std::vector<std::array<LocalIndex, 2>> localLinks(const ParticleState& model) {
  const IdIndex index(model.points.id);
  auto local = [&](Index id) { return index.find(id); };
  std::vector<std::array<LocalIndex, 2>> links(model.adjacency.size());
  for (std::size_t k = 0; k < links.size(); ++k) {
    const LocalIndex a = local(model.adjacency[k][0]), b = local(model.adjacency[k][1]);
    links[k] =
        a < 0 || b < 0 ? std::array<LocalIndex, 2>{-1, -1} : std::array<LocalIndex, 2>{std::min(a, b), std::max(a, b)};
  }
  return links;
}

}  // namespace

std::vector<double> referenceLinkLengths(const ParticleState& model) {
  const std::vector<std::array<LocalIndex, 2>> links = localLinks(model);
  KESSLER_VERIFY(std::none_of(links.begin(), links.end(), [](const auto& l) { return l[0] < 0; }),
                 "fragments: a link joins a point outside the model");
  std::vector<double> lengths(links.size());
  const auto n = static_cast<std::ptrdiff_t>(links.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t k = 0; k < n; ++k)
    lengths[k] = (model.points.x[links[k][1]] - model.points.x[links[k][0]]).norm();
  return lengths;
}

FragmentSet findFragments(const ParticleState& model, const std::vector<double>& reference_lengths,
                          const FragmentOptions& options) {
  const PointStore& points = model.points;
  const LocalIndex n = points.size();
  const std::vector<std::array<LocalIndex, 2>> links = localLinks(model);
  KESSLER_VERIFY(options.link_stretch > 1.0, "fragments: link stretch {} must exceed 1", options.link_stretch);
  KESSLER_VERIFY(reference_lengths.empty() || reference_lengths.size() == links.size(),
                 "fragments: {} reference link lengths for {} links", reference_lengths.size(), links.size());
  const Mirror mirror(options.symmetry_axes);

  FragmentSet set;
  set.link_stretch = options.link_stretch;
  set.reference_lengths = !reference_lengths.empty();
  set.links = static_cast<LocalIndex>(links.size());

  // Which links hold: independent per link, so the parallel loop is deterministic.
  std::vector<std::uint8_t> alive(links.size(), 0);
  const auto link_count = static_cast<std::ptrdiff_t>(links.size());
  std::ptrdiff_t first_bad = link_count;
#pragma omp parallel for schedule(static) reduction(min : first_bad)
  for (std::ptrdiff_t k = 0; k < link_count; ++k) {
    const auto [i, j] = links[k];
    if (i < 0 || j <= i || j >= n) {
      first_bad = std::min(first_bad, k);
      continue;
    }
    if (points.unlinked(i) || points.unlinked(j)) continue;
    const double initial = set.reference_lengths
                               ? reference_lengths[k]
                               : estimated_link_per_spacing * 0.5 * (points.spacing0[i] + points.spacing0[j]);
    alive[k] = (points.x[j] - points.x[i]).norm() < options.link_stretch * initial;
  }
  KESSLER_VERIFY(first_bad == link_count, "fragments: link {} joins points outside the {} of the model", first_bad, n);

  UnionFind sets(n);
  for (std::size_t k = 0; k < links.size(); ++k) {
    if (alive[k])
      sets.unite(links[k][0], links[k][1]);
    else
      ++set.broken_links;
  }

  // Fragments numbered in the order of their first point; members grouped by a counting sort.
  std::vector<LocalIndex> root_label(static_cast<std::size_t>(n), -1);
  set.label.assign(static_cast<std::size_t>(n), -1);
  LocalIndex fragments = 0;
  for (LocalIndex p = 0; p < n; ++p) {
    if (points.unlinked(p)) continue;
    const LocalIndex root = sets.find(p);
    if (root_label[root] < 0) root_label[root] = fragments++;
    set.label[p] = root_label[root];
  }
  std::vector<std::vector<LocalIndex>> members(static_cast<std::size_t>(fragments));
  for (LocalIndex p = 0; p < n; ++p)
    if (set.label[p] >= 0) members[set.label[p]].push_back(p);

  set.fragments.resize(members.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (LocalIndex f = 0; f < fragments; ++f) set.fragments[f] = measureFragment(model, members[f], mirror);

  std::vector<LocalIndex> order(static_cast<std::size_t>(fragments));
  std::iota(order.begin(), order.end(), LocalIndex{0});
  std::sort(order.begin(), order.end(), [&](LocalIndex a, LocalIndex b) {
    const Fragment& x = set.fragments[a];
    const Fragment& y = set.fragments[b];
    return x.mass != y.mass ? x.mass > y.mass : x.first_point < y.first_point;
  });
  std::vector<LocalIndex> rank(order.size());
  std::vector<Fragment> sorted(order.size());
  for (std::size_t r = 0; r < order.size(); ++r) {
    rank[order[r]] = static_cast<LocalIndex>(r);
    sorted[r] = set.fragments[order[r]];
  }
  set.fragments = std::move(sorted);
  set.point_id.assign(points.id.begin(), points.id.begin() + n);
  // Outside the parallel region: the area checks its argument and may throw.
  for (Fragment& f : set.fragments) f.area = nasaFragmentArea(f.lc);
  for (LocalIndex& l : set.label)
    if (l >= 0) l = rank[l];

  set.eroded_mass.assign(model.bodies.size(), 0.0);
  set.body_mass.assign(model.bodies.size(), 0.0);
  for (LocalIndex p = 0; p < n; ++p) {
    const double m = points.mass[p] * mirror.images();
    set.body_mass[points.body[p]] += m;
    if (points.unlinked(p)) set.eroded_mass[points.body[p]] += m;
  }
  return set;
}

std::vector<CumulativeCount> cumulativeDistribution(const FragmentSet& set) {
  std::vector<std::size_t> order(set.fragments.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return set.fragments[a].lc > set.fragments[b].lc; });
  std::vector<CumulativeCount> counts;
  counts.reserve(order.size());
  long total = 0;
  for (const std::size_t f : order) {
    total += set.fragments[f].copies;
    counts.push_back({set.fragments[f].lc, total});
  }
  return counts;
}

}  // namespace kessler::analysis
