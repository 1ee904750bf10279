#pragma once
// Tabular equation of state from a SESAME-format ASCII file (LANL; Lyon & Johnson, LA-UR-92-3407,
// 1992; docs/eos.md): table 201 (Z, A, rho0, B0, T0) and table 301 (NR densities, NT temperatures,
// P(rho, T) in GPa and E(rho, T) in MJ/kg, density fastest; densities in g/cm^3). Kessler works in
// SI internally.
// p(rho, e) is found by inverting E(rho, T) for T along each density, then interpolating P.
#include "material/eos/state.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace kessler::eos {

struct SesameTable {
  int material_id = 0;
  double z = 0.0, a = 0.0;          // table 201 (mean atomic number and weight)
  double density = 0.0;             // rho0, kg/m^3 (SI)
  double bulk_modulus = 0.0;        // B0, Pa
  double temperature0 = 0.0;        // T0, K
  std::vector<double> rho;          // kg/m^3, increasing
  std::vector<double> temperature;  // K, increasing
  std::vector<double> pressure;     // Pa, [it * rho.size() + ir]
  std::vector<double> energy;       // J/kg, same layout
};

// Reads a SESAME ASCII file; throws kessler::InputError naming the file, line and what is
// wrong (not SESAME, truncated, missing table, non-monotonic grid, non-finite value, ...).
// `material_id` 0 takes the first material in the file.
SesameTable readSesame(const std::filesystem::path& file, int material_id = 0);

// Writes a table in the same format (five E15.8 numbers per line).
void writeSesame(const SesameTable& table, const std::filesystem::path& file);

struct TabularParameters {
  std::string file;  // path of the SESAME file
  int material_id = 0;
};

class Tabular {
 public:
  Tabular();  // an empty table, so configurations can be default-built; evaluate() throws
  explicit Tabular(const TabularParameters& p);  // reads the file
  explicit Tabular(std::shared_ptr<const SesameTable> table);
  // Throws kessler::NumericalError if (rho, e) lies outside the table.
  State evaluate(double rho, double e) const;
  double referenceDensity() const { return table_->density; }
  const SesameTable& table() const { return *table_; }
  // The file and material it was read from (empty for a table built in memory).
  const TabularParameters& parameters() const { return parameters_; }

 private:
  std::shared_ptr<const SesameTable> table_;  // shared: copies of a material share one table
  TabularParameters parameters_;
  double floor_modulus_ = 0.0;  // K0 of the c^2 floor: B0, or the largest |P| if B0 <= 0
};

}  // namespace kessler::eos
