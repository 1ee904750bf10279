#pragma once
// The neighbourhood part of the OTM step (docs/theory.md §2-4): each material point's node
// neighbourhood from a cell-list search, with the seizing-contact policy across bodies, and the
// LME shape functions there. Results go to Model::connectivity in point order, identical for any
// thread count.
#include "approx/lme.hpp"
#include "search/cell_list.hpp"
#include "solver/common/contact.hpp"
#include "solver/common/own_sums.hpp"
#include "solver/otm/model.hpp"
#include "solver/otm/settings.hpp"

#include <span>
#include <vector>

namespace kessler::otm {

class Neighbourhoods {
 public:
  explicit Neighbourhoods(const Settings& settings) : settings_(settings) {}

  // Rebuilds the connectivity of all points held. Throws NumericalError naming the point if
  // its shape functions cannot be built (outside the convex hull of its nodes, no nodes). In a
  // distributed run (`share`, `node_share`: the rank's own points and nodes, and the ranks; collective), the cell sizes
  // are agreed by all ranks, only own points count and throw, and the bodies' contact records join every rank's; if any
  // own point's search went beyond `halo_radius` (what the halo holds), the model is left as it was (the multipliers
  // restored, no point torn) and it returns false: search again with a halo of at least largestRadius(). Points
  // with a 0 in `searched` (if given: ghosts whose rows no own node needs) get no row, as debris.
  bool update(Model& model, const Share& share = {}, const Share& node_share = {}, double halo_radius = 0.0,
              std::span<const std::uint8_t> searched = {});

  // Time spent in the search and in the shape functions during the last update.
  double searchSeconds() const { return search_seconds_; }
  double shapeSeconds() const { return shape_seconds_; }
  // Intact points released so far because they lay outside the hull of every neighbourhood tried
  // (torn from their body; retryPoints), and their mass.
  LocalIndex tornPoints() const { return torn_; }
  // A distributed run: the largest radius any point's search reached in the last update (its cut-off
  // radius, widened where it found too few nodes or its shape functions failed), over every rank.
  double largestRadius() const { return largest_radius_; }
  double tornMass() const { return torn_mass_; }

 private:
  struct Scratch {
    std::vector<LocalIndex> node;  // neighbours of the point being processed: visible first
    std::size_t visible = 0;       // how many of them are visible
    std::vector<LocalIndex> rows;  // neighbours of all points of this thread, in order
    // Points of this thread whose shape functions failed or are ill-conditioned, with the
    // smallest variance of their first attempt (lme::Result::covariance; -1 if it failed).
    std::vector<std::pair<LocalIndex, double>> retry;
    std::vector<double> N;  // shape functions of retried points
    std::vector<Vec3> dN;
    SeizingProbe contact;
    double radius = 0.0;  // how far the last gather() searched
    std::vector<Vec3> offsets;
    std::vector<Vec3> occluders;  // eroded points near the point being processed
  };

  // Collects the neighbour nodes of point p within `scale` times its cut-off radius into
  // s.node; returns their count. With `visibility`, nodes hidden behind eroded points (see
  // hidden()) go to the end of the list, after the s.visible visible ones.
  int gather(const Model& model, LocalIndex p, double scale, bool visibility, Scratch& s) const;
  // Visibility across cracks: node position xa is hidden from point p when the segment between
  // them crosses eroded material, i.e. a sample on it lies nearer an eroded point (of
  // s.occluders, within `spacing`) than any intact one. collectOccluders: the eroded points
  // within `radius` of xp, into s.occluders (none: nothing is hidden).
  void collectOccluders(const Vec3& xp, int body, double radius, Scratch& s) const;
  bool hidden(const Vec3& xp, const Vec3& xa, double spacing, const Scratch& s) const;
  // The points that decide visibility: the intact ones, and the eroded ones within `reach` of
  // them (debris further away hides nothing).
  void buildOccluders(const Model& model, double reach);
  // LME shape functions of point p over the nodes `row` (warm-started from its lambda), with
  // support size h and locality gamma_scale times the settings' gamma.
  lme::Result shapeFunctionsAt(Model& model, LocalIndex p, std::span<const LocalIndex> row, std::span<double> N,
                               std::span<Vec3> dN, Scratch& s, double h, double gamma_scale = 1.0) const;
  // Retries the points whose shape functions failed or are ill-conditioned with larger radii and
  // smoother supports; an intact point outside the hull of every attempt is torn (fails and is
  // released); throws if an intact point's shape functions still fail otherwise.
  // What the retries change in the points once the search is kept (apply()), and the first own
  // point whose shape functions failed.
  struct Pending {
    std::vector<LocalIndex> torn;      // intact points torn from their body
    std::vector<LocalIndex> released;  // failed points leaving their body (zero rows)
    LocalIndex failed = -1;
    lme::Result failure;
  };
  Pending retryPoints(Model& model, const Share& share);
  // Applies the retries' changes, and throws on every rank if an own point's shape functions failed.
  void apply(Model& model, const Share& share, const Pending& pending);

  Settings settings_;
  CellList cells_;
  CellList eroded_cells_, intact_cells_;
  std::vector<Vec3> eroded_x_, intact_x_;
  std::vector<int> eroded_body_;
  std::vector<Scratch> scratch_;  // one per thread
  std::vector<int> count_;
  std::vector<int> visible_;              // per point: the first visible_ nodes of its row are visible
  std::vector<int> chunk_thread_;         // per chunk of points: the thread that searched it
  std::vector<std::size_t> chunk_start_;  // and where its node lists start in that thread's rows
  std::vector<std::uint32_t> transpose_scratch_;
  std::vector<double> spacing_;      // per point: its support size h this step (a cube root each)
  double cutoff_per_spacing_ = 0.0;  // the LME cut-off radius over h (a logarithm and a root)
  double search_seconds_ = 0.0, shape_seconds_ = 0.0;
  LocalIndex torn_ = 0;
  std::vector<double> radius_;       // per point: how far its search reached
  double largest_radius_ = 0.0;      // over every rank's own points (a distributed run)
  std::vector<Vec3> lambda_before_;  // a distributed run: the multipliers before the search
  double torn_mass_ = 0.0;
};

}  // namespace kessler::otm
