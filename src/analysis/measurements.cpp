#include "analysis/measurements.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace kessler::analysis {
namespace {

// The material of a plate projected onto its plane, every mirror image included: `slab_only`
// keeps the points inside the original thickness slab; `keep` selects the points (intact, of
// the wall's largest fragment, ...).
template <class Keep>
std::vector<Vec2> projectPlate(const ParticleState& model, const PlateSpec& plate, const PlaneFrame& frame,
                               const Mirror& mirror, bool slab_only, const Keep& keep) {
  std::vector<Vec2> projected;
  forEachPointOf(model.points, plate.body, [&](LocalIndex p) {
    if (!keep(p)) return;
    for (int mask = 0; mask < mirror.images(); ++mask) {
      const Vec3 x = mirror.image(model.points.x[p], mask);
      const double s = frame.normal.dot(x);
      if (slab_only && (s < plate.frontFace() || s > plate.rear_face)) continue;
      projected.push_back(frame.project(x));
    }
  });
  return projected;
}

}  // namespace

PlateSpec plateFromBox(int body, const geometry::Box& box, const Vec3& shot_direction) {
  const Vec3 extent = box.max - box.min;
  int thin = 2;
  for (int axis = 1; axis >= 0; --axis)
    if (extent[axis] < extent[thin]) thin = axis;
  PlateSpec plate;
  plate.body = body;
  plate.thickness = extent[thin];
  const bool forward = shot_direction[thin] >= 0.0;
  plate.normal = forward ? Vec3::Unit(thin) : Vec3(-Vec3::Unit(thin));
  plate.rear_face = forward ? box.max[thin] : -box.min[thin];
  return plate;
}

Vec3 shotLineHit(const Vec3& x0, const Vec3& direction, const Vec3& normal, double offset) {
  const double along = normal.dot(direction);
  KESSLER_VERIFY(std::abs(along) > 1e-12, "the shot line is parallel to the plate");
  return x0 + direction * ((offset - normal.dot(x0)) / along);
}

void checkGeometry(const ParticleState& model, const ImpactGeometry& geometry) {
  const auto bodies = static_cast<int>(model.bodies.size());
  if (!(geometry.shot_direction.norm() > 0.0)) throw InputError("analysis: the shot direction is zero");
  for (const int b : geometry.projectile_bodies)
    if (b < 0 || b >= bodies) throw InputError(fmt::format("analysis: projectile body {} does not exist", b));
  const Vec3 e = geometry.shot_direction.normalized();
  for (std::size_t i = 0; i < geometry.plates.size(); ++i) {
    const PlateSpec& plate = geometry.plates[i];
    if (plate.body < 0 || plate.body >= bodies)
      throw InputError(fmt::format("analysis: plate {} refers to body {}, which does not exist", i, plate.body));
    if (!(plate.thickness > 0.0))
      throw InputError(
          fmt::format("analysis: plate '{}' has thickness {} m", model.bodies[plate.body].name, plate.thickness));
    if (std::abs(plate.normal.norm() - 1.0) > 1e-9 || !(plate.normal.dot(e) > 1e-6))
      throw InputError(fmt::format("analysis: the normal of plate '{}' must be a unit vector pointing along the shot",
                                   model.bodies[plate.body].name));
    for (std::size_t j = 0; j < i; ++j)
      if (geometry.plates[j].body == plate.body)
        throw InputError(fmt::format("analysis: body '{}' is listed as two plates", model.bodies[plate.body].name));
  }
  if (!geometry.plates.empty() &&
      (geometry.cloud_reference < 0 || geometry.cloud_reference >= static_cast<int>(geometry.plates.size())))
    throw InputError(fmt::format("analysis: cloud reference plate {} does not exist", geometry.cloud_reference));
  for (std::size_t i = 0; i < geometry.symmetry_axes.size(); ++i) {
    const int axis = geometry.symmetry_axes[i];
    if (axis < 0 || axis > 2) throw InputError(fmt::format("analysis: symmetry axis {} must be 0, 1 or 2", axis));
    for (std::size_t j = 0; j < i; ++j)
      if (geometry.symmetry_axes[j] == axis) throw InputError("analysis: a symmetry axis is listed twice");
  }
}

namespace {

// The mean initial spacing of a plate's points.
double meanSpacing(const ParticleState& model, const PlateSpec& plate) {
  double sum = 0.0;
  LocalIndex count = 0;
  forEachPointOf(model.points, plate.body, [&](LocalIndex p) {
    sum += model.points.spacing0[p];
    ++count;
  });
  KESSLER_VERIFY(count > 0, "plate '{}' has no points", model.bodies[plate.body].name);
  return sum / count;
}

}  // namespace

double holeCell(const ParticleState& model, const ImpactGeometry& geometry, int plate) {
  return geometry.cell_size > 0.0 ? geometry.cell_size : meanSpacing(model, geometry.plates[plate]);
}

HoleMeasurement measureHole(const ParticleState& model, const ImpactGeometry& geometry, int plate_index) {
  checkGeometry(model, geometry);
  const PlateSpec& plate = geometry.plates[plate_index];
  const Mirror mirror(geometry.symmetry_axes);
  const Vec3 e = geometry.shot_direction.normalized();
  const double mid = plate.rear_face - 0.5 * plate.thickness;
  const PlaneFrame frame = planeFrame(shotLineHit(geometry.impact_point, e, plate.normal, mid), plate.normal);
  const auto intact = [&](LocalIndex p) { return model.points.broken[p] == 0; };

  HoleMeasurement hole;
  hole.plate = plate_index;
  hole.body = plate.body;
  const OccupancyGrid grid(projectPlate(model, plate, frame, mirror, true, intact),
                           holeCell(model, geometry, plate_index), Vec2::Zero());
  hole.cell = grid.cell();
  // A stray point in the cell of the shot line must not hide the hole: look one cell around.
  const auto region = emptyRegionAt(grid, Vec2::Zero(), 1);
  if (!region) return hole;
  hole.found = true;
  hole.open = region->touches_border;
  hole.ellipse = fitEllipse(grid, *region);
  hole.centre = frame.lift(hole.ellipse.centre);
  hole.major_direction = hole.ellipse.major_direction[0] * frame.u + hole.ellipse.major_direction[1] * frame.w;

  std::vector<std::uint8_t> covered(static_cast<std::size_t>(grid.nx()) * grid.ny(), 0);
  for (const Vec2& q : projectPlate(model, plate, frame, mirror, false, intact)) {
    const int k = grid.cellOf(q);
    if (k >= 0) covered[k] = 1;
  }
  long clear = 0;
  for (const int k : region->cells) clear += covered[k] == 0;
  hole.through_area = hole.ellipse.area * static_cast<double>(clear) / static_cast<double>(region->cells.size());
  return hole;
}

RearWallDamage measureRearWall(const ParticleState& model, const FragmentSet& fragments,
                               const ImpactGeometry& geometry) {
  checkGeometry(model, geometry);
  KESSLER_VERIFY(!geometry.plates.empty(), "rear-wall damage needs at least one plate");
  KESSLER_VERIFY(fragments.label.size() == static_cast<std::size_t>(model.points.size()),
                 "rear-wall damage: fragments of another model ({} labels for {} points)", fragments.label.size(),
                 model.points.size());
  const auto wall_index = static_cast<int>(geometry.plates.size()) - 1;
  const PlateSpec& plate = geometry.plates.back();
  const Mirror mirror(geometry.symmetry_axes);
  RearWallDamage damage;
  damage.plate = wall_index;
  damage.body = plate.body;
  damage.spacings_through = plate.thickness / meanSpacing(model, plate);

  for (LocalIndex p = 0; p < model.points.owned; ++p)
    if (model.points.debris(p) && model.points.lastStruck(p) == plate.body)
      damage.debris_struck += model.points.mass[p] * mirror.images();
  forEachPointOf(model.points, plate.body, [&](LocalIndex p) {
    if (model.points.broken[p] && plate.normal.dot(model.points.x[p]) > plate.rear_face)
      damage.eroded_mass_behind += model.points.mass[p] * mirror.images();
  });

  // Fragments are sorted by mass: the first of this body is the wall itself.
  LocalIndex wall = -1;
  for (std::size_t f = 0; f < fragments.fragments.size(); ++f) {
    const Fragment& fragment = fragments.fragments[f];
    if (fragment.body != plate.body) continue;
    if (wall < 0) {
      wall = static_cast<LocalIndex>(f);
    } else if (plate.normal.dot(fragment.centre) > plate.rear_face) {
      damage.spall_fragments += fragment.copies;
      damage.spall_mass += fragment.mass * fragment.copies;
    }
  }
  if (wall < 0) {
    // Nothing of the wall holds together: it is gone, which is a perforation.
    damage.perforations = 1;
    damage.classification = "perforation";
    return damage;
  }

  const Vec3 e = geometry.shot_direction.normalized();
  const PlaneFrame frame =
      planeFrame(shotLineHit(geometry.impact_point, e, plate.normal, plate.rear_face), plate.normal);
  const auto attached = [&](LocalIndex p) { return fragments.label[p] == wall; };
  const OccupancyGrid grid(projectPlate(model, plate, frame, mirror, false, attached),
                           holeCell(model, geometry, wall_index), Vec2::Zero());
  // Fewer than 4 cells (2h x 2h) is below the resolution of the projected point cloud.
  constexpr std::size_t min_cells = 4;
  for (const EmptyRegion& region : emptyRegions(grid)) {
    if (region.touches_border || region.cells.size() < min_cells) continue;
    ++damage.perforations;
    damage.perforation_diameters.push_back(fitEllipse(grid, region).equivalent_diameter);
  }
  std::sort(damage.perforation_diameters.begin(), damage.perforation_diameters.end(), std::greater<>());

  // Bulge: the attached material's furthest reach behind the original rear face (its points start
  // a fraction of a spacing inside the face).
  forEachPointOf(model.points, plate.body, [&](LocalIndex p) {
    if (attached(p)) damage.bulge = std::max(damage.bulge, plate.normal.dot(model.points.x[p]) - plate.rear_face);
  });
  // Incipient spall: failed wall points (still in the wall) nearer the rear than the front of the
  // attached wall in their column (one raster cell), so that a crater in the front face of a bulged
  // wall does not count.
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<double> front(static_cast<std::size_t>(grid.nx()) * grid.ny(), infinity), rear(front.size(), -infinity);
  forEachPointOf(model.points, plate.body, [&](LocalIndex p) {
    if (!attached(p)) return;
    const int k = grid.cellOf(frame.project(model.points.x[p]));
    if (k < 0) return;
    const double s = plate.normal.dot(model.points.x[p]);
    front[k] = std::min(front[k], s);
    rear[k] = std::max(rear[k], s);
  });
  forEachPointOf(model.points, plate.body, [&](LocalIndex p) {
    if (!model.points.failed(p)) return;
    const int k = grid.cellOf(frame.project(model.points.x[p]));
    if (k < 0 || !(rear[k] > front[k])) return;
    if (plate.normal.dot(model.points.x[p]) > 0.5 * (front[k] + rear[k]))
      damage.incipient_mass += model.points.mass[p] * mirror.images();
  });

  if (damage.perforations > 0)
    damage.classification = "perforation";
  else if (damage.spall_fragments > 0)
    damage.classification = "detached_spall";
  else if (damage.incipient_mass > 0.0)
    damage.classification = "incipient_spall";
  else if (damage.bulge > grid.cell())
    damage.classification = "bulge";
  return damage;
}

}  // namespace kessler::analysis
