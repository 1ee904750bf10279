#pragma once
// Equations of state: pressure and sound speed from density and specific internal energy.
// Each model is a small value type with `evaluate(rho, e)`; a material holds an `Eos` variant
// and visits it once per range of points, never per point (CONTRIBUTING.md, "Physics code").
#include "material/eos/ideal_gas.hpp"
#include "material/eos/mie_gruneisen.hpp"
#include "material/eos/polynomial.hpp"
#include "material/eos/tabular.hpp"
#include "material/eos/tillotson.hpp"

#include <variant>

namespace kessler::eos {

// New models go last: the deck reader and the resolved-deck writer map model names to these
// indices (io/material_keys.hpp: eos_models).
using Eos = std::variant<MieGruneisen, Polynomial, Tillotson, Tabular, IdealGas>;

inline double referenceDensity(const Eos& eos) {
  return std::visit([](const auto& model) { return model.referenceDensity(); }, eos);
}

// Name of the model, as written in decks ("mie-gruneisen", "polynomial", "tillotson", "tabular",
// "ideal-gas").
const char* modelName(const Eos& eos);

}  // namespace kessler::eos
