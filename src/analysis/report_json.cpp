// The "analysis" object of summary.json. Keys carry their SI unit (_m, _kg, _m_per_s, _deg);
// docs/analysis.md lists them, and tools/plots/fragments.py reads "breakup_model".
#include "analysis/report.hpp"

#include <array>
#include <numbers>

namespace kessler::analysis {
namespace {

using nlohmann::json;

constexpr double deg = 180.0 / std::numbers::pi;

json vec(const Vec3& x) {
  return json::array({x[0], x[1], x[2]});
}

json fragmentsJson(const Report& r) {
  const FragmentSet& set = r.fragments;
  json out = {{"count", set.count()},
              {"distinct", set.fragments.size()},
              {"link_stretch", set.link_stretch},
              {"links", set.links},
              {"broken_links", set.broken_links},
              {"reference_link_lengths", set.reference_lengths},
              {"csv", "fragments.csv"},
              {"cumulative_csv", "fragments_cumulative.csv"},
              {"points_csv", "fragment_points.csv"}};
  json eroded = json::object();
  json mass = json::object();
  for (std::size_t b = 0; b < r.body_names.size(); ++b) {
    eroded[r.body_names[b]] = set.eroded_mass[b];
    mass[r.body_names[b]] = set.body_mass[b];
  }
  out["eroded_mass_kg"] = eroded;
  out["body_mass_kg"] = mass;
  json largest = json::array();
  for (std::size_t f = 0; f < set.fragments.size() && f < 10; ++f) {
    const Fragment& x = set.fragments[f];
    largest.push_back({{"body", r.body_names[x.body]},
                       {"material", r.material_names[x.material]},
                       {"mass_kg", x.mass},
                       {"lc_m", x.lc},
                       {"speed_m_per_s", x.speed},
                       {"points", x.points},
                       {"copies", x.copies}});
  }
  out["largest"] = largest;
  return out;
}

json breakupJson(const Report& r) {
  const BreakupEvent& e = *r.event;
  const BreakupPrediction& p = *r.breakup;
  json out = {{"projectile_mass_kg", e.projectile_mass},
              {"target_mass_kg", e.target_mass},
              {"impact_speed_m_per_s", e.impact_speed},
              {"specific_energy_J_per_g", p.specific_energy},
              {"catastrophic", p.catastrophic},
              {"reference_mass_kg", p.reference_mass},
              {"coefficient", breakup_coefficient},
              {"mass_exponent", breakup_mass_exponent},
              {"length_exponent", breakup_length_exponent}};
  // Simulated and predicted N(>=Lc) side by side at a few sizes.
  const auto cumulative = cumulativeDistribution(r.fragments);
  json table = json::array();
  for (const double lc : std::array{0.5e-3, 1e-3, 2e-3, 5e-3, 10e-3, 20e-3}) {
    long simulated = 0;
    for (const CumulativeCount& c : cumulative)
      if (c.lc >= lc) simulated = c.count;
    table.push_back({{"lc_m", lc}, {"simulated", simulated}, {"predicted", p.count(lc)}});
  }
  out["comparison"] = table;
  return out;
}

json holeJson(const Report& r, const HoleMeasurement& h) {
  return {{"plate", h.plate},
          {"body", r.body_names[h.body]},
          {"found", h.found},
          {"open", h.open},
          {"diameter_m", h.ellipse.equivalent_diameter},
          {"major_axis_m", h.ellipse.major},
          {"minor_axis_m", h.ellipse.minor},
          {"area_m2", h.ellipse.area},
          {"through_area_m2", h.through_area},
          {"centre_m", vec(h.centre)},
          {"major_direction", vec(h.major_direction)},
          {"cell_m", h.cell}};
}

json cloudJson(const CloudMeasurement& c) {
  return {{"body", c.name},
          {"mass_kg", c.mass},
          {"points", c.points},
          {"leading_edge_m", c.leading_edge},
          {"max_radius_m", c.max_radius},
          {"length_m", c.length},
          {"width_m", c.width},
          {"length_to_width", c.length_to_width},
          {"bulk_leading_edge_m", c.bulk_leading_edge},
          {"bulk_radius_m", c.bulk_radius},
          {"bulk_length_to_width", c.bulk_length_to_width},
          {"mean_axial_speed_m_per_s", c.mean_axial_speed},
          {"bulk_axial_speed_m_per_s", c.bulk_axial_speed},
          {"bulk_radial_speed_m_per_s", c.bulk_radial_speed},
          {"front_centre_m", vec(c.front_centre)},
          {"front_deflection_deg", c.front_deflection * deg},
          {"front_normal_angle_deg", c.front_normal_angle * deg}};
}

json shieldJson(const ShieldComparison& s) {
  return {{"model", s.model},
          {"projectile_diameter_m", s.projectile.diameter},
          {"projectile_density_kg_per_m3", s.projectile.density},
          {"impact_speed_m_per_s", s.projectile.speed},
          {"obliquity_deg", s.projectile.obliquity * deg},
          {"spacing_m", s.spacing},
          {"wall_yield_stress_Pa", s.wall.yield_stress},
          {"wall_brinell_hardness", s.wall.brinell_hardness},
          {"wall_sound_speed_m_per_s", s.wall.sound_speed},
          {"critical_diameter_m", s.critical_diameter},
          {"penetration_depth_m", s.penetration_depth},
          {"regime", s.regime},
          {"predicts_perforation", s.predicts_perforation},
          {"simulated", s.simulated},
          {"caveat", s.caveat}};
}

}  // namespace

nlohmann::json toJson(const Report& r) {
  json out = json::object();
  out["debris"] = r.debris;
  out["fragments"] = fragmentsJson(r);
  if (r.breakup) out["breakup_model"] = breakupJson(r);
  json holes = json::array();
  for (const HoleMeasurement& h : r.holes) holes.push_back(holeJson(r, h));
  out["holes"] = holes;
  json clouds = json::array();
  for (const CloudMeasurement& c : r.clouds) clouds.push_back(cloudJson(c));
  out["debris_clouds"] = clouds;
  out["ejecta"] = {{"mass_kg", r.ejecta.mass},
                   {"points", r.ejecta.points},
                   {"height_m", r.ejecta.height},
                   {"inner_angle_deg", r.ejecta.inner_angle * deg},
                   {"outer_angle_deg", r.ejecta.outer_angle * deg},
                   {"axis_tilt_deg", r.ejecta.axis_tilt * deg}};
  if (r.rear_wall) {
    const RearWallDamage& w = *r.rear_wall;
    out["rear_wall"] = {{"body", r.body_names[w.body]},
                        {"perforations", w.perforations},
                        {"perforation_diameters_m", w.perforation_diameters},
                        {"spall_fragments", w.spall_fragments},
                        {"spall_mass_kg", w.spall_mass},
                        {"eroded_mass_behind_kg", w.eroded_mass_behind},
                        {"debris_struck_kg", w.debris_struck},
                        {"bulge_m", w.bulge},
                        {"incipient_spall_mass_kg", w.incipient_mass},
                        {"spacings_through_thickness", w.spacings_through},
                        {"classification", w.classification},
                        {"failed", w.failed()}};
  }
  if (r.shield) out["ballistic_limit"] = shieldJson(*r.shield);
  return out;
}

}  // namespace kessler::analysis
