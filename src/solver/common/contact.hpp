#pragma once
// Contact between bodies, as every particle method sees it (docs/theory.md §3, §9).
//
// Seizing contact: a point takes the carriers of another body (OTM: its nodes; a particle method:
// its particles) into its neighbourhood only once that body's nearest carrier lies within the
// contact distance of it. From then on the two bodies interact through shared carriers, as one
// body: they stick. SeizingProbe applies that rule to the candidates a search found for one point
// and records which bodies touched (BodyInfo::touched), which debris contact needs.
//
// The other kind, a sliding contact on the bodies' surfaces, is solver/common/sliding_contact.hpp.
#include "parallel/communicator.hpp"
#include "solver/common/particle_state.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace kessler {

// Contacts are recorded as one bit per body; a problem with more bodies records none, and all its
// debris stays ballistic (solver/common/debris_contact.hpp).
constexpr std::size_t max_contact_bodies = 64;

inline std::uint64_t bodyBit(int body) {
  return std::uint64_t{1} << body;
}

// One thread's seizing-contact filter, for one point at a time.
class SeizingProbe {
 public:
  // For a problem of `bodies` bodies, before a search over all points.
  void reset(std::size_t bodies) {
    nearest_.resize(bodies);
    touching_.assign(bodies <= max_contact_bodies ? bodies : 0, 0);
  }
  // Before the candidates of one point are seen.
  void start() {
    std::fill(nearest_.begin(), nearest_.end(), std::numeric_limits<double>::infinity());
    foreign_ = false;
  }
  // A candidate of body `body` at squared distance d2 from a point of body `own`.
  void see(int own, int body, double d2) {
    if (body == own) return;
    foreign_ = true;
    nearest_[static_cast<std::size_t>(body)] = std::min(nearest_[static_cast<std::size_t>(body)], d2);
  }
  // Drops from `candidates` the carriers of every other body whose nearest carrier lies beyond
  // `reach2` (squared), and records the bodies within it as touching `own`. body_of: the carriers'
  // bodies.
  void settle(std::vector<LocalIndex>& candidates, std::span<const int> body_of, int own, double reach2) {
    if (foreign_)
      candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                      [&](LocalIndex a) {
                                        const int b = body_of[a];
                                        return b != own && nearest_[static_cast<std::size_t>(b)] > reach2;
                                      }),
                       candidates.end());
    if (touching_.size() == nearest_.size())
      for (std::size_t b = 0; b < touching_.size(); ++b)
        if (nearest_[b] <= reach2) touching_[static_cast<std::size_t>(own)] |= std::uint64_t{1} << b;
  }
  // Adds to `touching` (per body) the bodies whose carriers its points took since reset().
  void addTouching(std::span<std::uint64_t> touching) const {
    for (std::size_t b = 0; b < touching_.size() && b < touching.size(); ++b) touching[b] |= touching_[b];
  }

 private:
  std::vector<double> nearest_;          // squared distance per body
  std::vector<std::uint64_t> touching_;  // per body
  bool foreign_ = false;
};

// Adds the contacts a search saw (SeizingProbe::addTouching, over its probes) to
// BodyInfo::touched, both ways: a body touches itself and every body whose carriers its points
// took (bit b of touching[a]), and those touch it.
void recordContacts(ParticleState& state, std::span<const std::uint64_t> touching);
// Every rank's records of BodyInfo::touched joined (a distributed run: each rank sees the contacts
// of its own points). Collective.
void joinContacts(std::vector<BodyInfo>& bodies, const parallel::Communicator& comm);

// Marks the points released as debris since the last call (passes_through still 0) with the
// bodies they pass through: their own, and those their body has touched so far.
void markNewDebris(ParticleState& state);

}  // namespace kessler
