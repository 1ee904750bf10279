// The end-of-run printout: the measurements in the units people quote them in.
#include "analysis/report.hpp"

#include <fmt/format.h>

#include <numbers>
#include <string>
#include <vector>

namespace kessler::analysis {
namespace {

constexpr double mm = 1e3;
constexpr double deg = 180.0 / std::numbers::pi;

void line(std::string& out, const std::string& text) {
  out += text;
  out += '\n';
}

void printHole(std::string& out, const Report& r, const HoleMeasurement& h) {
  const std::string& name = r.body_names[h.body];
  if (!h.found) {
    line(out, fmt::format("  hole in {:<12} none (intact material at the shot line)", name));
    return;
  }
  line(out, fmt::format("  hole in {:<12} diameter {:.2f} mm (axes {:.2f} x {:.2f} mm), clear {:.0f}%{}", name,
                        h.ellipse.equivalent_diameter * mm, h.ellipse.major * mm, h.ellipse.minor * mm,
                        h.ellipse.area > 0.0 ? 100.0 * h.through_area / h.ellipse.area : 0.0,
                        h.open ? ", open to the plate edge" : ""));
}

}  // namespace

std::string formatReport(const Report& r) {
  std::string out;
  line(out, "Impact analysis");
  if (!r.debris)
    line(out,
         "  no debris            every body is still one piece and nothing failed: no hole, cloud or "
         "ballistic-limit verdict");
  for (const HoleMeasurement& h : r.holes) printHole(out, r, h);
  for (const CloudMeasurement& c : r.clouds) {
    if (c.points == 0) continue;
    line(out, fmt::format("  cloud {:<14} leading edge {:.1f} mm, radius {:.1f} mm, L/W {:.2f}, front {:.1f} deg "
                          "from the shot line, {:.3f} g",
                          c.name, c.leading_edge * mm, c.max_radius * mm, c.length_to_width, c.front_deflection * deg,
                          c.mass * 1e3));
    line(out, fmt::format("  {:<20} 95% of its mass: leading edge {:.1f} mm, radius {:.1f} mm, L/W {:.2f}", "",
                          c.bulk_leading_edge * mm, c.bulk_radius * mm, c.bulk_length_to_width));
    const double v = r.geometry.impact_speed;
    line(out, fmt::format("  {:<20} speeds: mean axial {:.2f} km/s, bulk front {:.2f} km/s, bulk radial {:.2f} km/s{}",
                          "", c.mean_axial_speed * 1e-3, c.bulk_axial_speed * 1e-3, c.bulk_radial_speed * 1e-3,
                          v > 0.0 ? fmt::format(" ({:.2f} / {:.2f} / {:.2f} of the impact speed)",
                                                c.mean_axial_speed / v, c.bulk_axial_speed / v, c.bulk_radial_speed / v)
                                  : std::string()));
  }
  if (r.ejecta.points > 0) {
    line(out, fmt::format("  back-splash          height {:.1f} mm, cone {:.0f}-{:.0f} deg from the normal, {:.3f} g",
                          r.ejecta.height * mm, r.ejecta.inner_angle * deg, r.ejecta.outer_angle * deg,
                          r.ejecta.mass * 1e3));
  }
  if (r.rear_wall) {
    const RearWallDamage& w = *r.rear_wall;
    line(out,
         fmt::format("  rear wall {:<10} {} ({}): {} perforation(s), {} detached spall fragment(s) ({:.3f} g), "
                     "{:.3f} g failed inside, bulge {:.2f} mm; struck by {:.3f} g of debris; {:.1f} point spacings "
                     "through its thickness",
                     r.body_names[w.body], w.classification, w.failed() ? "failed" : "holds", w.perforations,
                     w.spall_fragments, w.spall_mass * 1e3, w.incipient_mass * 1e3, w.bulge * 1e3,
                     w.debris_struck * 1e3, w.spacings_through));
  }
  if (r.shield) {
    const ShieldComparison& s = *r.shield;
    const bool whipple = s.model == "christiansen_whipple";
    line(out, fmt::format("  {}: critical diameter {:.2f} mm ({}) vs projectile {:.2f} mm -> {}; simulated: {}",
                          whipple ? "Christiansen BLE" : "Cour-Palais single wall", s.critical_diameter * mm, s.regime,
                          s.projectile.diameter * mm, s.predicts_perforation ? "perforation" : "no perforation",
                          s.simulated));
    if (!s.caveat.empty()) line(out, fmt::format("  {:<20} caveat: {}", "", s.caveat));
  }
  const FragmentSet& f = r.fragments;
  double eroded = 0.0;
  for (const double m : f.eroded_mass) eroded += m;
  line(out, fmt::format("  fragments            {} ({} distinct), sub-resolution debris {:.3f} g", f.count(),
                        f.fragments.size(), eroded * 1e3));
  if (r.body_names.size() > 1 && !f.fragments.empty()) {
    std::vector<long> per_body(r.body_names.size(), 0);
    for (const Fragment& fragment : f.fragments) per_body[static_cast<std::size_t>(fragment.body)] += fragment.copies;
    std::string counts;
    for (std::size_t b = 0; b < per_body.size(); ++b)
      counts += fmt::format("{}{} {}", b == 0 ? "" : ", ", r.body_names[b], per_body[b]);
    line(out, fmt::format("  fragments by body    {}", counts));
  }
  if (r.breakup) {
    line(out, fmt::format("  NASA breakup model   {} ({:.1f} J/g), M = {:.4g} kg: N(>1 mm) = {:.0f}, N(>5 mm) = {:.1f}",
                          r.breakup->catastrophic ? "catastrophic" : "non-catastrophic", r.breakup->specific_energy,
                          r.breakup->reference_mass, r.breakup->count(1e-3), r.breakup->count(5e-3)));
    // At the run's resolution: the smallest fragment's size, where the simulated count ends.
    double smallest = 0.0;
    for (const Fragment& fragment : f.fragments)
      if (fragment.lc > 0.0 && (smallest == 0.0 || fragment.lc < smallest)) smallest = fragment.lc;
    if (smallest > 0.0)
      line(out, fmt::format("  {:<20} N(>={:.2f} mm, the smallest fragment) = {:.0f}, simulated {}", "", smallest * mm,
                            r.breakup->count(smallest), f.count()));
  }
  return out;
}

}  // namespace kessler::analysis
