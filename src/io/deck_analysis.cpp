// The `analysis` section of the deck (docs/deck.md, docs/analysis.md): which bodies are the
// projectile and the plates of an impact, and the options of the end-of-run measurements. What
// the deck leaves out is inferred from the bodies; impossible geometries (a plate behind the
// projectile, a shot line that misses a plate) are errors at the key that causes them.
#include "io/deck_parts.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace kessler::io {

namespace {

// Bodies moving at least this fraction of the fastest body's speed are the projectile.
constexpr double projectile_speed_fraction = 0.5;

int bodyIndex(const Field& field, const std::vector<BodyConfig>& bodies) {
  const std::string name = field.text("a body name");
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].name == name) return static_cast<int>(i);
  std::vector<std::string> known;
  for (const BodyConfig& body : bodies) known.push_back(body.name);
  field.fail(fmt::format("unknown body (bodies: {})", fmt::join(known, ", ")));
}

// A body name or a list of them.
std::vector<int> bodyList(const Field& field, const std::vector<BodyConfig>& bodies) {
  std::vector<int> list;
  if (!field.node().IsSequence()) return {bodyIndex(field, bodies)};
  for (const Field& item : field.list()) {
    const int b = bodyIndex(item, bodies);
    if (std::find(list.begin(), list.end(), b) != list.end()) item.fail("is listed twice");
    list.push_back(b);
  }
  if (list.empty()) field.failBare("must name at least one body");
  return list;
}

// Where a body starts: the centre of its bounding box (an imported mesh has none: nullopt).
std::optional<Vec3> bodyCentre(const BodyConfig& body) {
  const geometry::BoundingBox box = geometry::bounds(body.mesh.shape);
  if (box.empty()) return std::nullopt;
  return 0.5 * (box.min + box.max);
}

bool isBox(const BodyConfig& body) {
  return std::holds_alternative<geometry::Box>(body.mesh.shape);
}

// Why body b cannot be a plate of a shot from `start` along unit `e`: not a box, the projectile,
// parallel to the shot, behind the projectile, or off the shot line. Empty when it can.
std::string plateProblem(const std::vector<BodyConfig>& bodies, const std::vector<int>& projectiles, int b,
                         const Vec3& e, const Vec3& start) {
  const BodyConfig& body = bodies[static_cast<std::size_t>(b)];
  if (std::find(projectiles.begin(), projectiles.end(), b) != projectiles.end())
    return fmt::format("body '{}' is the projectile", body.name);
  if (body.velocity.norm() > 0.0) return fmt::format("body '{}' moves: a plate is at rest", body.name);
  if (!isBox(body))
    return fmt::format("body '{}' is a {}: a plate must be a box", body.name, geometry::kindName(body.mesh.shape));
  const auto& box = std::get<geometry::Box>(body.mesh.shape);
  const Vec3 extent = box.max - box.min;
  int thin = 0;
  for (int d = 1; d < 3; ++d)
    if (extent[d] < extent[thin]) thin = d;
  if (std::abs(e[thin]) < 1e-3) return fmt::format("the shot direction runs parallel to plate '{}'", body.name);
  const Vec3 centre = *bodyCentre(body);
  if (e.dot(centre - start) <= 0.0)
    return fmt::format("plate '{}' lies behind the projectile: the shot moves away from it", body.name);
  // Where the shot line crosses the plate's mid-plane: it must fall on the plate.
  const Vec3 hit = start + e * ((centre[thin] - start[thin]) / e[thin]);
  for (int d = 0; d < 3; ++d)
    if (d != thin && (hit[d] < box.min[d] || hit[d] > box.max[d]))
      return fmt::format(
          "the shot line misses plate '{}': it crosses the plate's plane at ({:.4g}, {:.4g}, "
          "{:.4g}) mm, outside the plate",
          body.name, 1e3 * hit[0], 1e3 * hit[1], 1e3 * hit[2]);
  return {};
}

// The bodies that can be plates of the shot, in the order of their centres along it.
std::vector<int> inferPlates(const std::vector<BodyConfig>& bodies, const std::vector<int>& projectiles, const Vec3& e,
                             const Vec3& start) {
  std::vector<int> plates;
  for (int b = 0; b < static_cast<int>(bodies.size()); ++b)
    if (plateProblem(bodies, projectiles, b, e, start).empty()) plates.push_back(b);
  std::sort(plates.begin(), plates.end(),
            [&](int a, int b) { return e.dot(*bodyCentre(bodies[a])) < e.dot(*bodyCentre(bodies[b])); });
  return plates;
}

// The deck's plates: each one a plate of the shot, listed in the order the shot meets them.
// Without a start (a projectile from a mesh file) only the plates' shapes are checked.
void checkPlates(const AnalysisConfig& a, const std::vector<BodyConfig>& bodies, const std::optional<Vec3>& start,
                 const Field& plates_field) {
  const std::vector<Field> items = plates_field.node().IsSequence() ? plates_field.list() : std::vector<Field>{};
  double previous = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.plates.size(); ++i) {
    const Field& at = items.empty() ? plates_field : items[i];
    const BodyConfig& body = bodies[static_cast<std::size_t>(a.plates[i])];
    if (!start) {
      if (!isBox(body))
        at.fail(
            fmt::format("body '{}' is a {}: a plate must be a box", body.name, geometry::kindName(body.mesh.shape)));
      continue;
    }
    const std::string problem = plateProblem(bodies, a.projectiles, a.plates[i], a.shot_direction, *start);
    if (!problem.empty()) at.fail(problem);
    const double along = a.shot_direction.dot(*bodyCentre(body));
    if (along < previous) at.fail("the plates must be listed in the order the shot line meets them");
    previous = along;
  }
}

void parseRearWall(const Field& field, AnalysisConfig& a) {
  MapField map = field.map({"yield_stress", "brinell_hardness", "sound_speed"});
  a.wall_given = true;
  if (std::optional<Field> f = map.find("yield_stress")) a.wall_yield_stress = f->positive(units::pressure);
  if (std::optional<Field> f = map.find("brinell_hardness"))
    a.wall_brinell_hardness = f->positive(units::dimensionless);
  if (std::optional<Field> f = map.find("sound_speed")) a.wall_sound_speed = f->positive(units::velocity);
}

}  // namespace

AnalysisConfig parseAnalysis(const std::optional<Field>& field, const std::vector<BodyConfig>& bodies,
                             const Field& bodies_field) {
  AnalysisConfig a;
  std::optional<MapField> map;
  if (field)
    map = field->map(
        {"enabled", "projectile", "plates", "shot_direction", "cloud_reference", "link_stretch", "plots", "rear_wall"});
  auto find = [&](std::string_view key) { return map ? map->find(key) : std::nullopt; };
  if (std::optional<Field> enabled = find("enabled")) a.enabled = enabled->boolean();
  if (std::optional<Field> plots = find("plots")) a.plots = plots->boolean();
  if (std::optional<Field> stretch = find("link_stretch")) {
    a.link_stretch = stretch->quantity(units::dimensionless);
    if (!(a.link_stretch > 1.0)) stretch->fail("must exceed 1 (a link breaks when stretched beyond this factor)");
  }
  if (std::optional<Field> wall = find("rear_wall")) parseRearWall(*wall, a);
  if (!a.enabled) return a;

  // The projectile: named, else the bodies moving at least half as fast as the fastest one.
  const std::optional<Field> projectile = find("projectile");
  if (projectile) {
    a.projectiles = bodyList(*projectile, bodies);
  } else {
    double fastest = 0.0;
    for (const BodyConfig& body : bodies) fastest = std::max(fastest, body.velocity.norm());
    for (int b = 0; b < static_cast<int>(bodies.size()); ++b)
      if (fastest > 0.0 && bodies[b].velocity.norm() >= projectile_speed_fraction * fastest) a.projectiles.push_back(b);
  }
  const Field& where = projectile ? *projectile : (field ? *field : bodies_field);
  if (a.projectiles.empty()) {
    if (field)
      field->failBare(
          "no body moves, so there is no projectile to analyse: name one with "
          "analysis.projectile or set analysis.enabled: false");
    a.enabled = false;  // nothing moves: not an impact
    return a;
  }
  const BodyConfig& lead = bodies[static_cast<std::size_t>(a.projectiles.front())];
  // The speed and direction of the shot are relative to the target: the first body that is not a
  // projectile (at rest in a shield deck; moving in a collision of two satellites).
  Vec3 target_velocity = Vec3::Zero();
  for (int b = 0; b < static_cast<int>(bodies.size()); ++b)
    if (std::find(a.projectiles.begin(), a.projectiles.end(), b) == a.projectiles.end()) {
      target_velocity = bodies[static_cast<std::size_t>(b)].velocity;
      break;
    }
  const Vec3 relative = lead.velocity - target_velocity;
  a.impact_speed = relative.norm();
  if (!(a.impact_speed > 0.0))
    where.failBare(
        fmt::format("the projectile '{}' does not move relative to the target: nothing to analyse", lead.name));

  if (std::optional<Field> direction = find("shot_direction")) {
    const Vec3 d = direction->vector(units::dimensionless);
    if (!(d.norm() > 0.0)) direction->fail("must not be zero");
    a.shot_direction = d.normalized();
  } else {
    a.shot_direction = relative.normalized();
  }
  const std::optional<Vec3> start = bodyCentre(lead);

  const std::optional<Field> plates = find("plates");
  if (plates) {
    a.plates = bodyList(*plates, bodies);
  } else if (start) {
    a.plates = inferPlates(bodies, a.projectiles, a.shot_direction, *start);
  }
  if (a.plates.empty()) {
    if (field && plates) plates->failBare("must name at least one plate");
    // No plate: a collision of bodies (two satellites, or a projectile against an imported mesh)
    // gets the fragments and the breakup model, without holes, clouds or a rear wall. A body on
    // its own (a Taylor bar) has nothing to analyse.
    if (bodies.size() < 2) a.enabled = false;
    return a;
  }
  if (plates) checkPlates(a, bodies, start, *plates);

  if (std::optional<Field> reference = find("cloud_reference")) {
    const int b = bodyIndex(*reference, bodies);
    auto found = std::find(a.plates.begin(), a.plates.end(), b);
    if (found == a.plates.end()) reference->fail("must be one of the plates");
    a.cloud_reference = static_cast<int>(found - a.plates.begin());
  }
  return a;
}

}  // namespace kessler::io
