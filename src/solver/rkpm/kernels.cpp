#include "solver/rkpm/kernels.hpp"

#include "core/error.hpp"
#include "search/cell_list.hpp"
#include "solver/common/mirror.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace kessler::rkpm {

namespace {

// The crack's cells (KernelInput::crack) as boxes, and which of them lie near a point.
class Crack {
 public:
  Crack(const KernelInput& in, std::span<const CellFace> faces, double reach) {
    if (in.crack.empty()) return;
    const auto n = in.reference.size();
    std::vector<LocalIndex> index(n, -1);
    for (std::size_t p = 0; p < n; ++p)
      if (in.crack[p]) {
        index[p] = static_cast<LocalIndex>(lo_.size());
        lo_.push_back(Vec3::Constant(std::numeric_limits<double>::infinity()));
        hi_.push_back(Vec3::Constant(-std::numeric_limits<double>::infinity()));
      }
    if (lo_.empty()) return;
    for (const CellFace& f : faces)
      for (const LocalIndex side : {f.inner, f.outer}) {
        if (side < 0 || index[static_cast<std::size_t>(side)] < 0) continue;
        const auto b = static_cast<std::size_t>(index[static_cast<std::size_t>(side)]);
        lo_[b] = lo_[b].cwiseMin(f.centroid);
        hi_[b] = hi_[b].cwiseMax(f.centroid);
      }
    double half_diagonal = 0.0;
    for (std::size_t b = 0; b < lo_.size(); ++b) {
      // Shrunk by a little, so that a segment along a face, or ending on one, does not pass inside.
      const Vec3 inset = 1e-9 * (hi_[b] - lo_[b]);
      lo_[b] += inset;
      hi_[b] -= inset;
      centre_.push_back(0.5 * (lo_[b] + hi_[b]));
      half_diagonal = std::max(half_diagonal, 0.5 * (hi_[b] - lo_[b]).norm());
    }
    radius_ = reach + half_diagonal;
    cells_.build(centre_, static_cast<LocalIndex>(centre_.size()), radius_);
  }
  bool empty() const { return lo_.empty(); }
  // The crack's cells that a segment from x of length below the reach may meet.
  void near(const Vec3& x, std::vector<LocalIndex>& out) const {
    out.clear();
    if (!empty()) cells_.forEachWithin(x, radius_, [&](LocalIndex b, double) { out.push_back(b); });
  }
  // Whether the segment a-b passes through the inside of one of the cells `near`.
  bool hides(const Vec3& a, const Vec3& b, std::span<const LocalIndex> near) const {
    const Vec3 d = b - a;
    for (const LocalIndex c : near) {
      const auto i = static_cast<std::size_t>(c);
      double enter = 0.0, leave = 1.0;
      for (int axis = 0; axis < 3 && enter < leave; ++axis) {
        if (d[axis] == 0.0) {
          if (a[axis] <= lo_[i][axis] || a[axis] >= hi_[i][axis]) leave = -1.0;
          continue;
        }
        double t0 = (lo_[i][axis] - a[axis]) / d[axis], t1 = (hi_[i][axis] - a[axis]) / d[axis];
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
      }
      if (enter < leave) return true;
    }
    return false;
  }

 private:
  std::vector<Vec3> lo_, hi_, centre_;
  CellList cells_;
  double radius_ = 0.0;
};

// The search for the particles whose support reaches a point. Most supports lie near one value, and
// a few, stretched with their particles' F at a kernel update, far beyond it (in the rod deck up to
// five times the median): searching for every particle within the largest would scan most of the
// model for each point. So the particles whose support exceeds the 99th percentile are binned apart
// and searched within the largest, the others within the percentile.
class Search {
 public:
  Search(const KernelInput& in, double reach) : support_(in.support), reach_(reach), common_(reach) {
    std::vector<double> held;
    for (std::size_t p = 0; p < in.support.size(); ++p)
      if (in.alone.empty() || !in.alone[p]) held.push_back(in.support[p]);
    if (!held.empty()) {
      const auto at = held.begin() + static_cast<std::ptrdiff_t>((held.size() - 1) * 99 / 100);
      std::nth_element(held.begin(), at, held.end());
      if (*at > 0.0) common_ = std::min(reach, *at);
    }
    cells_.build(in.reference, static_cast<LocalIndex>(in.reference.size()), common_);
    if (common_ < reach) {
      for (std::size_t p = 0; p < in.support.size(); ++p)
        if (in.support[p] > common_ && (in.alone.empty() || !in.alone[p])) {
          wide_.push_back(static_cast<LocalIndex>(p));
          wide_x_.push_back(in.reference[p]);
        }
      wide_cells_.build(wide_x_, static_cast<LocalIndex>(wide_x_.size()), reach);
    }
  }
  // Calls f(i, squared distance) for every particle i whose support may reach q (a superset).
  template <class F>
  void forEachReaching(const Vec3& q, F&& f) const {
    if (wide_.empty()) {
      cells_.forEachWithin(q, common_, f);
      return;
    }
    cells_.forEachWithin(q, common_, [&](LocalIndex i, double d2) {
      if (support_[static_cast<std::size_t>(i)] <= common_) f(i, d2);
    });
    wide_cells_.forEachWithin(q, reach_, [&](LocalIndex w, double d2) { f(wide_[static_cast<std::size_t>(w)], d2); });
  }

 private:
  std::span<const double> support_;
  double reach_, common_;
  CellList cells_, wide_cells_;
  std::vector<LocalIndex> wide_;
  std::vector<Vec3> wide_x_;
};

// The kernel values at one point of body `body`, as (particle, mirror, value) entries: the particles
// in the search's order, then each image (in the order of its code) in the same order; `shift` is
// the sum of the values times their images' shifts.
class Evaluator {
 public:
  Evaluator(const KernelInput& in, const Search& search, const Mirrors& mirrors, const Crack& crack, double reach)
      : in_(in), search_(search), mirrors_(mirrors), crack_(crack), reach_(reach) {}

  // False where the moment matrix is singular (rcond() then says how nearly). With `seen_past_crack`
  // the crack hides nothing from x.
  bool at(const Vec3& x, int body, double scale, std::vector<LocalIndex>& who, std::vector<std::uint8_t>& mirror,
          std::vector<double>& psi, Vec3& shift, bool seen_past_crack = false) {
    who.clear();
    mirror.clear();
    samples_.clear();
    codes_.clear();
    if (seen_past_crack)
      near_crack_.clear();
    else
      crack_.near(x, near_crack_);
    mirrors_.near(x, reach_, [&](std::uint8_t m) {
      // The image T X_i of particle i seen from x is i seen from T^-1 x: |x - T X_i| = |T^-1 x - X_i|.
      // The search's hits first, in its order, then the tests on each (a call per hit that small
      // is inlined into the search's loop; the tests are not).
      hits_.clear();
      search_.forEachReaching(mirrors_.point(x, mirrors_.inverse(m)), [&](LocalIndex i, double d2) {
        hits_.push_back({i, d2});
      });
      for (const auto& [i, d2] : hits_) {
        if (in_.body[i] != body || d2 >= in_.support[i] * in_.support[i]) continue;
        if (!in_.alone.empty() && in_.alone[static_cast<std::size_t>(i)]) continue;
        if (!near_crack_.empty() && crack_.hides(x, mirrors_.point(in_.reference[i], m), near_crack_)) continue;
        who.push_back(i);
        mirror.push_back(mirrors_.flips(m));
        codes_.push_back(m);
        samples_.push_back({x - mirrors_.point(in_.reference[i], m), in_.support[i], in_.volume[i]});
      }
    });
    psi.assign(who.size(), 0.0);
    rcond_ = rk::shapeValues(samples_, scale, psi);
    shift = Vec3::Zero();
    for (std::size_t e = 0; e < codes_.size(); ++e)
      if (codes_[e] != 0) shift += psi[e] * (mirrors_.point(Vec3::Zero(), codes_[e]));
    return rcond_ >= rk::min_rcond;
  }
  double rcond() const { return rcond_; }

  // The row of a point that takes particle `owner`'s coefficient alone.
  static void alone(LocalIndex owner, std::vector<LocalIndex>& who, std::vector<std::uint8_t>& mirror,
                    std::vector<double>& psi, Vec3& shift) {
    who.assign(1, owner);
    mirror.assign(1, 0);
    psi.assign(1, 1.0);
    shift = Vec3::Zero();
  }

 private:
  const KernelInput& in_;
  const Search& search_;
  const Mirrors& mirrors_;
  const Crack& crack_;
  double reach_;
  std::vector<LocalIndex> near_crack_;
  std::vector<rk::Sample> samples_;
  std::vector<std::uint8_t> codes_;
  std::vector<std::pair<LocalIndex, double>> hits_;  // a search's (particle, squared distance)
  double rcond_ = 0.0;
};

// One table row's entries as they are gathered.
template <class T>
struct Row {
  std::vector<LocalIndex> column;
  std::vector<std::uint8_t> mirror;
  std::vector<T> value;
};

template <class T>
Table<T> flatten(std::vector<Row<T>>& rows) {
  Table<T> t;
  t.offset.resize(rows.size() + 1);
  for (std::size_t r = 0; r < rows.size(); ++r)
    t.offset[r + 1] = t.offset[r] + static_cast<LocalIndex>(rows[r].column.size());
  const auto entries = static_cast<std::size_t>(t.offset.back());
  t.column.reserve(entries);
  t.mirror.reserve(entries);
  t.value.reserve(entries);
  for (Row<T>& row : rows) {
    t.column.insert(t.column.end(), row.column.begin(), row.column.end());
    t.mirror.insert(t.mirror.end(), row.mirror.begin(), row.mirror.end());
    t.value.insert(t.value.end(), row.value.begin(), row.value.end());
    row = Row<T>{};
  }
  return t;
}

// The cells after a kernel update (KernelInput::cell_F): each cell's faces mapped by its own F, one
// face per cell and side; kept_faces (surface faces, one side each) renumbered to match.
struct MappedCells {
  std::vector<CellFace> faces;
  std::vector<double> volume;
  std::vector<LocalIndex> kept;
};

MappedCells mappedCells(const KernelInput& in) {
  MappedCells m;
  const auto n = in.reference.size();
  m.volume.resize(n);
  std::vector<Mat3> cofactor(n);  // det F F^-T
  for (std::size_t j = 0; j < n; ++j) {
    const Mat3& F = in.cell_F[j];
    m.volume[j] = F.determinant() * in.cell_volume[j];
    cofactor[j] = F.determinant() * F.inverse().transpose();
  }
  std::vector<LocalIndex> inner_side(in.faces.size());
  m.faces.reserve(2 * in.faces.size());
  auto mapped = [&](const CellFace& f, LocalIndex side, const Vec3& area) {
    const auto j = static_cast<std::size_t>(side);
    return CellFace{cofactor[j] * area, in.reference[j] + in.cell_F[j] * (f.centroid - in.cell_origin[j]), side, -1};
  };
  for (std::size_t f = 0; f < in.faces.size(); ++f) {
    const CellFace& face = in.faces[f];
    inner_side[f] = static_cast<LocalIndex>(m.faces.size());
    m.faces.push_back(mapped(face, face.inner, face.area));
    if (face.outer >= 0) m.faces.push_back(mapped(face, face.outer, Vec3(-face.area)));
  }
  for (const LocalIndex f : in.kept_faces) m.kept.push_back(inner_side[static_cast<std::size_t>(f)]);
  return m;
}

}  // namespace

Kernels buildKernels(const KernelInput& in) {
  const auto n = static_cast<LocalIndex>(in.reference.size());
  Kernels k;
  if (n == 0) return k;
  MappedCells mapped;
  if (!in.cell_F.empty()) mapped = mappedCells(in);
  const std::span<const CellFace> all_faces = in.cell_F.empty() ? in.faces : std::span<const CellFace>(mapped.faces);
  const std::span<const double> cell_volume =
      in.cell_F.empty() ? in.cell_volume : std::span<const double>(mapped.volume);
  const std::span<const LocalIndex> kept_faces =
      in.cell_F.empty() ? in.kept_faces : std::span<const LocalIndex>(mapped.kept);
  // The search's reach: the largest support of a particle that is in other rows (one standing alone is
  // in none, and debris, stretched far, would widen every search).
  double reach = 0.0;
  for (std::size_t p = 0; p < in.support.size(); ++p)
    if (in.alone.empty() || !in.alone[p]) reach = std::max(reach, in.support[p]);
  if (!(reach > 0.0)) reach = *std::max_element(in.support.begin(), in.support.end());
  const Search search(in, reach);
  const Mirrors mirrors = in.mirrors.any() ? Mirrors(in.mirrors, reach) : Mirrors();
  const Crack crack(in, all_faces, reach);
  auto cracked = [&](LocalIndex p) { return !in.crack.empty() && in.crack[static_cast<std::size_t>(p)] != 0; };
  auto lone = [&](LocalIndex p) { return !in.alone.empty() && in.alone[static_cast<std::size_t>(p)] != 0; };

  // Where a moment matrix was singular: the first such point in index order (faces after particles).
  struct Failure {
    std::size_t at = std::numeric_limits<std::size_t>::max();
    Vec3 x = Vec3::Zero();
    int body = 0;
    double rcond = 0.0;
  };
  Failure failure;
  auto fail = [&](std::size_t at, const Vec3& x, int body, double rcond) {
#pragma omp critical(rkpm_kernel_failure)
    if (at < failure.at) failure = {at, x, body, rcond};
  };

  // The values at the particles.
  std::vector<Row<double>> rows(static_cast<std::size_t>(n));
  std::vector<Vec3> shift(static_cast<std::size_t>(n));
#pragma omp parallel
  {
    Evaluator e(in, search, mirrors, crack, reach);
#pragma omp for schedule(dynamic, 256)
    for (LocalIndex p = 0; p < n; ++p) {
      Row<double>& r = rows[static_cast<std::size_t>(p)];
      Vec3& s = shift[static_cast<std::size_t>(p)];
      if (lone(p)) {
        Evaluator::alone(p, r.column, r.mirror, r.value, s);
      } else if (!e.at(in.reference[p], in.body[p], in.support[p], r.column, r.mirror, r.value, s, cracked(p))) {
        if (in.alone_where_singular) {
          Evaluator::alone(p, r.column, r.mirror, r.value, s);
#pragma omp atomic
          ++k.fallbacks;
        } else {
          fail(static_cast<std::size_t>(p), in.reference[p], in.body[p], e.rcond());
        }
      }
    }
  }
  k.psi = flatten(rows);
  if (std::any_of(shift.begin(), shift.end(), [](const Vec3& s) { return s != Vec3::Zero(); }))
    k.shift = std::move(shift);

  // The values at the faces' centroids. A face two cells share (before any kernel update) is
  // evaluated once, first, and kept until both cells have summed it; a face of one cell alone (every
  // face after an update) is evaluated as its cell sums it, so that all the faces' values are never
  // held at once.
  const std::size_t faces = all_faces.size();
  auto evaluateFace = [&](Evaluator& e, std::size_t f, Row<double>& r) {
    const CellFace& face = all_faces[f];
    const bool inside_crack = cracked(face.inner) && (face.outer < 0 || cracked(face.outer));
    Vec3 unused;
    if (lone(face.inner)) {
      Evaluator::alone(face.inner, r.column, r.mirror, r.value, unused);
    } else if (!e.at(face.centroid, in.body[face.inner], in.support[face.inner], r.column, r.mirror, r.value, unused,
                     inside_crack)) {
      if (in.alone_where_singular) {
        Evaluator::alone(face.inner, r.column, r.mirror, r.value, unused);
#pragma omp atomic
        ++k.fallbacks;
      } else {
        fail(static_cast<std::size_t>(n) + f, face.centroid, in.body[face.inner], e.rcond());
      }
    }
  };
  std::vector<LocalIndex> shared_row(faces, -1);
  std::vector<std::size_t> shared_faces;
  for (std::size_t f = 0; f < faces; ++f)
    if (all_faces[f].outer >= 0) {
      shared_row[f] = static_cast<LocalIndex>(shared_faces.size());
      shared_faces.push_back(f);
    }
  rows.assign(shared_faces.size(), {});
#pragma omp parallel
  {
    Evaluator e(in, search, mirrors, crack, reach);
#pragma omp for schedule(dynamic, 256)
    for (std::size_t r = 0; r < shared_faces.size(); ++r) evaluateFace(e, shared_faces[r], rows[r]);
  }
  const Table<double> shared = flatten(rows);

  // Each cell's faces.
  std::vector<LocalIndex> first(static_cast<std::size_t>(n) + 1, 0), cell_faces;
  for (const CellFace& f : all_faces) {
    ++first[static_cast<std::size_t>(f.inner) + 1];
    if (f.outer >= 0) ++first[static_cast<std::size_t>(f.outer) + 1];
  }
  for (std::size_t p = 0; p < static_cast<std::size_t>(n); ++p) first[p + 1] += first[p];
  cell_faces.resize(static_cast<std::size_t>(first.back()));
  {
    std::vector<LocalIndex> cursor(first.begin(), first.end() - 1);
    for (std::size_t f = 0; f < faces; ++f) {
      cell_faces[static_cast<std::size_t>(cursor[all_faces[f].inner]++)] = static_cast<LocalIndex>(f);
      if (all_faces[f].outer >= 0)
        cell_faces[static_cast<std::size_t>(cursor[all_faces[f].outer]++)] = static_cast<LocalIndex>(f);
    }
  }
  std::vector<LocalIndex> kept_row(faces, -1);
  for (std::size_t r = 0; r < kept_faces.size(); ++r)
    kept_row[static_cast<std::size_t>(kept_faces[r])] = static_cast<LocalIndex>(r);
  std::vector<Row<double>> kept(kept_faces.size());

  // The smoothed gradients: each cell's faces' values, summed per entry (particle, then mirror).
  std::vector<Row<Vec3>> gradients(static_cast<std::size_t>(n));
#pragma omp parallel
  {
    // The cell's terms, as its faces give them, then summed per entry, found by column through `head`
    // (one chain per column, an entry per mirror): each entry's terms are added in the order of the
    // cell's faces.
    struct Term {
      std::int64_t key;  // 8 particle + mirror
      Vec3 value;
    };
    struct Entry {
      std::int64_t key;
      Vec3 sum;
      LocalIndex next;  // the column's next entry, or -1
    };
    std::vector<Term> terms;
    std::vector<Entry> entries;
    std::vector<LocalIndex> head(static_cast<std::size_t>(n), -1), order;
    Evaluator e(in, search, mirrors, crack, reach);
    Row<double> own;
    auto add = [&](const Vec3& area, std::span<const LocalIndex> column, std::span<const std::uint8_t> mirror,
                   std::span<const double> value) {
      for (std::size_t slot = 0; slot < column.size(); ++slot)
        terms.push_back({8 * static_cast<std::int64_t>(column[slot]) + mirror[slot], value[slot] * area});
    };
#pragma omp for schedule(dynamic, 64)
    for (LocalIndex j = 0; j < n; ++j) {
      terms.clear();
      entries.clear();
      for (LocalIndex s = first[j]; s < first[j + 1]; ++s) {
        const auto f = static_cast<std::size_t>(cell_faces[static_cast<std::size_t>(s)]);
        const Vec3 area = all_faces[f].inner == j ? all_faces[f].area : Vec3(-all_faces[f].area);
        Row<double>* row = nullptr;
        if (shared_row[f] >= 0) {
          const LocalIndex r = shared_row[f];
          const auto b = static_cast<std::size_t>(shared.offset[r]),
                     size = static_cast<std::size_t>(shared.offset[r + 1]) - b;
          add(area, std::span(shared.column).subspan(b, size), std::span(shared.mirror).subspan(b, size),
              std::span(shared.value).subspan(b, size));
          if (kept_row[f] >= 0 && all_faces[f].inner == j) {
            row = &kept[static_cast<std::size_t>(kept_row[f])];
            row->column.assign(shared.column.begin() + b, shared.column.begin() + b + size);
            row->mirror.assign(shared.mirror.begin() + b, shared.mirror.begin() + b + size);
            row->value.assign(shared.value.begin() + b, shared.value.begin() + b + size);
          }
          continue;
        }
        row = kept_row[f] >= 0 ? &kept[static_cast<std::size_t>(kept_row[f])] : &own;
        evaluateFace(e, f, *row);
        add(area, row->column, row->mirror, row->value);
      }
      for (const Term& term : terms) {
        LocalIndex& chain = head[static_cast<std::size_t>(term.key / 8)];
        LocalIndex at = chain;
        while (at >= 0 && entries[static_cast<std::size_t>(at)].key != term.key)
          at = entries[static_cast<std::size_t>(at)].next;
        if (at < 0) {
          at = static_cast<LocalIndex>(entries.size());
          entries.push_back({term.key, Vec3::Zero(), chain});
          chain = at;
        }
        entries[static_cast<std::size_t>(at)].sum += term.value;
      }
      // The row's entries by key.
      order.resize(entries.size());
      for (std::size_t i = 0; i < entries.size(); ++i) order[i] = static_cast<LocalIndex>(i);
      std::sort(order.begin(), order.end(), [&](LocalIndex a, LocalIndex b) {
        return entries[static_cast<std::size_t>(a)].key < entries[static_cast<std::size_t>(b)].key;
      });
      Row<Vec3>& row = gradients[static_cast<std::size_t>(j)];
      const double inv = 1.0 / cell_volume[j];
      row.column.reserve(entries.size());
      row.mirror.reserve(entries.size());
      row.value.reserve(entries.size());
      for (const LocalIndex i : order) {
        const Entry& entry = entries[static_cast<std::size_t>(i)];
        row.column.push_back(static_cast<LocalIndex>(entry.key / 8));
        row.mirror.push_back(static_cast<std::uint8_t>(entry.key % 8));
        row.value.push_back(inv * entry.sum);
        head[static_cast<std::size_t>(entry.key / 8)] = -1;
      }
    }
  }
  if (failure.at != std::numeric_limits<std::size_t>::max()) {
    const Vec3 mm = 1e3 * failure.x;
    throw Error(fmt::format(
        "RKPM: the reproducing kernel's moment matrix is singular at ({:.4g}, {:.4g}, {:.4g}) mm in body '{}' "
        "(reciprocal condition {:.2g}): fewer than four particles not in one plane reach it (docs/theory.md §12)",
        mm.x(), mm.y(), mm.z(), in.bodies[static_cast<std::size_t>(failure.body)], failure.rcond));
  }
  k.gradient = flatten(gradients);
  k.at_faces = flatten(kept);
  return k;
}

Vec3 valueAt(const Table<double>& psi, std::span<const Vec3> coefficients, LocalIndex k) {
  Vec3 sum = Vec3::Zero();
  for (LocalIndex e = psi.offset[k]; e < psi.offset[k + 1]; ++e) {
    const auto slot = static_cast<std::size_t>(e);
    sum += psi.value[slot] * reflect(coefficients[static_cast<std::size_t>(psi.column[slot])], psi.mirror[slot]);
  }
  return sum;
}

void interpolate(const Table<double>& psi, std::span<const Vec3> coefficients, std::span<Vec3> out) {
  const LocalIndex n = psi.rows();
#pragma omp parallel for schedule(static)
  for (LocalIndex k = 0; k < n; ++k) out[k] = valueAt(psi, coefficients, k);
}

void interpolate(const Table<double>& psi, std::span<const Vec3> a, std::span<const Vec3> b, std::span<Vec3> out_a,
                 std::span<Vec3> out_b) {
  const LocalIndex n = psi.rows();
#pragma omp parallel for schedule(static)
  for (LocalIndex k = 0; k < n; ++k) {
    Vec3 sum_a = Vec3::Zero(), sum_b = Vec3::Zero();
    for (LocalIndex e = psi.offset[k]; e < psi.offset[k + 1]; ++e) {
      const auto slot = static_cast<std::size_t>(e);
      const auto i = static_cast<std::size_t>(psi.column[slot]);
      sum_a += psi.value[slot] * reflect(a[i], psi.mirror[slot]);
      sum_b += psi.value[slot] * reflect(b[i], psi.mirror[slot]);
    }
    out_a[k] = sum_a;
    out_b[k] = sum_b;
  }
}

std::vector<Vec3> interpolatingCoefficients(const Table<double>& psi, std::span<const double> particle_mass,
                                            std::span<const double> mass, std::span<const Vec3> values,
                                            std::span<const Vec3> guess, int passes) {
  const LocalIndex n = psi.rows();
  std::vector<Vec3> out(guess.begin(), guess.end()), best, residual(static_cast<std::size_t>(n));
  double best_residual = std::numeric_limits<double>::infinity();
  for (int pass = 0; pass <= passes; ++pass) {
    interpolate(psi, out, residual);
    double largest = 0.0;
    for (LocalIndex k = 0; k < n; ++k) {
      const auto s = static_cast<std::size_t>(k);
      residual[s] = values[s] - residual[s];
      largest = std::max(largest, residual[s].norm());
    }
    // Past the first pass (which gives the momentum), the passes go on while they bring the largest
    // residual down; the best is kept.
    if (pass >= 1) {
      if (!(largest < best_residual)) break;
      best_residual = largest;
      best = out;
    }
    if (pass == passes) break;
    for (LocalIndex k = 0; k < n; ++k)
      spreadImpulse(psi, mass, k, particle_mass[static_cast<std::size_t>(k)] * residual[static_cast<std::size_t>(k)],
                    out);
  }
  return best;
}

void spreadImpulse(const Table<double>& psi, std::span<const double> mass, LocalIndex k, const Vec3& impulse,
                   std::span<Vec3> coefficient_v) {
  for (LocalIndex e = psi.offset[k]; e < psi.offset[k + 1]; ++e) {
    const auto slot = static_cast<std::size_t>(e);
    const auto i = static_cast<std::size_t>(psi.column[slot]);
    coefficient_v[i] += reflect(impulse, psi.mirror[slot]) * (psi.value[slot] / mass[i]);
  }
}

}  // namespace kessler::rkpm
