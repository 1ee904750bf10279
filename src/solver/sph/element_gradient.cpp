#include "solver/sph/element_gradient.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <utility>

namespace kessler::sph {

namespace {

// The gradient of corner c's trilinear shape function at the reference cube's centre, in the cube's
// coordinates (corner c at (+-1, +-1, +-1), bit 0 of c for +x, bit 1 +y, bit 2 +z).
Vec3 cornerSlope(int c) {
  return Vec3((c & 1) ? 0.125 : -0.125, (c & 2) ? 0.125 : -0.125, (c & 4) ? 0.125 : -0.125);
}

Mat3 deviator(const Mat3& t) {
  return t - t.trace() / 3.0 * Mat3::Identity();
}

}  // namespace

void ElementGradient::weigh(const Model& model, const Reconstruction& reconstruction, const Mirrors& mirrors,
                            const std::vector<std::uint8_t>& dirty) {
  const PointStore& points = model.points;
  const auto& node_elements = reconstruction.nodeElements();
  const auto& element_nodes = reconstruction.elementNodes();
  const std::vector<Vec3>& node_reference = reconstruction.nodeReference();
  const std::vector<Vec3>& particle_reference = reconstruction.particleReference();
  const auto nodes = static_cast<LocalIndex>(node_elements.size());
  if (dirty.empty()) weights_.assign(static_cast<std::size_t>(nodes), {});
  const auto intact = [&](LocalIndex q) { return q >= 0 && intact_[static_cast<std::size_t>(q)] != 0; };
#pragma omp parallel for schedule(dynamic, 256)
  for (LocalIndex a = 0; a < nodes; ++a) {
    if (!dirty.empty() && !dirty[a]) continue;
    weights_[a].clear();
    const Vec3& X = node_reference[a];
    LocalIndex any = -1;
    for (const LocalIndex q : node_elements[a]) any = q >= 0 ? q : any;
    if (any < 0) continue;
    const double cell = model.lattices[static_cast<std::size_t>(points.body[any])].cell.maxCoeff();
    // The images that leave the node where it is (it lies on their planes): their elements share it.
    std::vector<std::uint8_t> fixing{0};
    for (std::size_t c = 1; c < mirrors.count(); ++c)
      if ((mirrors.point(X, static_cast<std::uint8_t>(c)) - X).norm() < 1e-9 * cell)
        fixing.push_back(static_cast<std::uint8_t>(c));
    std::vector<std::pair<LocalIndex, std::uint8_t>> own;
    for (const LocalIndex q : node_elements[a])
      if (intact(q))
        for (const std::uint8_t m : fixing) own.emplace_back(q, m);
    std::vector<Weight>& weights = weights_[a];
    if (own.empty()) continue;
    if (own.size() == 8) {
      for (const auto& [q, m] : own) weights.push_back({q, m, 0.125});
      continue;
    }
    // The fit: the node's elements and their neighbours (in index order, the same on every rank).
    std::vector<std::pair<LocalIndex, std::uint8_t>> fit;
    for (const auto& [q, m] : own)
      for (const LocalIndex b : element_nodes[q])
        for (const LocalIndex r : node_elements[b])
          if (intact(r)) fit.emplace_back(r, m);
    std::sort(fit.begin(), fit.end());
    fit.erase(std::unique(fit.begin(), fit.end()), fit.end());
    Eigen::Matrix4d moment = Eigen::Matrix4d::Zero();
    std::vector<Eigen::Vector4d> basis(fit.size());
    std::vector<double> weight(fit.size());
    for (std::size_t k = 0; k < fit.size(); ++k) {
      const Vec3 d = (mirrors.point(particle_reference[fit[k].first], fit[k].second) - X) / cell;
      basis[k] << 1.0, d[0], d[1], d[2];
      weight[k] = std::exp(-d.squaredNorm());
      moment += weight[k] * basis[k] * basis[k].transpose();
    }
    const Eigen::LDLT<Eigen::Matrix4d> ldlt(moment);
    // (Particles on one plane or line cannot place a node off it: the node takes part in nothing.)
    const Eigen::Vector4d pivots = ldlt.vectorD();
    if (ldlt.info() != Eigen::Success || !(pivots.minCoeff() > 1e-8 * pivots.maxCoeff())) continue;
    const Eigen::Vector4d coefficients = ldlt.solve(Eigen::Vector4d(1.0, 0.0, 0.0, 0.0));
    for (std::size_t k = 0; k < fit.size(); ++k)
      weights.push_back({fit[k].first, fit[k].second, weight[k] * basis[k].dot(coefficients)});
  }
}

void ElementGradient::update(const Model& model, const Reconstruction& reconstruction, const Mirrors& mirrors,
                             std::span<const std::uint32_t> touches, long layout) {
  const PointStore& points = model.points;
  const auto n = static_cast<std::size_t>(points.size());
  active_.assign(n, 0);
  if (share_ <= 0.0) return;
  std::vector<std::uint8_t> intact(n);
  for (LocalIndex p = 0; p < points.size(); ++p)
    intact[p] = !points.unlinked(p) && !points.debris(p) && model.element[p][0] >= 0;
  const auto& element_nodes = reconstruction.elementNodes();
  const auto& node_elements = reconstruction.nodeElements();
  if (layout != layout_ || mirrors.count() != images_ || intact.size() != intact_.size()) {
    intact_ = std::move(intact);
    layout_ = layout;
    images_ = mirrors.count();
    weigh(model, reconstruction, mirrors, {});
  } else if (intact != intact_) {
    // A particle's state enters the fits of the nodes of every element that shares a node with its own.
    std::vector<std::uint8_t> dirty(weights_.size(), 0);
    for (std::size_t r = 0; r < n; ++r) {
      if (intact[r] == intact_[r] || element_nodes[r][0] < 0) continue;
      for (const LocalIndex b : element_nodes[r])
        for (const LocalIndex q : node_elements[b])
          if (q >= 0)
            for (const LocalIndex a : element_nodes[q]) dirty[a] = 1;
    }
    intact_ = std::move(intact);
    weigh(model, reconstruction, mirrors, dirty);
  }
  const auto nodes = static_cast<LocalIndex>(weights_.size());
  x_.resize(static_cast<std::size_t>(nodes));
#pragma omp parallel for schedule(static)
  for (LocalIndex a = 0; a < nodes; ++a) {
    Vec3 x = Vec3::Zero();
    for (const Weight& w : weights_[a]) x += w.weight * mirrors.point(points.x[w.particle], w.image);
    x_[a] = x;
  }
  corner_gradient_.resize(n);
  nodes_.resize(n);
#pragma omp parallel for schedule(static)
  for (LocalIndex p = 0; p < points.size(); ++p) {
    if (!intact_[p] || touches[p] != 0) continue;
    const std::array<LocalIndex, 8>& corners = element_nodes[p];
    if (std::any_of(corners.begin(), corners.end(), [&](LocalIndex a) { return weights_[a].empty(); })) continue;
    std::array<Vec3, 8> x;
    for (int c = 0; c < 8; ++c) x[c] = x_[corners[c]];
    // (A hexahedron distorted as far as the reconstruction fails its element: SPH's gradient alone.)
    if (!(elementQuality(x) >= min_quality_)) continue;
    Mat3 J = Mat3::Zero();  // dx / dxi at the centre
    for (int c = 0; c < 8; ++c) J.noalias() += x[c] * cornerSlope(c).transpose();
    if (!(J.determinant() > 0.0)) continue;  // (inverted at the centre: SPH's gradient alone)
    const Mat3 inverse_t = J.inverse().transpose();
    for (int c = 0; c < 8; ++c) corner_gradient_[p][c] = inverse_t * cornerSlope(c);
    nodes_[p] = corners;
    active_[p] = 1;
  }
}

void ElementGradient::moveNodes(std::span<const Vec3> v, const Mirrors& mirrors) {
  if (share_ <= 0.0) return;
  const auto nodes = static_cast<LocalIndex>(weights_.size());
  v_.resize(static_cast<std::size_t>(nodes));
#pragma omp parallel for schedule(static)
  for (LocalIndex a = 0; a < nodes; ++a) {
    Vec3 sum = Vec3::Zero();
    for (const Weight& w : weights_[a]) sum += w.weight * mirrors.vector(v[w.particle], w.image);
    v_[a] = sum;
  }
}

Mat3 ElementGradient::blend(LocalIndex p, const Mat3& L_sph) const {
  Mat3 L_e = Mat3::Zero();
  for (int c = 0; c < 8; ++c) L_e.noalias() += v_[nodes_[p][c]] * corner_gradient_[p][c].transpose();
  return share_ * deviator(L_e) + (1.0 - share_) * deviator(L_sph) + L_sph.trace() / 3.0 * Mat3::Identity();
}

Mat3 ElementGradient::pairStress(LocalIndex p, const Mat3& stress) const {
  return takesPart(p) ? Mat3(stress - share_ * deviator(stress)) : stress;
}

void ElementGradient::addForces(const PointStore& points, const Reconstruction& reconstruction, const Mirrors& mirrors,
                                std::vector<Vec3>& f) {
  if (share_ <= 0.0) return;
  // Each node's force from the hexahedra that take part, -sum V s dev(sigma) grad N_a (the power of
  // the elements' share of the deviator is sum V s dev(sigma) : dev(L_e) = sum V s dev(sigma) : L_e),
  // summed by the node over its corners in order, then from the nodes to the particles their weights
  // move them by.
  const auto n = static_cast<std::size_t>(points.size());
  stress_.resize(n);
#pragma omp parallel for schedule(static)
  for (LocalIndex p = 0; p < points.size(); ++p)
    if (takesPart(p)) stress_[p] = share_ * points.volume[p] * deviator(points.stress[p]);
  const auto& node_elements = reconstruction.nodeElements();
  const auto nodes = static_cast<LocalIndex>(weights_.size());
  force_.resize(weights_.size());
#pragma omp parallel for schedule(static)
  for (LocalIndex a = 0; a < nodes; ++a) {
    Vec3 force = Vec3::Zero();
    for (int c = 0; c < 8; ++c) {
      const LocalIndex p = node_elements[a][c];  // a is corner c of p
      if (p >= 0 && takesPart(p)) force.noalias() -= stress_[p] * corner_gradient_[p][c];
    }
    force_[a] = force;
  }
  for (std::size_t a = 0; a < weights_.size(); ++a)
    for (const Weight& w : weights_[a]) f[w.particle] += w.weight * mirrors.vector(force_[a], w.image);
}

}  // namespace kessler::sph
