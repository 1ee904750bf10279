#pragma once
// The particle store: structure-of-arrays for the material points (docs/theory.md §1), which every
// method shares (a method keeps its own stores beside it: OTM's nodes, solver/otm/node_store.hpp).
// Each point and node names its body (`body`); a body is the set of entries that name it, wherever
// they sit. A method may keep each body's entries together (OTM does, so that a material law runs
// over a whole range at once: bodyRanges). Loops run over the owned entries [0, owned), so that
// copies of other processes' entries (ghosts) can sit behind them.
// Each store declares its arrays once, in fields(): resize, permutation and the checkpoint all
// visit that list, so a new array is added there and nowhere else.
#include "core/types.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace kessler {

struct PointStore {
  std::vector<Index> id;
  std::vector<std::int32_t> body;
  std::vector<Vec3> x;
  std::vector<Vec3> v;
  std::vector<double> mass;              // fixed
  std::vector<double> volume;            // current
  std::vector<double> volume0;           // reference
  std::vector<double> spacing0;          // reference support size h (mean edge of the initial tet)
  std::vector<Mat3> F;                   // deformation gradient
  std::vector<Mat3> dF;                  // increment of the last step
  std::vector<Mat3> stress;              // Cauchy stress
  std::vector<double> energy;            // specific internal energy (J/kg)
  std::vector<double> sound_speed;       // longitudinal wave speed, for the time step
  std::vector<double> plastic_strain;    // equivalent plastic strain
  std::vector<double> temperature;       // K
  std::vector<double> damage;            // Johnson-Cook damage D in [0, 1]
  std::vector<double> strain_energy;     // energy density driving eigenerosion, J/m^3 of reference volume
  std::vector<double> ductile_work;      // plastic work above the triaxiality cut-off, J/m^3 of reference volume
  std::vector<double> viscous_pressure;  // artificial bulk viscosity q, Pa (part of stress)
  // Christensen's limiter phi in [0, 1] of the step's compression (docs/theory.md §5): 1 where the
  // compression is smooth over the point's support, 0 in a shock; the viscosity acts on the rest.
  // Set by the discretisation every step before the material update.
  std::vector<double> viscosity_limiter;
  // The volume strain the averaging took away: over the steps, the sum of tr(dF - I) less its patch
  // average (volume averaging; docs/theory.md §4). Drives the stabilisation pressure.
  std::vector<double> volume_defect;
  std::vector<Mat3> be;  // elastic left Cauchy-Green tensor (plasticity)
  // 1 once the point has broken (eigenerosion, damage or spall): no strength, no tension; failed(p)
  // while it stays in its body, debris(p) once released (stored and written as "eroded").
  std::vector<std::uint8_t> broken;
  // 1 once the point belongs to no fragment although its material is intact: an SPH element failed
  // by its distortion (docs/theory.md §10), whose reconstructed shape no longer says which
  // neighbours it holds on to. The laws see intact material; the fragment analysis, free mass.
  std::vector<std::uint8_t> loose;
  // Debris contact (solver/common/debris_contact.hpp), for broken points: bit b set if body b cannot stop
  // the point (its own body and the bodies that body touched when it was released; 0 before),
  // and the body whose nodes carry it: its own while it is failed but not yet released, none once
  // it is debris, -1 if it has struck no body yet, -2 - b after it last struck body b.
  std::vector<std::int64_t> passes_through;
  std::vector<std::int32_t> carrier;
  LocalIndex owned = 0;

  // Every array, once: visit(name, array, value of a new entry). Store is PointStore, const or not.
  template <class Store, class Visit>
  static void fields(Store& s, Visit&& visit) {
    const Vec3 zero = Vec3::Zero();
    const Mat3 identity = Mat3::Identity();
    visit("id", s.id, Index{0});
    visit("body", s.body, std::int32_t{0});
    visit("x", s.x, zero);
    visit("v", s.v, zero);
    visit("mass", s.mass, 0.0);
    visit("volume", s.volume, 0.0);
    visit("volume0", s.volume0, 0.0);
    visit("spacing0", s.spacing0, 0.0);
    visit("F", s.F, identity);
    visit("dF", s.dF, identity);
    visit("stress", s.stress, Mat3::Zero().eval());
    visit("energy", s.energy, 0.0);
    visit("sound_speed", s.sound_speed, 0.0);
    visit("plastic_strain", s.plastic_strain, 0.0);
    visit("temperature", s.temperature, 0.0);
    visit("damage", s.damage, 0.0);
    visit("strain_energy", s.strain_energy, 0.0);
    visit("ductile_work", s.ductile_work, 0.0);
    visit("viscous_pressure", s.viscous_pressure, 0.0);
    visit("viscosity_limiter", s.viscosity_limiter, 0.0);
    visit("volume_defect", s.volume_defect, 0.0);
    visit("be", s.be, identity);
    visit("eroded", s.broken, std::uint8_t{0});
    visit("loose", s.loose, std::uint8_t{0});
    visit("passes_through", s.passes_through, std::int64_t{0});
    visit("carrier", s.carrier, std::int32_t{-1});
  }
  static constexpr int field_count = 26;

  LocalIndex size() const { return static_cast<LocalIndex>(x.size()); }
  void resize(std::size_t n);
  // Reorders every array: new index i holds what old index order[i] held (order: a permutation).
  void permute(const std::vector<LocalIndex>& order);
  double density(LocalIndex p) const { return mass[p] / volume[p]; }
  // The states of a point (docs/theory.md §8): intact; failed, still part of its body, bearing
  // compression only (no strength, no tension: fractured material under pressure); debris,
  // released once it bears no compression: ballistic, pushed back by the bodies it strikes.
  bool failed(LocalIndex p) const { return broken[p] && carrier[p] == body[p]; }
  bool debris(LocalIndex p) const { return broken[p] && carrier[p] != body[p]; }
  // In no fragment: broken, or loose (its material intact).
  bool unlinked(LocalIndex p) const { return broken[p] || loose[p]; }
  // An intact point fails: it stays in its body until the integrator releases it.
  void fail(LocalIndex p) {
    broken[p] = 1;
    carrier[p] = body[p];
  }
  // Debris point p strikes body b (solver/common/debris_contact.hpp); the last body it struck, -1 if none.
  void strike(LocalIndex p, int b) { carrier[p] = -2 - b; }
  int lastStruck(LocalIndex p) const { return carrier[p] <= -2 ? -2 - carrier[p] : -1; }
  // Current support size: the reference spacing scaled with the volume change.
  double spacing(LocalIndex p) const;
};

// A body: a name and one material. Its points (and a method's nodes) are those whose `body` is its
// index, wherever they sit in the store: a process holds any subset, in any order.
struct BodyInfo {
  std::string name;
  int material = 0;
  // Bodies it has been in contact with so far, its own included (bit b: body b; the first 64
  // bodies): what its debris passes through (solver/common/debris_contact.hpp).
  std::uint64_t touched = 0;
};

// Calls f(p) for each owned point of body `body`, in store order.
template <class F>
void forEachPointOf(const PointStore& points, int body, F&& f) {
  for (LocalIndex p = 0; p < points.owned; ++p)
    if (points.body[p] == body) f(p);
}

// Where each id of a store's entries (all of them, ghosts included) sits: a table by id while the
// ids are compact, a sorted list otherwise (a process holding a few points of a large run, or a
// damaged file). Throws if an id is negative or appears twice.
class IdIndex {
 public:
  explicit IdIndex(std::span<const Index> ids);
  // The entry holding `id`, -1 if none does.
  LocalIndex find(Index id) const;

 private:
  std::vector<LocalIndex> by_id_;
  std::vector<std::pair<Index, LocalIndex>> sorted_;
};

// Entries [begin, end) of a store.
struct IndexRange {
  LocalIndex begin = 0, end = 0;
};

// The range each body's entries take among the first `count` of `body`, for a method that keeps
// each body's entries together (OTM, which updates materials body by body): ranges[b] is empty
// for a body without entries. Throws naming the entry if a body's entries are not contiguous.
std::vector<IndexRange> bodyRanges(std::span<const std::int32_t> body, LocalIndex count, std::size_t bodies);

}  // namespace kessler
