#include "solver/otm/neighbourhoods.hpp"

#include "approx/lme.hpp"
#include "core/error.hpp"
#include "core/exact_sum.hpp"
#include "core/timer.hpp"
#include "solver/common/debris_contact.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kessler::otm {

void Neighbourhoods::buildOccluders(const Model& model, double reach) {
  const PointStore& points = model.points;
  eroded_x_.clear();
  eroded_body_.clear();
  intact_x_.clear();
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  double spacing_sum = 0.0;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (points.broken[p]) continue;
    lo = lo.cwiseMin(points.x[p]);
    hi = hi.cwiseMax(points.x[p]);
    spacing_sum += points.spacing(p);
    intact_x_.push_back(points.x[p]);
  }
  lo.array() -= reach;
  hi.array() += reach;
  // Debris that has flown away from every intact point hides nothing.
  for (LocalIndex q = 0; q < points.owned; ++q) {
    const Vec3& x = points.x[q];
    if (!points.broken[q] || (x.array() < lo.array()).any() || (x.array() > hi.array()).any()) continue;
    eroded_x_.push_back(x);
    eroded_body_.push_back(points.body[q]);
  }
  if (eroded_x_.empty() || intact_x_.empty()) {
    eroded_x_.clear();
    return;
  }
  const double spacing = spacing_sum / static_cast<double>(intact_x_.size());
  eroded_cells_.build(eroded_x_, static_cast<LocalIndex>(eroded_x_.size()), reach);
  intact_cells_.build(intact_x_, static_cast<LocalIndex>(intact_x_.size()), spacing);
}

void Neighbourhoods::collectOccluders(const Vec3& xp, int body, double radius, Scratch& s) const {
  s.occluders.clear();
  if (eroded_x_.empty()) return;
  eroded_cells_.forEachWithin(xp, radius, [&](LocalIndex k, double) {
    if (eroded_body_[k] == body) s.occluders.push_back(eroded_x_[k]);
  });
}

bool Neighbourhoods::hidden(const Vec3& xp, const Vec3& xa, double spacing, const Scratch& s) const {
  const Vec3 d = xa - xp;
  const double length2 = d.squaredNorm();
  // A sample in eroded material lies within about half a spacing of an eroded point.
  const double spacing2 = 0.5625 * spacing * spacing;
  // Most segments pass no eroded point that near: nothing to sample.
  bool near = false;
  for (const Vec3& e : s.occluders) {
    const Vec3 f = e - xp;
    const double t = length2 > 0.0 ? std::clamp(f.dot(d) / length2, 0.0, 1.0) : 0.0;
    if ((f - t * d).squaredNorm() < spacing2) {
      near = true;
      break;
    }
  }
  if (!near) return false;
  // Samples at a quarter, half and three quarters: a band one point thick takes more than a quarter of
  // any segment across it within the cut-off radius (2.3 h).
  constexpr int samples = 4;
  for (int k = 1; k < samples; ++k) {
    const Vec3 y = xp + (static_cast<double>(k) / samples) * d;
    double eroded2 = spacing2;
    for (const Vec3& e : s.occluders) eroded2 = std::min(eroded2, (e - y).squaredNorm());
    if (eroded2 >= spacing2) continue;
    bool intact_nearer = false;
    intact_cells_.forEachWithin(y, std::sqrt(eroded2), [&](LocalIndex, double) { intact_nearer = true; });
    if (!intact_nearer) return true;
  }
  return false;
}

int Neighbourhoods::gather(const Model& model, LocalIndex p, double scale, bool visibility, Scratch& s) const {
  const NodeStore& nodes = model.nodes;
  const PointStore& points = model.points;
  const double h = spacing_[p];
  const int own = points.body[p];
  // A sliding contact keeps the bodies' neighbourhoods apart (solver/common/sliding_contact.hpp).
  const double contact2 =
      settings_.contact.sliding() ? -1.0 : settings_.contact_distance * settings_.contact_distance * h * h;
  double radius = scale * (h * cutoff_per_spacing_);
  for (int attempt = 0;; ++attempt) {
    // Seizing contact (solver/common/contact.hpp): another body's nodes count only once that
    // body's nearest node lies within the contact distance.
    s.contact.start();
    s.node.clear();
    cells_.forEachWithin(points.x[p], radius, [&](LocalIndex a, double d2) {
      s.contact.see(own, nodes.body[a], d2);
      s.node.push_back(a);
    });
    s.contact.settle(s.node, nodes.body, own, contact2);
    s.visible = s.node.size();
    if (visibility) {
      collectOccluders(points.x[p], own, radius, s);
      if (!s.occluders.empty()) {
        const auto hidden_begin = std::stable_partition(s.node.begin(), s.node.end(), [&](LocalIndex a) {
          return nodes.body[a] != own || !hidden(points.x[p], nodes.x[a], h, s);
        });
        s.visible = static_cast<std::size_t>(hidden_begin - s.node.begin());
      }
    }
    if (static_cast<int>(s.visible) >= settings_.min_neighbours || attempt == 12) break;
    radius *= 1.25;
  }
  s.radius = radius;
  return static_cast<int>(s.node.size());
}

lme::Result Neighbourhoods::shapeFunctionsAt(Model& model, LocalIndex p, std::span<const LocalIndex> row,
                                             std::span<double> N, std::span<Vec3> dN, Scratch& s, double h,
                                             double gamma_scale) const {
  const PointStore& points = model.points;
  s.offsets.resize(row.size());
  for (std::size_t i = 0; i < row.size(); ++i) s.offsets[i] = points.x[p] - model.nodes.x[row[i]];
  // Nodes nearly coplanar as seen from the point (lme::min_covariance) are refused: failed material
  // is retried or released, intact material retried (retryPoints).
  return lme::shapeFunctions(s.offsets, lme::beta(gamma_scale * settings_.lme_gamma, h), h, model.lme_lambda[p], N, dN,
                             true);
}

// A point near a strongly compressed or re-entrant surface can fall outside the hull of the nodes
// within its cut-off, or so near its edge that their covariance is nearly singular
// (lme::min_covariance) and its gradients would fling its nodes. It is retried from lambda = 0 with
// radii 1.5, 2.25 and 3.375 times larger and gamma 1, 1/2 and 1/4 times the settings' (without the
// visibility test). A failed point that stays so is released; an intact one takes the
// best-conditioned of its attempts, the first included, and the run stops only if none converged.
// Rare, so the connectivity is then rebuilt with the retried rows (not at all when every retried
// point keeps its first row).
Neighbourhoods::Pending Neighbourhoods::retryPoints(Model& model, const Share& share) {
  PointStore& points = model.points;
  Connectivity& conn = model.connectivity;
  const LocalIndex np = points.owned;
  Pending pending;
  std::vector<std::pair<LocalIndex, double>> retry;
  for (const Scratch& s : scratch_) retry.insert(retry.end(), s.retry.begin(), s.retry.end());
  if (retry.empty()) return pending;
  std::sort(retry.begin(), retry.end());  // in point order, as the rows

  Scratch& s = scratch_.front();
  s.N.clear();
  s.dN.clear();
  s.rows.clear();
  std::vector<std::size_t> start(retry.size() + 1, 0);
  std::vector<char> kept(retry.size(), 0);  // the point keeps the row of its first attempt
  for (std::size_t k = 0; k < retry.size(); ++k) {
    // Plain names, not a structured binding: the lambda below captures them (C++20 allows it, clang 14
    // does not).
    const LocalIndex p = retry[k].first;
    const double first_covariance = retry[k].second;
    lme::Result r;
    int n = 0;
    double radius = radius_[p];
    auto attempt = [&](int i) {
      n = gather(model, p, std::pow(1.5, i), false, s);
      radius = s.radius;
      const auto size = static_cast<std::size_t>(n);
      s.N.resize(start[k] + size);
      s.dN.resize(start[k] + size);
      model.lme_lambda[p].setZero();  // the warm start may be what failed
      // Smoother shape functions too (gamma halved at each attempt): a point squeezed into a layer
      // of nodes (against a rigid wall, say) sees the nodes beyond the layer with weights
      // exp(-gamma (d/h)^2) that vanish at gamma = 4, and its covariance turns singular.
      r = shapeFunctionsAt(model, p, s.node, std::span<double>(s.N.data() + start[k], size),
                           std::span<Vec3>(s.dN.data() + start[k], size), s, spacing_[p], std::pow(0.5, i - 1));
    };
    double best = first_covariance;  // of the best ill-conditioned attempt so far (0: the first)
    int best_attempt = first_covariance >= 0.0 ? 0 : -1;
    for (int i = 1; i < 4; ++i) {
      attempt(i);
      if (r.status == lme::Status::converged) break;
      if (r.status == lme::Status::ill_conditioned && r.covariance > best) {
        best = r.covariance;
        best_attempt = i;
      }
    }
    // An intact point outside the hull of every neighbourhood tried (the nodes around it have moved
    // more than three supports away) has torn from its body: it fails and leaves with the failed.
    // (Its state changes once the search is kept: apply().)
    const bool torn = !points.failed(p) && best_attempt < 0 &&
                      (r.status == lme::Status::outside_hull || r.status == lme::Status::no_nodes) &&
                      points.x[p].allFinite();
    if (torn) pending.torn.push_back(p);
    if (r.status != lme::Status::converged && (points.failed(p) || torn)) {
      // Failed material outside the hull of every neighbourhood (or at its very edge) is leaving
      // its body: released to fly on (a zero row), with the velocity it has.
      std::fill(s.N.begin() + static_cast<std::ptrdiff_t>(start[k]), s.N.end(), 0.0);
      std::fill(s.dN.begin() + static_cast<std::ptrdiff_t>(start[k]), s.dN.end(), Vec3::Zero());
      pending.released.push_back(p);
    } else if (r.status != lme::Status::converged && best_attempt == 0) {
      kept[k] = 1;  // intact, and no retry is better conditioned than the first attempt
      s.N.resize(start[k]);
      s.dN.resize(start[k]);
      start[k + 1] = start[k];
      continue;
    } else if (r.status != lme::Status::converged && best_attempt > 0) {
      if (best_attempt != 3) attempt(best_attempt);  // intact: the best-conditioned retry
    } else if (r.status != lme::Status::converged && pending.failed < 0 && share.own(p)) {
      pending.failed = p;
      pending.failure = r;
      // A point whose own position is not finite finds no nodes: say what is wrong with it.
      if (!points.x[p].allFinite()) pending.failure.status = lme::Status::not_finite;
    }
    radius_[p] = radius;
    s.rows.insert(s.rows.end(), s.node.begin(), s.node.begin() + n);
    start[k + 1] = start[k] + static_cast<std::size_t>(n);
    count_[p] = n;
  }
  if (std::all_of(kept.begin(), kept.end(), [](char c) { return c != 0; })) return pending;
  // New rows in point order: the old rows of the points that converged or kept theirs, the retried ones.
  Connectivity rebuilt;
  rebuilt.offset.assign(static_cast<std::size_t>(np) + 1, 0);
  for (LocalIndex p = 0; p < np; ++p) rebuilt.offset[p + 1] = rebuilt.offset[p] + count_[p];
  const auto entries = static_cast<std::size_t>(rebuilt.offset[np]);
  rebuilt.node.resize(entries);
  rebuilt.N.resize(entries);
  rebuilt.dN.resize(entries);
  auto copyRow = [&](const LocalIndex* node, const double* N, const Vec3* dN, Index length, Index to) {
    std::copy_n(node, length, rebuilt.node.begin() + to);
    std::copy_n(N, length, rebuilt.N.begin() + to);
    std::copy_n(dN, length, rebuilt.dN.begin() + to);
  };
  std::size_t k = 0;
  for (LocalIndex p = 0; p < np; ++p) {
    const Index to = rebuilt.offset[p];
    if (k < retry.size() && retry[k].first == p && !kept[k]) {
      copyRow(s.rows.data() + start[k], s.N.data() + start[k], s.dN.data() + start[k], count_[p], to);
    } else {
      const Index from = conn.offset[p];
      copyRow(conn.node.data() + from, conn.N.data() + from, conn.dN.data() + from, count_[p], to);
    }
    if (k < retry.size() && retry[k].first == p) ++k;
  }
  conn.offset = std::move(rebuilt.offset);
  conn.node = std::move(rebuilt.node);
  conn.N = std::move(rebuilt.N);
  conn.dN = std::move(rebuilt.dN);
  return pending;
}

bool Neighbourhoods::update(Model& model, const Share& share, const Share& node_share, double halo_radius,
                            std::span<const std::uint8_t> searched) {
  NodeStore& nodes = model.nodes;
  PointStore& points = model.points;
  Connectivity& conn = model.connectivity;
  const LocalIndex np = points.owned;
  KESSLER_VERIFY(searched.empty() || searched.size() == static_cast<std::size_t>(np),
                 "{} points to search or not for {} points", searched.size(), np);
  auto rowless = [&](LocalIndex p) {
    return points.debris(p) || (!searched.empty() && !searched[static_cast<std::size_t>(p)]);
  };

  Stopwatch watch;
  // Cells of the mean cut-off radius of the intact points: a query with a larger radius visits more
  // cells, so this is only about cost. The largest radius would let a few strongly expanded points
  // (release waves, spall) make the cells, and so every query, far too large. Deterministic sums
  // whatever the thread count.
  const std::size_t bodies = model.bodies.size();
  cutoff_per_spacing_ = lme::cutoffRadius(settings_.lme_gamma, 1.0, settings_.lme_tolerance);
  spacing_.resize(static_cast<std::size_t>(np));
  radius_.assign(static_cast<std::size_t>(np), 0.0);
  if (share.comm) lambda_before_ = model.lme_lambda;
#pragma omp parallel for schedule(static)
  for (LocalIndex p = 0; p < np; ++p) spacing_[p] = points.spacing(p);
  const Eigen::Vector2d sum = ownSums<2>(share, np, [&](LocalIndex p) {
    return points.broken[p] ? Eigen::Vector2d(0.0, 0.0) : Eigen::Vector2d(spacing_[p], 1.0);
  });
  const double spacing_sum = sum[0];
  const auto intact = static_cast<LocalIndex>(sum[1]);
  const double cell_size =
      intact > 0 ? lme::cutoffRadius(settings_.lme_gamma, spacing_sum / intact, settings_.lme_tolerance) : 1.0;
  double node_cell = std::max(cell_size, 1e-300);
  if (share.comm) {
    std::int64_t own = 0;
    for (LocalIndex a = 0; a < nodes.size(); ++a) own += node_share.own(a) ? 1 : 0;
    node_cell = agreedCellSize(nodes.x, nodes.size(), own, node_cell, share);
  }
  cells_.build(nodes.x, nodes.size(), node_cell, /*enlarge=*/!share.comm);
  if (settings_.crack_visibility) buildOccluders(model, cell_size);

  const int threads = omp_get_max_threads();
  scratch_.resize(static_cast<std::size_t>(threads));
  count_.assign(static_cast<std::size_t>(np), 0);
  visible_.resize(static_cast<std::size_t>(np));
  conn.offset.assign(static_cast<std::size_t>(np) + 1, 0);
  double shape_time = 0.0;
  constexpr LocalIndex chunk = 256;
  const LocalIndex chunks = (np + chunk - 1) / chunk;
  chunk_thread_.resize(static_cast<std::size_t>(chunks));
  chunk_start_.resize(static_cast<std::size_t>(chunks));

  // Two passes, so that the shape functions are written straight into the connectivity (a copy
  // per thread would double the largest arrays of a run): the search first, keeping only the
  // node lists, then the shape functions at their final place once the offsets are known.
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    Scratch& s = scratch_[static_cast<std::size_t>(t)];
    s.contact.reset(bodies);
    s.retry.clear();
    // Chunks of points, dynamically scheduled (points near cracks cost more: the visibility
    // test); a chunk's node lists go to the searching thread's rows, in point order, and the
    // chunk remembers which thread and where.
    s.rows.clear();
#pragma omp for schedule(dynamic, 1)
    for (LocalIndex c = 0; c < chunks; ++c) {
      chunk_thread_[c] = t;
      chunk_start_[c] = s.rows.size();
      const LocalIndex end = std::min<LocalIndex>(np, (c + 1) * chunk);
      for (LocalIndex p = c * chunk; p < end; ++p) {
        // Debris has no row (solver/common/debris_contact.hpp); failed points search as intact ones.
        if (rowless(p)) {
          s.node.clear();
          count_[p] = visible_[p] = 0;
        } else {
          count_[p] = gather(model, p, 1.0, settings_.crack_visibility, s);
          visible_[p] = static_cast<int>(s.visible);
          radius_[p] = s.radius;
        }
        s.rows.insert(s.rows.end(), s.node.begin(), s.node.end());
      }
    }
#pragma omp barrier
#pragma omp single
    {
      for (LocalIndex p = 0; p < np; ++p) conn.offset[p + 1] = conn.offset[p] + count_[p];
      const auto entries = static_cast<std::size_t>(conn.offset[np]);
      conn.resizeRows(entries);
    }
    // Each point's row and shape functions depend on nothing but the point, so any schedule gives
    // the same result: dynamic, since the cost varies (debris costs nothing, contact rows
    // are longer). The row comes from the node lists of the thread that searched the point's chunk.
    Stopwatch shape_watch;
#pragma omp for schedule(dynamic, 256) nowait
    for (LocalIndex p = 0; p < np; ++p) {
      if (rowless(p)) continue;
      const LocalIndex c = p / chunk;
      const Index first = conn.offset[p];
      const auto n = static_cast<std::size_t>(count_[p]);
      const LocalIndex* row = scratch_[static_cast<std::size_t>(chunk_thread_[c])].rows.data() + chunk_start_[c] +
                              (first - conn.offset[c * chunk]);
      std::copy_n(row, n, conn.node.begin() + first);
      // Over the visible nodes; the hidden ones, at the end of the row, get zero weight. A point
      // that lies outside the hull of its visible nodes (boxed in by eroded points rather than
      // facing a crack) takes them all.
      const auto visible = static_cast<std::size_t>(visible_[p]);
      std::fill(conn.N.begin() + first + visible, conn.N.begin() + first + n, 0.0);
      std::fill(conn.dN.begin() + first + visible, conn.dN.begin() + first + n, Vec3::Zero());
      lme::Result r = shapeFunctionsAt(model, p, std::span<const LocalIndex>(row, visible),
                                       std::span<double>(conn.N.data() + first, visible),
                                       std::span<Vec3>(conn.dN.data() + first, visible), s, spacing_[p]);
      if (r.status != lme::Status::converged && visible < n) {
        model.lme_lambda[p].setZero();
        r = shapeFunctionsAt(model, p, std::span<const LocalIndex>(row, n), std::span<double>(conn.N.data() + first, n),
                             std::span<Vec3>(conn.dN.data() + first, n), s, spacing_[p]);
      }
      if (r.status != lme::Status::converged)
        s.retry.emplace_back(p, r.status == lme::Status::ill_conditioned ? r.covariance : -1.0);
    }
    const double my_shape_time = shape_watch.seconds();
#pragma omp critical
    shape_time = std::max(shape_time, my_shape_time);
  }
  const Pending pending = retryPoints(model, share);
  // A distributed run's halo holds what searches up to `halo_radius` around its points need: a
  // search that went further anywhere is done again, from the same state, with a wider halo.
  if (share.comm) {
    double largest = 0.0;
    for (LocalIndex p = 0; p < np; ++p)
      if (share.own(p) && !points.debris(p)) largest = std::max(largest, radius_[p]);
    largest_radius_ = share.max(largest);
    if (largest_radius_ > halo_radius) {
      model.lme_lambda = lambda_before_;
      return false;
    }
  }
  apply(model, share, pending);
  std::vector<std::uint64_t> touching(bodies, 0);
  for (const Scratch& s : scratch_) s.contact.addTouching(touching);
  recordContacts(model, touching);
  if (share.comm) joinContacts(model.bodies, *share.comm);
  conn.buildTranspose(nodes.size(), transpose_scratch_);
  const double total = watch.seconds();
  shape_seconds_ = shape_time;
  search_seconds_ = total - shape_time;
  return true;
}

void Neighbourhoods::apply(Model& model, const Share& share, const Pending& pending) {
  PointStore& points = model.points;
  for (const LocalIndex p : pending.torn) {
    points.fail(p);
    if (share.own(p)) {
      ++torn_;
      torn_mass_ += points.mass[p];
    }
  }
  for (const LocalIndex p : pending.released) {
    points.carrier[p] = -1;
    points.stress[p].setZero();
    points.viscous_pressure[p] = 0.0;
  }
  share.stopTogether(
      pending.failed >= 0,
      [&] {
        const LocalIndex failed = pending.failed;
        const Vec3& x = points.x[failed];
        throw NumericalError(fmt::format(
            "LME shape functions failed at material point {} of body '{}' at ({:.6g}, {:.6g}, {:.6g}) m: {} "
            "({} nodes, residual {:.3g} h after {} iterations)",
            points.id[failed], model.bodies[points.body[failed]].name, x[0], x[1], x[2],
            lme::describe(pending.failure.status), count_[failed], pending.failure.residual,
            pending.failure.iterations));
      },
      "another rank's shape functions failed (its message says where)");
}

}  // namespace kessler::otm
