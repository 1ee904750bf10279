#include "material/eos/eos.hpp"

#include <type_traits>

namespace kessler::eos {

const char* modelName(const Eos& eos) {
  return std::visit(
      [](const auto& model) -> const char* {
        using Model = std::decay_t<decltype(model)>;
        if constexpr (std::is_same_v<Model, MieGruneisen>) {
          return "mie-gruneisen";
        } else if constexpr (std::is_same_v<Model, Polynomial>) {
          return "polynomial";
        } else if constexpr (std::is_same_v<Model, Tillotson>) {
          return "tillotson";
        } else if constexpr (std::is_same_v<Model, Tabular>) {
          return "tabular";
        } else {
          static_assert(std::is_same_v<Model, IdealGas>, "a model of the Eos variant has no name");
          return "ideal-gas";
        }
      },
      eos);
}

}  // namespace kessler::eos
