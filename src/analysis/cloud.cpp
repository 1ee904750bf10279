// Debris cloud behind the target and back-splash (ejecta) in front of it (measurements.hpp).
// These run once per run over the points, serially, so the sums are deterministic.
#include "analysis/measurements.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace kessler::analysis {
namespace {

double angleBetween(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// The points (all mirror images) of `bodies` behind the reference plate's original rear face.
struct CloudSample {
  Vec3 x, v;
  double mass;
  bool simulated;  // image 0: counts as a simulated point
};

std::vector<CloudSample> cloudSamples(const ParticleState& model, const std::vector<int>& bodies, const PlateSpec& ref,
                                      const Mirror& mirror) {
  std::vector<CloudSample> samples;
  for (const int b : bodies) {
    forEachPointOf(model.points, b, [&](LocalIndex p) {
      for (int mask = 0; mask < mirror.images(); ++mask) {
        const Vec3 x = mirror.image(model.points.x[p], mask);
        if (ref.normal.dot(x) > ref.rear_face)
          samples.push_back({x, mirror.image(model.points.v[p], mask), model.points.mass[p], mask == 0});
      }
    });
  }
  return samples;
}

// The mass-weighted q-quantile of values (sorted with their weights).
double weightedQuantile(std::vector<std::pair<double, double>>& values, double q) {
  std::sort(values.begin(), values.end());
  double total = 0.0;
  for (const auto& v : values) total += v.second;
  double cumulative = 0.0;
  for (const auto& [value, weight] : values) {
    cumulative += weight;
    if (cumulative >= q * total) return value;
  }
  return values.back().first;
}

CloudMeasurement measureCloud(const std::vector<CloudSample>& samples, const Vec3& origin, const Vec3& e,
                              const Vec3& normal) {
  CloudMeasurement cloud;
  if (samples.empty()) return cloud;
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  std::vector<std::pair<double, double>> axial_mass, radial_mass, axial_speed, radial_speed;
  double axial_momentum = 0.0;
  for (const CloudSample& s : samples) {
    const Vec3 d = s.x - origin;
    const double axial = e.dot(d);
    const Vec3 off_axis = d - axial * e;
    const double radial = off_axis.norm();
    axial_momentum += s.mass * e.dot(s.v);
    axial_speed.emplace_back(e.dot(s.v), s.mass);
    radial_speed.emplace_back(radial > 0.0 ? off_axis.dot(s.v) / radial : 0.0, s.mass);
    cloud.mass += s.mass;
    cloud.points += s.simulated;
    lo = std::min(lo, axial);
    hi = std::max(hi, axial);
    cloud.max_radius = std::max(cloud.max_radius, radial);
    axial_mass.emplace_back(axial, s.mass);
    radial_mass.emplace_back(radial, s.mass);
  }
  cloud.leading_edge = hi;
  cloud.length = hi - lo;
  cloud.width = 2.0 * cloud.max_radius;
  cloud.length_to_width = cloud.width > 0.0 ? cloud.length / cloud.width : 0.0;
  cloud.bulk_leading_edge = weightedQuantile(axial_mass, 0.95);
  cloud.bulk_radius = weightedQuantile(radial_mass, 0.95);
  const double bulk_length = cloud.bulk_leading_edge - weightedQuantile(axial_mass, 0.05);
  cloud.bulk_length_to_width = cloud.bulk_radius > 0.0 ? bulk_length / (2.0 * cloud.bulk_radius) : 0.0;
  cloud.mean_axial_speed = axial_momentum / cloud.mass;
  cloud.bulk_axial_speed = weightedQuantile(axial_speed, 0.95);
  cloud.bulk_radial_speed = weightedQuantile(radial_speed, 0.95);
  // The front: the leading tenth of the cloud's length, whose mass centre gives the direction
  // the cloud travels (Piekutowski's "leading edge" of the debris cloud).
  const double front_start = hi - 0.1 * cloud.length;
  Vec3 moment = Vec3::Zero();
  double front_mass = 0.0;
  for (const CloudSample& s : samples) {
    if (e.dot(s.x - origin) < front_start) continue;
    moment += s.mass * s.x;
    front_mass += s.mass;
  }
  cloud.front_centre = moment / front_mass;
  const Vec3 front = cloud.front_centre - origin;
  if (front.norm() > 0.0) {
    cloud.front_deflection = angleBetween(front, e);
    cloud.front_normal_angle = angleBetween(front, normal);
  }
  return cloud;
}

}  // namespace

std::vector<CloudMeasurement> measureClouds(const ParticleState& model, const ImpactGeometry& geometry) {
  checkGeometry(model, geometry);
  std::vector<CloudMeasurement> clouds;
  if (geometry.plates.empty()) return clouds;
  const PlateSpec& ref = geometry.plates[geometry.cloud_reference];
  const Vec3 e = geometry.shot_direction.normalized();
  const Vec3 origin = shotLineHit(geometry.impact_point, e, ref.normal, ref.rear_face);
  const Mirror mirror(geometry.symmetry_axes);

  std::vector<int> bodies = geometry.projectile_bodies;
  if (std::find(bodies.begin(), bodies.end(), ref.body) == bodies.end()) bodies.push_back(ref.body);
  for (const int b : bodies) {
    CloudMeasurement cloud = measureCloud(cloudSamples(model, {b}, ref, mirror), origin, e, ref.normal);
    cloud.name = model.bodies[b].name;
    cloud.body = b;
    clouds.push_back(std::move(cloud));
  }
  CloudMeasurement all = measureCloud(cloudSamples(model, bodies, ref, mirror), origin, e, ref.normal);
  all.name = "all";
  clouds.push_back(std::move(all));
  return clouds;
}

EjectaMeasurement measureEjecta(const ParticleState& model, const ImpactGeometry& geometry) {
  checkGeometry(model, geometry);
  EjectaMeasurement ejecta;
  if (geometry.plates.empty()) return ejecta;
  const PlateSpec& first = geometry.plates.front();
  const Vec3 e = geometry.shot_direction.normalized();
  const Vec3 up = -first.normal;  // the front face's outward normal, towards the gun
  const Vec3 origin = shotLineHit(geometry.impact_point, e, first.normal, first.frontFace());
  const Mirror mirror(geometry.symmetry_axes);

  // Back-splash: material in front of the original front face that moves up-range; the tail of
  // a projectile still on its way in moves down-range and is not ejecta.
  std::vector<std::pair<double, double>> angles;
  Vec3 direction_sum = Vec3::Zero();
  for (LocalIndex p = 0; p < model.points.size(); ++p) {
    for (int mask = 0; mask < mirror.images(); ++mask) {
      const Vec3 x = mirror.image(model.points.x[p], mask);
      const double height = first.frontFace() - first.normal.dot(x);
      if (height <= 0.0 || model.points.v[p].dot(mirror.image(e, mask)) >= 0.0) continue;
      const double m = model.points.mass[p];
      ejecta.mass += m;
      ejecta.points += mask == 0;
      ejecta.height = std::max(ejecta.height, height);
      const Vec3 d = x - origin;
      angles.emplace_back(angleBetween(d, up), m);
      direction_sum += m * d.normalized();
    }
  }
  if (angles.empty()) return ejecta;
  ejecta.inner_angle = weightedQuantile(angles, 0.05);
  ejecta.outer_angle = weightedQuantile(angles, 0.95);
  ejecta.axis_tilt = angleBetween(direction_sum, up);
  return ejecta;
}

}  // namespace kessler::analysis
