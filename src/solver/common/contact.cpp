#include "solver/common/contact.hpp"

#include "core/error.hpp"

#include <cstring>

namespace kessler {

void recordContacts(ParticleState& state, std::span<const std::uint64_t> touching) {
  const std::size_t bodies = state.bodies.size();
  if (bodies > max_contact_bodies) return;
  for (std::size_t a = 0; a < bodies; ++a) {
    state.bodies[a].touched |= bodyBit(static_cast<int>(a));
    for (std::size_t b = 0; b < bodies; ++b)
      if ((touching[a] >> b) & 1u) {
        state.bodies[a].touched |= bodyBit(static_cast<int>(b));
        state.bodies[b].touched |= bodyBit(static_cast<int>(a));
      }
  }
}

void joinContacts(std::vector<BodyInfo>& bodies, const parallel::Communicator& comm) {
  if (comm.size() == 1) return;
  std::vector<std::uint64_t> mine(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) mine[b] = bodies[b].touched;
  for (const std::vector<std::byte>& theirs : comm.allGather(std::as_bytes(std::span<const std::uint64_t>(mine)))) {
    KESSLER_VERIFY(theirs.size() == mine.size() * sizeof(std::uint64_t), "contact records of {} bytes for {} bodies",
                   theirs.size(), mine.size());
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, theirs.data() + b * sizeof bits, sizeof bits);
      bodies[b].touched |= bits;
    }
  }
}

void markNewDebris(ParticleState& state) {
  PointStore& points = state.points;
  const bool contact = state.bodies.size() <= max_contact_bodies;
  for (LocalIndex p = 0; p < points.owned; ++p) {
    if (!points.debris(p) || points.passes_through[p] != 0) continue;
    const BodyInfo& body = state.bodies[static_cast<std::size_t>(points.body[p])];
    const std::uint64_t bits = contact ? bodyBit(points.body[p]) | body.touched : ~std::uint64_t{0};
    points.passes_through[p] = static_cast<std::int64_t>(bits);
  }
}

}  // namespace kessler
