#include "parallel/partition.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <limits>

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

#if KESSLER_HAVE_MPI

// Zoltan's state, and the points it asks for through its callbacks while it cuts.
struct Partition::Zoltan {
  Zoltan_Struct* zz = nullptr;
  std::span<const Vec3> x;
  std::span<const Index> ids;
  std::span<const double> work;
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
    for (int k = 0; k < 3; ++k) x[3 * i + k] = z.x[local[i]][k];
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

void Partition::cut(std::span<const Vec3> x, std::span<const Index> ids, std::span<const double> work) {
  zoltan_->x = x;
  zoltan_->ids = ids;
  zoltan_->work = work;
  int changes = 0, gid_words = 0, lid_words = 0, imports = 0, exports = 0;
  ZOLTAN_ID_PTR import_global = nullptr, import_local = nullptr, export_global = nullptr, export_local = nullptr;
  int *import_procs = nullptr, *import_parts = nullptr, *export_procs = nullptr, *export_parts = nullptr;
  check(Zoltan_LB_Partition(zoltan_->zz, &changes, &gid_words, &lid_words, &imports, &import_global, &import_local,
                            &import_procs, &import_parts, &exports, &export_global, &export_local, &export_procs,
                            &export_parts),
        "partition");
  Zoltan_LB_Free_Part(&import_global, &import_local, &import_procs, &import_parts);
  Zoltan_LB_Free_Part(&export_global, &export_local, &export_procs, &export_parts);
  zoltan_->x = {};
  zoltan_->ids = {};
  zoltan_->work = {};
}

int Partition::assign(const Vec3& x) const {
  double coords[3] = {x[0], x[1], x[2]};
  int rank = -1;
  check(Zoltan_LB_Point_Assign(zoltan_->zz, coords, &rank), "point assignment");
  return rank;
}

std::vector<int> Partition::assign(const Vec3& lo, const Vec3& hi) const {
  std::vector<int> ranks(static_cast<std::size_t>(comm_.size()));
  int count = 0;
  check(Zoltan_LB_Box_Assign(zoltan_->zz, lo[0], lo[1], lo[2], hi[0], hi[1], hi[2], ranks.data(), &count),
        "box assignment");
  ranks.resize(static_cast<std::size_t>(count));
  return ranks;
}

Box Partition::cutBox(int rank) const {
  int dimensions = 0;
  Box box;
  check(Zoltan_RCB_Box(zoltan_->zz, rank, &dimensions, &box.lo[0], &box.lo[1], &box.lo[2], &box.hi[0], &box.hi[1],
                       &box.hi[2]),
        "subdomain box");
  return box;
}

#else  // one process: a communicator of one rank never reaches Zoltan

struct Partition::Zoltan {};

Partition::Partition(const Communicator& comm) : comm_(comm) {}
Partition::~Partition() = default;
void Partition::cut(std::span<const Vec3>, std::span<const Index>, std::span<const double>) {}
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
