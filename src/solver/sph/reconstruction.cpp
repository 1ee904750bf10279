#include "solver/sph/reconstruction.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kessler::sph {

double elementQuality(const std::array<Vec3, 8>& x) {
  // The twelve edges, each pointing along +x, +y, +z of the reference cube (edge[d][c] from corner
  // c, whose bit d is clear, to its neighbour along d), and their lengths: each corner meets three.
  std::array<std::array<Vec3, 8>, 3> edge;
  std::array<std::array<double, 8>, 3> length;
  for (int d = 0; d < 3; ++d)
    for (int c = 0; c < 8; ++c)
      if (!((c >> d) & 1)) {
        edge[d][c] = x[c | (1 << d)] - x[c];
        length[d][c] = edge[d][c].norm();
      }
  double quality = std::numeric_limits<double>::infinity();
  for (int c = 0; c < 8; ++c) {
    Mat3 edges;
    for (int d = 0; d < 3; ++d) edges.col(d) = edge[d][c & ~(1 << d)];
    const double lengths = length[0][c & ~1] * length[1][c & ~2] * length[2][c & ~4];
    quality = std::min(quality, lengths > 0.0 ? edges.determinant() / lengths : -1.0);
  }
  return quality;
}

Reconstruction::Reconstruction(const Model& model) {
  const PointStore& points = model.points;
  const auto n = static_cast<std::size_t>(points.size());
  KESSLER_VERIFY(model.element.size() == n && model.lattices.size() == model.bodies.size(),
                 "reconstruction: {} elements for {} particles, {} lattices for {} bodies", model.element.size(), n,
                 model.lattices.size(), model.bodies.size());
  element_nodes_.assign(n, {-1, -1, -1, -1, -1, -1, -1, -1});
  particle_reference_.assign(n, Vec3::Zero());
  quality_.assign(n, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const LatticeFrame& frame = model.lattices[b];
    if (frame.cell == Vec3::Zero()) continue;
    // The body's nodes on a grid one larger than its elements' extent (of the particles held: a
    // distributed run's rank holds a part).
    std::array<int, 3> lo{0, 0, 0}, hi{0, 0, 0};
    bool held = false;
    for (std::size_t p = 0; p < n; ++p) {
      if (points.body[p] != static_cast<std::int32_t>(b)) continue;
      const std::array<int, 3>& e = model.element[p];
      KESSLER_VERIFY(e[0] >= 0 && e[1] >= 0 && e[2] >= 0,
                     "reconstruction: particle {} of a lattice body has no element", points.id[p]);
      for (int a = 0; a < 3; ++a) {
        lo[a] = held ? std::min(lo[a], e[a]) : e[a];
        hi[a] = held ? std::max(hi[a], e[a] + 2) : e[a] + 2;
      }
      held = true;
    }
    const std::array<int, 3> size{hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    std::vector<LocalIndex> at(static_cast<std::size_t>(size[0]) * size[1] * size[2], -1);
    for (std::size_t p = 0; p < n; ++p) {
      if (points.body[p] != static_cast<std::int32_t>(b)) continue;
      const std::array<int, 3>& e = model.element[p];
      particle_reference_[p] = frame.origin + (Vec3(e[0], e[1], e[2]) + Vec3::Constant(0.5)).cwiseProduct(frame.cell);
      for (int c = 0; c < 8; ++c) {
        const int i = e[0] + (c & 1), j = e[1] + ((c >> 1) & 1), k = e[2] + ((c >> 2) & 1);
        LocalIndex& node = at[(static_cast<std::size_t>(k - lo[2]) * size[1] + (j - lo[1])) * size[0] + (i - lo[0])];
        if (node < 0) {
          node = static_cast<LocalIndex>(id_.size());
          id_.push_back(static_cast<Index>(id_.size()));
          body_.push_back(static_cast<std::int32_t>(b));
          reference_.push_back(frame.origin + Vec3(i, j, k).cwiseProduct(frame.cell));
          node_elements_.push_back({-1, -1, -1, -1, -1, -1, -1, -1});
        }
        element_nodes_[p][c] = node;
        node_elements_[node][c] = static_cast<LocalIndex>(p);
      }
    }
  }
  x_ = reference_;
  v_.assign(x_.size(), Vec3::Zero());
  mass_.assign(x_.size(), 0.0);
}

void Reconstruction::rebuild(const Model& model) {
  const PointStore& points = model.points;
  const auto nodes = static_cast<LocalIndex>(x_.size());
#pragma omp parallel for schedule(static)
  for (LocalIndex a = 0; a < nodes; ++a) {
    const std::array<LocalIndex, 8>& elements = node_elements_[a];
    int intact = 0, present = 0;
    for (const LocalIndex p : elements) {
      present += p >= 0;
      intact += p >= 0 && !points.unlinked(p);
    }
    // Beside failed material only: from every element, failed ones too (it is drawn, never judged).
    const bool all = intact == 0;
    Vec3 x = Vec3::Zero(), v = Vec3::Zero();
    for (const LocalIndex p : elements) {
      if (p < 0 || (!all && points.unlinked(p))) continue;
      x += intact == 8 ? points.x[p] : Vec3(points.x[p] + points.F[p] * (reference_[a] - particle_reference_[p]));
      v += points.v[p];
    }
    const int count = all ? present : intact;
    x_[a] = x / count;
    v_[a] = v / count;
  }
}

LocalIndex Reconstruction::failDistorted(Model& model, double min_quality, const Share& share) {
  PointStore& points = model.points;
  std::vector<std::uint8_t> fail(static_cast<std::size_t>(points.owned), 0);
#pragma omp parallel for schedule(static)
  for (LocalIndex p = 0; p < points.owned; ++p) {
    const std::array<LocalIndex, 8>& nodes = element_nodes_[p];
    // (A ghost's element may lack nodes this rank cannot rebuild: its owner judges it.)
    if (nodes[0] < 0 || points.unlinked(p) || !share.own(p)) {
      quality_[p] = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    std::array<Vec3, 8> corners;
    for (int c = 0; c < 8; ++c) corners[c] = x_[nodes[c]];
    const double quality = elementQuality(corners);
    quality_[p] = quality;
    fail[p] = !(quality >= min_quality);
  }
  // The element fails, not its material: the particle keeps its state and strength (a copper Taylor
  // bar's rim shears through the threshold without fracture), and belongs to no fragment.
  std::int64_t failed = 0;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (!fail[p]) continue;
    points.loose[p] = 1;
    ++failed;
  }
  return static_cast<LocalIndex>(share.sum(failed));
}

std::vector<double> Reconstruction::latticeReach(const Model& model, const Share& share) const {
  // (One ring beyond none: the farthest intact particle whose element shares a node with its own.)
  return extendReach(model, std::vector<double>(static_cast<std::size_t>(model.points.owned), 0.0), share);
}

std::vector<double> Reconstruction::extendReach(const Model& model, const std::vector<double>& reach,
                                                const Share& share) const {
  const PointStore& points = model.points;
  std::vector<double> further(static_cast<std::size_t>(points.owned), 0.0);
#pragma omp parallel for schedule(static)
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (element_nodes_[p][0] < 0 || points.unlinked(p) || !share.own(p)) continue;
    double farthest = reach[p];
    for (const LocalIndex node : element_nodes_[p])
      for (const LocalIndex q : node_elements_[node])
        if (q >= 0 && q != p && !points.unlinked(q))
          farthest = std::max(farthest, (points.x[q] - points.x[p]).norm() + reach[q]);
    further[p] = farthest;
  }
  return further;
}

NodeCloud Reconstruction::cloud() const {
  // Not the bodies' surfaces: SPH's walls and contact act on the particles' cells (node_cloud.hpp).
  return {id_, body_, x_, v_, mass_, static_cast<LocalIndex>(x_.size()), false};
}

}  // namespace kessler::sph
