#pragma once
// Quantities with units, as written in decks: "10 mm", "6.18 km/s", "20 us", "2.7 g/cm^3".
// A unit expression is a product/quotient of SI-prefixed symbols with integer powers, e.g.
// "kg/m^3", "J/(kg*K)", "m s^-1". The result is the value in SI units and its dimension.
#include <array>
#include <string>
#include <string_view>

namespace kessler::units {

// Exponents of length, mass, time and temperature.
struct Dimension {
  std::array<int, 4> exponent{0, 0, 0, 0};
  bool operator==(const Dimension&) const = default;
};

inline constexpr Dimension dimensionless{{0, 0, 0, 0}};
inline constexpr Dimension length{{1, 0, 0, 0}};
inline constexpr Dimension mass{{0, 1, 0, 0}};
inline constexpr Dimension time{{0, 0, 1, 0}};
inline constexpr Dimension temperature{{0, 0, 0, 1}};
inline constexpr Dimension velocity{{1, 0, -1, 0}};
inline constexpr Dimension acceleration{{1, 0, -2, 0}};
inline constexpr Dimension density{{-3, 1, 0, 0}};
inline constexpr Dimension pressure{{-1, 1, -2, 0}};
inline constexpr Dimension energy{{2, 1, -2, 0}};
inline constexpr Dimension specific_energy{{2, 0, -2, 0}};
inline constexpr Dimension specific_heat{{2, 0, -2, -1}};
inline constexpr Dimension energy_per_area{{0, 1, -2, 0}};
inline constexpr Dimension rate{{0, 0, -1, 0}};

// A human-readable SI form of a dimension, e.g. "m/s" or "kg/m^3".
std::string describe(Dimension d);

struct Quantity {
  double value = 0.0;  // in SI units
  Dimension dimension;
};

// Parses "<number> [unit]". A bare number is dimensionless. Throws kessler::InputError with
// a message saying what is wrong (no file/line: the caller adds where).
Quantity parse(std::string_view text);

// Parses a unit expression alone ("km/s"), returning the SI factor and dimension.
Quantity parseUnit(std::string_view unit);

// Parses text and converts to SI, checking the dimension. A bare number is accepted for any
// dimension and taken to be in SI units.
double toSI(std::string_view text, Dimension expected);

}  // namespace kessler::units
