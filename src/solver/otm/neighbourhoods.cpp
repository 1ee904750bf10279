#include "solver/otm/neighbourhoods.hpp"

#include "approx/lme.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kessler::otm {

int Neighbourhoods::gather(const Model& model, LocalIndex p, double scale, Scratch& s) const {
  const NodeStore& nodes = model.nodes;
  const PointStore& points = model.points;
  const double h = points.spacing(p);
  const int own = points.body[p];
  const double contact2 = settings_.contact_distance * settings_.contact_distance * h * h;
  double radius = scale * lme::cutoffRadius(settings_.lme_gamma, h, settings_.lme_tolerance);
  for (int attempt = 0;; ++attempt) {
    s.candidates.clear();
    cells_.forEachWithin(points.x[p], radius,
                         [&](LocalIndex a, double d2) { s.candidates.emplace_back(a, d2); });
    // Seizing contact: another body's nodes count only once that body is close enough.
    std::fill(s.nearest_foreign.begin(), s.nearest_foreign.end(), std::numeric_limits<double>::infinity());
    for (const auto& [a, d2] : s.candidates)
      if (nodes.body[a] != own) s.nearest_foreign[nodes.body[a]] = std::min(s.nearest_foreign[nodes.body[a]], d2);
    s.node.clear();
    for (const auto& [a, d2] : s.candidates)
      if (nodes.body[a] == own || s.nearest_foreign[nodes.body[a]] <= contact2) s.node.push_back(a);
    if (static_cast<int>(s.node.size()) >= settings_.min_neighbours || attempt == 12) break;
    radius *= 1.25;
  }
  return static_cast<int>(s.node.size());
}

void Neighbourhoods::update(Model& model) {
  NodeStore& nodes = model.nodes;
  PointStore& points = model.points;
  Connectivity& conn = model.connectivity;
  const LocalIndex np = points.owned;

  Stopwatch watch;
  // Cells of the mean cut-off radius of the intact points: a query with a larger radius visits more
  // cells, so this is only about cost. The largest radius would let a few strongly expanded points
  // (release waves, spall) make the cells, and so every query, far too large.
  double radius_sum = 0.0;
  LocalIndex intact = 0;
  for (LocalIndex p = 0; p < np; ++p) {
    if (points.eroded[p]) continue;
    radius_sum += lme::cutoffRadius(settings_.lme_gamma, points.spacing(p), settings_.lme_tolerance);
    ++intact;
  }
  const double cell_size = intact > 0 ? radius_sum / intact : 1.0;
  cells_.build(nodes.x, nodes.size(), std::max(cell_size, 1e-300));

  const int threads = omp_get_max_threads();
  scratch_.resize(static_cast<std::size_t>(threads));
  count_.assign(static_cast<std::size_t>(np), 0);
  conn.offset.assign(static_cast<std::size_t>(np) + 1, 0);
  const std::size_t bodies = model.bodies.size();

  // First failing point in index order, so the diagnosis does not depend on the threads.
  LocalIndex failed = np;
  lme::Result failure;
  double shape_time = 0.0;

#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    const int nt = omp_get_num_threads();
    Scratch& s = scratch_[static_cast<std::size_t>(t)];
    s.nearest_foreign.resize(bodies);
    // A static contiguous chunk per thread keeps each thread's buffer in point order.
    const LocalIndex begin = static_cast<LocalIndex>(static_cast<Index>(np) * t / nt);
    const LocalIndex end = static_cast<LocalIndex>(static_cast<Index>(np) * (t + 1) / nt);
    std::vector<LocalIndex>& all_nodes = s.rows;
    s.N.clear();
    s.dN.clear();
    all_nodes.clear();
    Stopwatch shape_watch;
    double my_shape_time = 0.0;
    LocalIndex my_failed = np;
    lme::Result my_failure;
    for (LocalIndex p = begin; p < end; ++p) {
      // Eroded points are debris flying ballistically: no neighbourhood, no shape functions.
      if (points.eroded[p]) {
        count_[p] = 0;
        continue;
      }
      // A point near a strongly compressed or re-entrant surface can fall outside the hull of
      // the nodes within its cut-off: retry from lambda = 0 with a larger radius before failing.
      int n = 0;
      lme::Result r;
      const std::size_t first = s.N.size();
      for (int attempt = 0; attempt < 4; ++attempt) {
        const double scale = attempt == 0 ? 1.0 : std::pow(1.5, attempt);
        n = gather(model, p, scale, s);
        shape_watch.restart();
        s.offsets.resize(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) s.offsets[i] = points.x[p] - nodes.x[s.node[i]];
        s.N.resize(first + static_cast<std::size_t>(n));
        s.dN.resize(first + static_cast<std::size_t>(n));
        std::span<double> N(s.N.data() + first, static_cast<std::size_t>(n));
        std::span<Vec3> dN(s.dN.data() + first, static_cast<std::size_t>(n));
        const double h = points.spacing(p);
        if (attempt > 0) points.lambda[p].setZero();  // the warm start may be what failed
        r = lme::shapeFunctions(s.offsets, lme::beta(settings_.lme_gamma, h), h, points.lambda[p], N, dN);
        my_shape_time += shape_watch.seconds();
        if (r.status == lme::Status::converged) break;
      }
      count_[p] = n;
      if (r.status != lme::Status::converged && my_failed == np) {
        my_failed = p;
        my_failure = r;
      }
      all_nodes.insert(all_nodes.end(), s.node.begin(), s.node.end());
    }
#pragma omp barrier
#pragma omp single
    {
      for (LocalIndex p = 0; p < np; ++p) conn.offset[p + 1] = conn.offset[p] + count_[p];
      const auto entries = static_cast<std::size_t>(conn.offset[np]);
      conn.node.resize(entries);
      conn.N.resize(entries);
      conn.dN.resize(entries);
    }
    const Index at = conn.offset[begin];
    std::copy(all_nodes.begin(), all_nodes.end(), conn.node.begin() + at);
    std::copy(s.N.begin(), s.N.end(), conn.N.begin() + at);
    std::copy(s.dN.begin(), s.dN.end(), conn.dN.begin() + at);
#pragma omp critical
    {
      if (my_failed < failed) {
        failed = my_failed;
        failure = my_failure;
      }
      shape_time = std::max(shape_time, my_shape_time);
    }
  }
  if (failed < np) {
    const Vec3& x = points.x[failed];
    throw NumericalError(fmt::format(
        "LME shape functions failed at material point {} of body '{}' at ({:.6g}, {:.6g}, {:.6g}) m: {} "
        "({} nodes, residual {:.3g} h after {} iterations)",
        points.id[failed], model.bodies[points.body[failed]].name, x[0], x[1], x[2], lme::describe(failure.status),
        count_[failed], failure.residual, failure.iterations));
  }
  conn.buildTranspose(nodes.size(), transpose_scratch_);
  const double total = watch.seconds();
  shape_seconds_ = shape_time;
  search_seconds_ = total - shape_time;
}

}  // namespace kessler::otm
