#include "solver/common/sliding_contact.hpp"

#include "search/cell_list.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace kessler {

namespace {

// A master triangle near a slave, at the step's positions.
struct Near {
  LocalIndex triangle = 0;
  Vec3 normal = Vec3::Zero();      // unit, out of the master body
  double depth = 0.0;              // the slave's height above the triangle's plane less the gaps (< 0: below)
  double longest = 0.0;            // the triangle's longest edge
  std::array<double, 3> weight{};  // barycentric coordinates of the slave's projection
  double distance = 0.0;           // from the slave to the triangle (infinite where it cannot be the nearest)
  bool over = false;               // the projection lies on the triangle
};

double segmentDistance(const Vec3& q, const Vec3& a, const Vec3& b) {
  const Vec3 e = b - a;
  const double t = std::clamp((q - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return (q - a - t * e).norm();
}

// The part of a change that a carrier's boundary leaves it (bit i of `held`: component i is held).
Vec3 freePart(Vec3 change, std::uint8_t held) {
  for (int axis = 0; axis < 3; ++axis)
    if ((held >> axis) & 1u) change[axis] = 0.0;
  return change;
}

// 1 / mass as the contact sees a carrier: a carrier held in every component does not move.
double inverseMass(const SlidingCarriers& c, LocalIndex a) {
  return (c.constrained[a] & 7u) == 7u ? 0.0 : 1.0 / c.mass[a];
}

}  // namespace

SlidingReport SlidingContact::apply(const ContactSurface& surface, const SlidingCarriers& c, std::size_t bodies) const {
  SlidingReport report;
  report.touching.assign(bodies <= 64 ? bodies : 0, 0);
  const auto& triangles = surface.triangles;
  if (triangles.empty() || surface.slaves.empty()) return report;
  const auto y = [&c](LocalIndex a) -> Vec3 { return c.x[a] + c.du[a]; };

  // The triangles binned by their centroids at the step's start positions plus displacement, each
  // body's apart (a slave looks only among the other bodies'); every point of a triangle lies within
  // its longest edge of its centroid.
  struct Binned {
    std::vector<Vec3> centre;
    std::vector<LocalIndex> triangle;
    CellList cells;
  };
  std::vector<Binned> binned;
  std::vector<double> radius(triangles.size());  // the farthest vertex from the centroid
  double longest = 0.0, widest = 0.0;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& v = triangles[t];
    const Vec3 a = y(v[0]), b = y(v[1]), d = y(v[2]);
    const auto body = static_cast<std::size_t>(c.body[v[0]]);
    if (binned.size() <= body) binned.resize(body + 1);
    const Vec3 centre = (a + b + d) / 3.0;
    binned[body].centre.push_back(centre);
    binned[body].triangle.push_back(static_cast<LocalIndex>(t));
    longest = std::max({longest, (b - a).norm(), (d - b).norm(), (a - d).norm()});
    radius[t] = std::max({(a - centre).norm(), (b - centre).norm(), (d - centre).norm()});
    widest = std::max(widest, radius[t]);
  }
  if (!(longest > 0.0)) return report;
  for (Binned& b : binned)
    if (!b.centre.empty()) b.cells.build(b.centre, static_cast<LocalIndex>(b.centre.size()), longest);
  // Only triangles within `decisive` of a slave decide what it meets. A face contact lies within
  // the larger of its triangle's longest edge and the two gaps (at most twice the largest gap, the
  // barycentric weights summing to one), an edge contact's vertex within the longest edge, and
  // the triangles around that vertex contain it. Where none lies so near, the slave meets
  // nothing, whichever triangles farther off are found. A triangle lies no nearer than its
  // centroid's distance less its radius; the others are passed over unevaluated, and the rest
  // are met in the same order, so the choice is the same as among every triangle within two
  // longest edges of the slave, the reach that bounds the search.
  double gap = 0.0;
  for (const double g : c.gap) gap = std::max(gap, g);
  const double decisive = std::max(longest, 2.0 * gap) * (1.0 + 1e-9);
  const double reach = std::min(2.0 * longest, decisive + widest);

  // The slaves that may meet another body's triangle: within reach of that body's triangles' box,
  // with a margin of two longest edges for what the corrections move. The others are passed over in
  // every visit.
  std::vector<std::pair<Vec3, Vec3>> box;  // per body
  for (const auto& v : triangles)
    for (const LocalIndex a : v) {
      const auto b = static_cast<std::size_t>(c.body[a]);
      if (box.size() <= b)
        box.resize(b + 1, {Vec3::Constant(std::numeric_limits<double>::infinity()),
                           Vec3::Constant(-std::numeric_limits<double>::infinity())});
      box[b].first = box[b].first.cwiseMin(y(a));
      box[b].second = box[b].second.cwiseMax(y(a));
    }
  const double margin = reach + 2.0 * longest;
  std::vector<LocalIndex> slaves;
  for (const LocalIndex s : surface.slaves) {
    if (!(c.mass[s] > 0.0)) continue;
    const Vec3 ys = y(s);
    for (std::size_t b = 0; b < box.size(); ++b) {
      if (static_cast<std::int32_t>(b) == c.body[s]) continue;
      const Vec3 outside = (box[b].first - ys).cwiseMax(ys - box[b].second).cwiseMax(0.0);
      if (outside.norm() <= margin) {
        slaves.push_back(s);
        break;
      }
    }
  }

  std::vector<Near> near;
  for (int visit = 0; visit < visits; ++visit) {
    const bool measure_only = visit == visits - 1;
    for (const LocalIndex s : slaves) {
      const Vec3 ys = y(s);
      near.clear();
      const auto visit_triangle = [&](LocalIndex t) {
        const auto& v = triangles[static_cast<std::size_t>(t)];
        for (const LocalIndex a : v)
          if (!(c.mass[a] > 0.0)) return;
        const Vec3 a = y(v[0]), b = y(v[1]), d = y(v[2]);
        Vec3 n = (b - a).cross(d - a);
        const double twice_area = n.norm();
        if (!(twice_area > 0.0)) return;
        n /= twice_area;
        Near item;
        item.triangle = t;
        item.normal = n;
        const double height = (ys - a).dot(n);
        item.longest = std::max({(b - a).norm(), (d - b).norm(), (a - d).norm()});
        const Vec3 p = ys - height * n;
        item.weight = {(b - p).cross(d - p).dot(n) / twice_area, (d - p).cross(a - p).dot(n) / twice_area,
                       (a - p).cross(b - p).dot(n) / twice_area};
        item.depth = c.gap.empty() ? height
                                   : height - (c.gap[s] + item.weight[0] * c.gap[v[0]] + item.weight[1] * c.gap[v[1]] +
                                               item.weight[2] * c.gap[v[2]]);
        item.over = *std::min_element(item.weight.begin(), item.weight.end()) >= -1e-12;
        item.distance = std::abs(height);  // the distance if over, else a lower bound of it
        near.push_back(item);
      };
      for (std::size_t b = 0; b < binned.size(); ++b)
        if (static_cast<std::int32_t>(b) != c.body[s] && !binned[b].centre.empty())
          binned[b].cells.forEachWithin(ys, reach, [&](LocalIndex i, double squared) {
            const LocalIndex t = binned[b].triangle[i];
            const double within = decisive + radius[static_cast<std::size_t>(t)];
            if (squared <= within * within) visit_triangle(t);
          });
      // A triangle the slave is not over lies at least its plane's distance away: one no nearer than a
      // triangle the slave is over cannot be the nearest (an over one wins a tie), and its distance to
      // the edges is not needed.
      double over_nearest = std::numeric_limits<double>::infinity();
      for (const Near& item : near)
        if (item.over) over_nearest = std::min(over_nearest, item.distance);
      for (Near& item : near) {
        if (item.over) continue;
        if (item.distance >= over_nearest) {
          item.distance = std::numeric_limits<double>::infinity();
          continue;
        }
        const auto& v = triangles[static_cast<std::size_t>(item.triangle)];
        const Vec3 a = y(v[0]), b = y(v[1]), d = y(v[2]);
        item.distance = std::min({segmentDistance(ys, a, b), segmentDistance(ys, b, d), segmentDistance(ys, d, a)});
      }
      if (near.empty()) continue;

      // The nearest master triangle decides (on ties, one the slave lies over): a face contact if the
      // slave is over it and below its plane, by less than its longest edge.
      const Near* closest = &near.front();
      for (const Near& item : near)
        if (item.distance < closest->distance || (item.distance == closest->distance && item.over && !closest->over))
          closest = &item;
      const Near* face =
          closest->over && closest->depth < 0.0 && closest->depth >= -closest->longest ? closest : nullptr;
      if (measure_only) {
        if (face != nullptr) report.deepest_remaining = std::max(report.deepest_remaining, -face->depth);
        continue;
      }
      const double inverse_s = inverseMass(c, s);
      if (face != nullptr) {
        const auto& v = triangles[static_cast<std::size_t>(face->triangle)];
        const Vec3& n = face->normal;
        double w = inverse_s;
        for (int i = 0; i < 3; ++i) w += face->weight[i] * face->weight[i] * inverseMass(c, v[i]);
        if (!(w > 0.0)) continue;  // slave and triangle all held
        // Back onto the triangle, the centre of mass kept.
        const double P = correct_positions_ ? -face->depth / w : 0.0;
        c.du[s] += freePart(P * inverse_s * n, c.constrained[s]);
        for (int i = 0; i < 3; ++i)
          c.du[v[i]] -= freePart(face->weight[i] * P * inverseMass(c, v[i]) * n, c.constrained[v[i]]);
        // Normal velocities equal where they approach; then Coulomb friction.
        const auto relative = [&]() {
          Vec3 at = Vec3::Zero();
          for (int i = 0; i < 3; ++i) at += face->weight[i] * c.v[v[i]];
          return Vec3(c.v[s] - at);
        };
        const auto push = [&](const Vec3& impulse) {
          c.v[s] += freePart(inverse_s * impulse, c.constrained[s]);
          for (int i = 0; i < 3; ++i)
            c.v[v[i]] -= freePart(face->weight[i] * inverseMass(c, v[i]) * impulse, c.constrained[v[i]]);
        };
        const double approach = relative().dot(n);
        if (approach < 0.0) {
          const double J = -approach / w;
          push(J * n);
          if (friction_ > 0.0) {
            const Vec3 r = relative();
            const Vec3 slip = r - r.dot(n) * n;
            const double speed = slip.norm();
            if (speed > 0.0) {
              const double Jt = std::min(friction_ * J, speed / w);
              push(-Jt / speed * slip);
            }
          }
        }
        ++report.face_contacts;
        report.met.emplace_back(s, c.body[v[0]]);
        if (!report.touching.empty()) {
          const auto mine = static_cast<std::size_t>(c.body[s]);
          report.touching[mine] |= std::uint64_t{1} << c.body[v[0]];
        }
        continue;
      }

      // An edge or vertex contact: inside every triangle around the nearest master vertex.
      if (closest->over) continue;
      LocalIndex m = -1;
      double nearest = std::numeric_limits<double>::infinity();
      for (const Near& item : near) {
        if (!(item.depth < 0.0)) continue;
        for (const LocalIndex a : triangles[static_cast<std::size_t>(item.triangle)]) {
          const double r = (y(a) - ys).norm();
          if (r < nearest) nearest = r, m = a;
        }
      }
      if (m < 0 || nearest > longest) continue;
      Vec3 normal = Vec3::Zero();
      bool inside = true, beneath = true;
      for (const Near& item : near) {
        const auto& v = triangles[static_cast<std::size_t>(item.triangle)];
        if (std::find(v.begin(), v.end(), m) == v.end()) continue;
        inside = inside && item.depth < 0.0;
        beneath = beneath && (ys - y(v[0])).dot(item.normal) < 0.0;
        normal += item.normal;
      }
      if (!inside || !(normal.norm() > 0.0)) continue;
      normal.normalize();
      // With gaps, the surface a slave meets beyond an edge or vertex is rounded: the planes pushed
      // out by the gaps meet in a square corner, which a particle ahead of a body's edge (a plate's,
      // beside a block sliding on it) lies inside without touching. Outside the body's own planes the
      // slave meets the vertex as a particle meets a particle, within the two gaps, along the line
      // between them.
      if (!c.gap.empty() && !beneath) {
        const Vec3 apart = ys - y(m);
        if (!(apart.norm() < c.gap[s] + c.gap[m])) continue;
        normal = apart.normalized();
      }
      const double vs = c.v[s].dot(normal), vm = c.v[m].dot(normal);
      if (!(vs - vm < 0.0)) continue;
      const double inverse_m = inverseMass(c, m);
      if (!(inverse_s + inverse_m > 0.0)) continue;
      // The momentum-weighted mean, a held side counting as infinitely heavy.
      const double mean = (inverse_m * vs + inverse_s * vm) / (inverse_s + inverse_m);
      c.v[s] += freePart((mean - vs) * normal, c.constrained[s]);
      c.v[m] += freePart((mean - vm) * normal, c.constrained[m]);
      ++report.edge_contacts;
      report.met.emplace_back(s, c.body[m]);
      if (!report.touching.empty())
        report.touching[static_cast<std::size_t>(c.body[s])] |= std::uint64_t{1} << c.body[m];
    }
  }
  return report;
}

}  // namespace kessler
