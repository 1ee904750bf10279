#pragma once
// Debris capture (docs/theory.md §9). Debris (failed material released from its body,
// solver/otm/release.hpp) carries no stress and flies ballistically until it reaches a body it may
// hit: then it joins that body's nodes (Neighbourhoods), is carried by them and loads them with
// its mass and momentum, and is released to fly on when it leaves their hull (a perforated wall).
// It may not hit its own body, nor a body its body was in contact with when it was released: the
// debris of a projectile breaking up in a bumper passes through the bumper's hole, and the rear
// wall behind is loaded by the debris cloud.
#include "solver/otm/model.hpp"

#include <span>

namespace kessler::otm {

// Debris capture needs one bit per body; a model with more bodies keeps all debris ballistic.
constexpr std::size_t max_capturing_bodies = 64;

// Marks the points released as debris since the last call (passes_through still 0) with the
// bodies they pass through: those their body has touched so far (BodyInfo::touched).
void markNewDebris(Model& model);

// Adds the contacts seen by a neighbour search to BodyInfo::touched, both ways: touching[a] has
// bit b set if nodes of body b lie in the rows of intact points of body a.
void recordContacts(Model& model, std::span<const std::uint64_t> touching);

// The inelastic impact of debris points caught this step (in point order; their rows are over
// the nodes of the catching body). Each takes the velocity interpolated from those nodes; the
// momentum it loses goes, through the same nodes, to the points of the body that share them (each node
// hands its share N m (v - v_nodes) to its points in proportion to N m), so momentum is exact;
// the kinetic energy this dissipates becomes internal energy of the debris point. Returns the
// energy dissipated (J).
double catchDebris(Model& model, std::span<const LocalIndex> caught);

}  // namespace kessler::otm
