// Checks of the parameter groups of an impact material (each names the bad key and value).
#include "core/error.hpp"
#include "material/impact_material.hpp"

namespace kessler {

void ThermalParameters::check() const {
  if (!(specific_heat > 0.0))
    throw InputError(fmt::format("thermal.specific_heat must be positive (got {})", specific_heat));
  if (!(taylor_quinney >= 0.0 && taylor_quinney <= 1.0))
    throw InputError(fmt::format("thermal.taylor_quinney must lie in [0, 1] (got {})", taylor_quinney));
  if (!(room_temperature > 0.0))
    throw InputError(fmt::format("thermal.room_temperature must be positive (got {})", room_temperature));
}

void ViscosityParameters::check() const {
  if (!(linear >= 0.0)) throw InputError(fmt::format("viscosity.linear must not be negative (got {})", linear));
  if (!(quadratic >= 0.0))
    throw InputError(fmt::format("viscosity.quadratic must not be negative (got {})", quadratic));
}

}  // namespace kessler
