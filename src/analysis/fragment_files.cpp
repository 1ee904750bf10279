// fragments.csv, fragments_cumulative.csv and fragment_points.csv. The analysis layer sits below
// io/, so it writes its text files itself: to a temporary name, then renamed over the target, so
// a reader never sees half a file.
#include "analysis/report.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

#include <fstream>
#include <system_error>

namespace kessler::analysis {
namespace {

void writeAtomically(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path temporary = file.string() + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw Error(fmt::format("cannot write '{}'", temporary.string()));
    out << text;
    out.close();
    if (!out) throw Error(fmt::format("writing '{}' failed", temporary.string()));
  }
  std::error_code error;
  std::filesystem::rename(temporary, file, error);
  if (error) throw Error(fmt::format("cannot replace '{}': {}", file.string(), error.message()));
}

std::string fragmentsCsv(const Report& r) {
  std::string text =
      "rank,body,material,points,copies,mass_kg,lc_m,extent1_m,extent2_m,extent3_m,area_m2,area_to_mass_m2_per_kg,"
      "x_m,y_m,z_m,vx_m_per_s,vy_m_per_s,vz_m_per_s,speed_m_per_s\n";
  const auto& fragments = r.fragments.fragments;
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    const Fragment& f = fragments[i];
    text += fmt::format(
        "{},{},{},{},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},"
        "{:.9g},{:.9g},{:.9g}\n",
        i + 1, r.body_names[f.body], r.material_names[f.material], f.points, f.copies, f.mass, f.lc, f.extents[0],
        f.extents[1], f.extents[2], f.area, f.area / f.mass, f.centre[0], f.centre[1], f.centre[2], f.velocity[0],
        f.velocity[1], f.velocity[2], f.speed);
  }
  return text;
}

std::string cumulativeCsv(const Report& r) {
  std::string text = "lc_m,count_ge_lc,nasa_count_ge_lc\n";
  for (const CumulativeCount& c : cumulativeDistribution(r.fragments)) {
    const std::string nasa = r.breakup && c.lc > 0.0 ? fmt::format("{:.6g}", r.breakup->count(c.lc)) : "";
    text += fmt::format("{:.9g},{},{}\n", c.lc, c.count, nasa);
  }
  return text;
}

// Which fragment each point ends in (its rank in fragments.csv; 0: broken, a free particle or
// eroded debris), by point id: with the outputs' ids and first positions it maps every fragment
// back to the material it came from (tools/plots/back_projection.py).
std::string pointsCsv(const Report& r) {
  const FragmentSet& f = r.fragments;
  std::string text = "id,fragment\n";
  text.reserve(text.size() + 16 * f.label.size());
  for (std::size_t p = 0; p < f.label.size(); ++p) text += fmt::format("{},{}\n", f.point_id[p], f.label[p] + 1);
  return text;
}

}  // namespace

void writeFragmentFiles(const std::filesystem::path& dir, const Report& report) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw Error(fmt::format("cannot create the folder '{}': {}", dir.string(), error.message()));
  writeAtomically(dir / "fragments.csv", fragmentsCsv(report));
  writeAtomically(dir / "fragments_cumulative.csv", cumulativeCsv(report));
  writeAtomically(dir / "fragment_points.csv", pointsCsv(report));
}

}  // namespace kessler::analysis
