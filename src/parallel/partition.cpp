#include "parallel/partition.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#if KESSLER_HAVE_MPI
#include <mpi.h>
#include <zoltan.h>
#endif

namespace kessler::parallel {

namespace {

Box boundsOf(const Communicator& comm, std::span<const Vec3> x) {
  std::array<double, 6> extent;
  extent.fill(-std::numeric_limits<double>::infinity());  // -lo and hi, so one maximum does both
  for (const Vec3& p : x)
    for (int k = 0; k < 3; ++k) {
      extent[k] = std::max(extent[k], -p[k]);
      extent[3 + k] = std::max(extent[3 + k], p[k]);
    }
  comm.max(extent);
  Box box;
  for (int k = 0; k < 3; ++k) {
    box.lo[k] = -extent[k];
    box.hi[k] = extent[3 + k];
  }
  return box;
}

}  // namespace

double imbalance(const Communicator& comm, double work) {
  const double largest = comm.max(work);
  ExactSum total;
  total.add(work);
  const double mean = comm.sum(total) / comm.size();
  return mean > 0.0 ? largest / mean : 1.0;
}

bool Rebalance::due(const Communicator& comm, double own_work) {
  imbalance_ = parallel::imbalance(comm, own_work);
  largest_imbalance_ = std::max(largest_imbalance_, imbalance_);
  return imbalance_ > std::max(at, 1.05 * cut_balance_);  // the same on every rank
}

void Rebalance::cut(const Communicator& comm, std::span<const double> work, std::span<const int> owner) {
  ++count_;
  std::vector<std::int64_t> given(static_cast<std::size_t>(comm.size()), 0);
  for (std::size_t k = 0; k < work.size(); ++k)
    given[static_cast<std::size_t>(owner[k])] += static_cast<std::int64_t>(work[k]);
  comm.sum(given);
  cut_balance_ = parallel::imbalance(comm, static_cast<double>(given[static_cast<std::size_t>(comm.rank())]));
}

#if KESSLER_HAVE_MPI

// Zoltan's state, and the points it asks for through its callbacks while it cuts.
struct Partition::Zoltan {
  Zoltan_Struct* zz = nullptr;
  std::span<const Vec3> x;
  std::span<const Index> ids;
  std::span<const double> work;
  // Zoltan's coordinates are ours times `scale` (RCB cuts first across the longest side of the box,
  // and a scaled axis becomes the longest: Partition::cut).
  Vec3 scale = Vec3::Ones();
  ~Zoltan() {
    if (zz) Zoltan_Destroy(&zz);
  }
};

namespace {

// Global ids are 64-bit and Zoltan's are 32 (Debian builds ZOLTAN_ID_TYPE as unsigned int): each id
// is two entries, low word first.
constexpr int id_words = 2;

void check(int status, const char* what) {
  KESSLER_VERIFY(status == ZOLTAN_OK || status == ZOLTAN_WARN, "Zoltan's {} failed (code {})", what, status);
}

}  // namespace

// Zoltan's callbacks are C functions: these are defined where Partition::Zoltan is visible.
extern "C" {
static int kesslerCountPoints(void* data, int* error) {
  *error = ZOLTAN_OK;
  return static_cast<int>(static_cast<Partition::Zoltan*>(data)->x.size());
}

static void kesslerListPoints(void* data, int, int, ZOLTAN_ID_PTR global, ZOLTAN_ID_PTR local, int weight_dim,
                              float* weights, int* error) {
  const auto& z = *static_cast<Partition::Zoltan*>(data);
  for (std::size_t i = 0; i < z.x.size(); ++i) {
    const auto id = static_cast<std::uint64_t>(z.ids[i]);
    global[id_words * i] = static_cast<ZOLTAN_ID_TYPE>(id & 0xffffffffULL);
    global[id_words * i + 1] = static_cast<ZOLTAN_ID_TYPE>(id >> 32);
    local[i] = static_cast<ZOLTAN_ID_TYPE>(i);
    if (weight_dim > 0) weights[i] = static_cast<float>(z.work[i]);
  }
  *error = ZOLTAN_OK;
}

static int kesslerDimensions(void*, int* error) {
  *error = ZOLTAN_OK;
  return 3;
}

static void kesslerPositions(void* data, int, int, int count, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR local, int, double* x,
                             int* error) {
  const auto& z = *static_cast<Partition::Zoltan*>(data);
  for (int i = 0; i < count; ++i)
    for (int k = 0; k < 3; ++k) x[3 * i + k] = z.x[local[i]][k] * z.scale[k];
  *error = ZOLTAN_OK;
}
}

Partition::Partition(const Communicator& comm) : comm_(comm), zoltan_(std::make_unique<Zoltan>()) {
  if (!comm_.handle()) return;
  static const bool initialised = [] {
    float version = 0.0f;
    check(Zoltan_Initialize(0, nullptr, &version), "initialisation");
    return true;
  }();
  (void)initialised;
  create();
}

// A fresh Zoltan state with Kessler's parameters (no cuts, no directions yet).
void Partition::create() {
  if (zoltan_->zz) Zoltan_Destroy(&zoltan_->zz);
  zoltan_->zz = Zoltan_Create(*static_cast<const MPI_Comm*>(comm_.handle()));
  KESSLER_VERIFY(zoltan_->zz, "Zoltan_Create failed");
  Zoltan_Struct* zz = zoltan_->zz;
  Zoltan_Set_Param(zz, "DEBUG_LEVEL", "0");
  Zoltan_Set_Param(zz, "LB_METHOD", "RCB");
  Zoltan_Set_Param(zz, "NUM_GID_ENTRIES", "2");
  Zoltan_Set_Param(zz, "NUM_LID_ENTRIES", "1");
  Zoltan_Set_Param(zz, "OBJ_WEIGHT_DIM", "1");
  // Cuts within 2% of the mean work (Zoltan allows 10% by default, as much as the threshold at which
  // a run cuts its points afresh: it would cut again and again).
  Zoltan_Set_Param(zz, "IMBALANCE_TOL", "1.02");
  // Which rank a point goes to is decided by owner() alone, after the cuts (below).
  Zoltan_Set_Param(zz, "RETURN_LISTS", "NONE");
  // The cuts stay for owner() and ranksMeeting(); each balance cuts afresh (no reuse of the last
  // cuts as a first guess), so a balance depends only on the points.
  Zoltan_Set_Param(zz, "KEEP_CUTS", "1");
  Zoltan_Set_Param(zz, "RCB_REUSE", "0");
  // Later cuts keep the directions of the first, chosen across the bodies as meshed: a debris cloud
  // stretches the points' box along the impact, and cuts across that axis would run through the
  // plates, every point of which is then within a halo of the cut (hvi at 36k points on 2 ranks:
  // rank 0's ghosts 12,657 -> 3,119 at 8 us, 2.77 -> 1.86 us per point-step).
  Zoltan_Set_Param(zz, "RCB_LOCK_DIRECTIONS", "1");
  // Points on a cut all go to one side, as owner() puts them: a plate's layers of points share their
  // coordinate across it, and Zoltan would otherwise count a layer split that owner() does not.
  Zoltan_Set_Param(zz, "RCB_RECTILINEAR_BLOCKS", "1");
  Zoltan_Set_Num_Obj_Fn(zz, kesslerCountPoints, zoltan_.get());
  Zoltan_Set_Obj_List_Fn(zz, kesslerListPoints, zoltan_.get());
  Zoltan_Set_Num_Geom_Fn(zz, kesslerDimensions, zoltan_.get());
  Zoltan_Set_Geom_Multi_Fn(zz, kesslerPositions, zoltan_.get());
}

Partition::~Partition() = default;

// RCB cuts first across the longest side of the points' box, and later cuts keep the directions of
// the first (RCB_LOCK_DIRECTIONS, above). That side may run through few layers of points: a lattice
// plate's layers share their coordinate, a cut can only part them between layers, and cuts through a
// thin plate or between bodies may leave one rank most of the work (a Whipple shield's rear wall,
// two layers thick, on 2 ranks: 87% of the particles on one). At the first cut each axis is tried
// first (scaled to be the longest; Zoltan's own choice first, in a fresh state each), and the one
// whose cuts leave the least imbalance, by owner() and the points' work, is kept for the run: the
// same choice on every rank.
void Partition::cut(std::span<const Vec3> x, std::span<const Index> ids, std::span<const double> work) {
  zoltan_->x = x;
  zoltan_->ids = ids;
  zoltan_->work = work;
  if (directions_chosen_) {
    partitionOnce();
  } else {
    const Vec3 extent = bounds_.hi - bounds_.lo;
    std::vector<Vec3> scales{Vec3::Ones()};
    for (int a = 0; a < 3; ++a)
      if (extent[a] > 0.0 && extent[a] < extent.maxCoeff()) {
        Vec3 scale = Vec3::Ones();
        scale[a] = 1.01 * extent.maxCoeff() / extent[a];
        scales.push_back(scale);
      }
    double best = std::numeric_limits<double>::infinity();
    std::size_t chosen = 0;
    for (std::size_t c = 0; c < scales.size(); ++c) {
      if (c > 0) create();
      zoltan_->scale = scales[c];
      partitionOnce();
      std::vector<std::int64_t> given(static_cast<std::size_t>(comm_.size()), 0);
      for (std::size_t i = 0; i < x.size(); ++i)
        given[static_cast<std::size_t>(assign(x[i]))] += static_cast<std::int64_t>(std::ceil(work[i]));
      comm_.sum(given);
      const auto largest = static_cast<double>(*std::max_element(given.begin(), given.end()));
      const auto total = static_cast<double>(std::accumulate(given.begin(), given.end(), std::int64_t{0}));
      const double imbalance = total > 0.0 ? largest * static_cast<double>(comm_.size()) / total : 1.0;
      if (imbalance < best * (1.0 - 1e-3)) {  // a clear gain over Zoltan's own choice
        best = imbalance;
        chosen = c;
      }
    }
    if (chosen + 1 != scales.size()) {
      create();
      zoltan_->scale = scales[chosen];
      partitionOnce();
    }
    directions_chosen_ = true;
  }
  zoltan_->x = {};
  zoltan_->ids = {};
  zoltan_->work = {};
}

void Partition::partitionOnce() {
  int changes = 0, gid_words = 0, lid_words = 0, imports = 0, exports = 0;
  ZOLTAN_ID_PTR import_global = nullptr, import_local = nullptr, export_global = nullptr, export_local = nullptr;
  int *import_procs = nullptr, *import_parts = nullptr, *export_procs = nullptr, *export_parts = nullptr;
  check(Zoltan_LB_Partition(zoltan_->zz, &changes, &gid_words, &lid_words, &imports, &import_global, &import_local,
                            &import_procs, &import_parts, &exports, &export_global, &export_local, &export_procs,
                            &export_parts),
        "partition");
  Zoltan_LB_Free_Part(&import_global, &import_local, &import_procs, &import_parts);
  Zoltan_LB_Free_Part(&export_global, &export_local, &export_procs, &export_parts);
}

int Partition::assign(const Vec3& x) const {
  const Vec3& scale = zoltan_->scale;
  double coords[3] = {x[0] * scale[0], x[1] * scale[1], x[2] * scale[2]};
  int rank = -1;
  check(Zoltan_LB_Point_Assign(zoltan_->zz, coords, &rank), "point assignment");
  return rank;
}

std::vector<int> Partition::assign(const Vec3& lo, const Vec3& hi) const {
  std::vector<int> ranks(static_cast<std::size_t>(comm_.size()));
  int count = 0;
  const Vec3 a = lo.cwiseProduct(zoltan_->scale), b = hi.cwiseProduct(zoltan_->scale);
  check(Zoltan_LB_Box_Assign(zoltan_->zz, a[0], a[1], a[2], b[0], b[1], b[2], ranks.data(), &count), "box assignment");
  ranks.resize(static_cast<std::size_t>(count));
  return ranks;
}

Box Partition::cutBox(int rank) const {
  int dimensions = 0;
  Box box;
  check(Zoltan_RCB_Box(zoltan_->zz, rank, &dimensions, &box.lo[0], &box.lo[1], &box.lo[2], &box.hi[0], &box.hi[1],
                       &box.hi[2]),
        "subdomain box");
  // (An outer face, +-DBL_MAX, stays one.)
  for (int k = 0; k < 3; ++k) {
    if (std::abs(box.lo[k]) < std::numeric_limits<double>::max()) box.lo[k] /= zoltan_->scale[k];
    if (std::abs(box.hi[k]) < std::numeric_limits<double>::max()) box.hi[k] /= zoltan_->scale[k];
  }
  return box;
}

#else  // one process: a communicator of one rank never reaches Zoltan

struct Partition::Zoltan {};

Partition::Partition(const Communicator& comm) : comm_(comm) {}
Partition::~Partition() = default;
void Partition::cut(std::span<const Vec3>, std::span<const Index>, std::span<const double>) {}
void Partition::partitionOnce() {}
void Partition::create() {}
int Partition::assign(const Vec3&) const {
  return 0;
}
std::vector<int> Partition::assign(const Vec3&, const Vec3&) const {
  return {0};
}
Box Partition::cutBox(int) const {
  return bounds_;
}

#endif

std::vector<int> Partition::balance(std::span<const Vec3> x, std::span<const Index> ids, std::span<const double> work) {
  KESSLER_VERIFY(ids.size() == x.size() && work.size() == x.size(), "partition of {} points with {} ids, {} weights",
                 x.size(), ids.size(), work.size());
  bounds_ = boundsOf(comm_, x);
  balanced_ = true;
  if (comm_.size() == 1) return std::vector<int>(x.size(), 0);
  cut(x, ids, work);
  // Zoltan may put a point that lies exactly on a cut on either side; owner() puts it on the lower
  // one. One rule for where a point belongs, at a balance and between balances.
  std::vector<int> owners(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) owners[i] = assign(x[i]);
  return owners;
}

int Partition::owner(const Vec3& x) const {
  KESSLER_VERIFY(balanced_, "a position assigned before the first balance");
  return comm_.size() == 1 ? 0 : assign(x);
}

std::vector<int> Partition::ranksMeeting(const Vec3& lo, const Vec3& hi) const {
  KESSLER_VERIFY(balanced_, "a box assigned before the first balance");
  if (comm_.size() == 1) return {0};
  std::vector<int> ranks = assign(lo, hi);
  std::sort(ranks.begin(), ranks.end());
  return ranks;
}

Box Partition::region(int rank) const {
  KESSLER_VERIFY(balanced_, "a region asked for before the first balance");
  constexpr double infinity = std::numeric_limits<double>::infinity();
  if (comm_.size() == 1) return {Vec3::Constant(-infinity), Vec3::Constant(infinity)};
  // Zoltan reports an outer face as +-DBL_MAX.
  Box box = cutBox(rank);
  for (int k = 0; k < 3; ++k) {
    if (box.lo[k] <= -std::numeric_limits<double>::max()) box.lo[k] = -infinity;
    if (box.hi[k] >= std::numeric_limits<double>::max()) box.hi[k] = infinity;
  }
  return box;
}

Box Partition::subdomain(int rank) const {
  KESSLER_VERIFY(balanced_, "a subdomain asked for before the first balance");
  if (comm_.size() == 1) return bounds_;
  // Zoltan reports an outer face as +-DBL_MAX.
  Box box = cutBox(rank);
  box.lo = box.lo.cwiseMax(bounds_.lo);
  box.hi = box.hi.cwiseMin(bounds_.hi);
  return box;
}

}  // namespace kessler::parallel
