#pragma once
// Fragments: the connected components of intact material over the initial mesh adjacency, as
// in the finite-element-reconstruction approach to breakup (fragments are the pieces of the
// original mesh that still hold together). Eroded points are debris below the resolution and
// are reported per body as mass only. See docs/analysis.md for the definitions.
#include "analysis/symmetry.hpp"
#include "core/types.hpp"
#include "solver/common/particle_state.hpp"

#include <array>
#include <vector>

namespace kessler::analysis {

struct FragmentOptions {
  // A link between two face-adjacent points breaks when its length exceeds this factor times
  // its initial length: material that separated without eroding (spall, a sheared plug) splits.
  // 2.5 lets compressed or sheared but continuous material (a link rarely stretches beyond
  // ~1.5 while the material still holds) stay whole, and splits pieces that have opened a gap
  // larger than about one point spacing.
  double link_stretch = 2.5;
  std::vector<int> symmetry_axes;  // mirror planes of a half/quarter model (0 = x, 1 = y, 2 = z)
};

struct Fragment {
  int body = 0;
  int material = 0;
  LocalIndex points = 0;            // simulated points (not counting mirror images)
  LocalIndex first_point = 0;       // smallest point index: a stable identity
  int copies = 1;                   // copies in the full model: mirror images of a fragment off the planes
  double mass = 0.0;                // kg, one copy, halves across a symmetry plane joined
  double volume = 0.0;              // m^3, current
  Vec3 centre = Vec3::Zero();       // centre of mass, m
  Vec3 velocity = Vec3::Zero();     // centre-of-mass velocity, m/s
  double speed = 0.0;               // |velocity|
  std::array<double, 3> extents{};  // m, largest first (see characteristicLength)
  Vec3 axis = Vec3::UnitX();        // direction of the largest extent
  double lc = 0.0;                  // characteristic length, m: mean of the three extents
  double area = 0.0;                // NASA average cross-section A(Lc), m^2
};

struct FragmentSet {
  std::vector<Fragment> fragments;  // by mass, largest first (ties: first_point)
  std::vector<LocalIndex> label;    // per point: index into fragments, -1 if eroded or loose
  std::vector<Index> point_id;      // per point: its id (PointStore::id), to find it in the outputs
  std::vector<double> eroded_mass;  // per body, kg in the full model: sub-resolution debris (eroded or loose)
  std::vector<double> body_mass;    // per body, kg in the full model
  double link_stretch = 0.0;
  LocalIndex links = 0, broken_links = 0;
  bool reference_lengths = false;  // false: initial link lengths estimated from the spacing

  // Number of fragments in the full model (mirror copies counted).
  long count() const;
};

// The initial length of every link of model.adjacency. Call right after the model is built
// (before the first step) and pass the result to findFragments.
std::vector<double> referenceLinkLengths(const ParticleState& model);

// Connected components of the intact points. `reference_lengths` are the initial link lengths
// (referenceLinkLengths); if empty they are estimated as 0.4 (h_i + h_j)/2 from the initial
// spacings, the barycentre distance of two face-adjacent near-regular tets (0.41 h).
// Deterministic: the union-find runs over the links in their stored order.
FragmentSet findFragments(const ParticleState& model, const std::vector<double>& reference_lengths,
                          const FragmentOptions& options);

// Lc of a set of positions with total volume `volume` and `count` points: the extents (max -
// min of the positions plus the mean point size (volume/count)^(1/3)) along the principal axes
// of their second moments, or along x, y, z, whichever box is tighter (smaller sum). Extents
// are returned largest first.
struct Shape3 {
  std::array<double, 3> extents{};
  Vec3 axis = Vec3::UnitX();
  double lc = 0.0;
};
Shape3 characteristicLength(const std::vector<Vec3>& positions, const std::vector<double>& weights, double volume,
                            long count);

// The cumulative distribution N(>=Lc): one entry per fragment, Lc descending, count including
// mirror copies.
struct CumulativeCount {
  double lc = 0.0;
  long count = 0;
};
std::vector<CumulativeCount> cumulativeDistribution(const FragmentSet& set);

}  // namespace kessler::analysis
