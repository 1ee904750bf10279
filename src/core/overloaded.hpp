#pragma once

namespace kessler {

// The usual visitor of lambdas for std::visit: Overloaded{[](const A&) {...}, [](const B&) {...}}.
template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
// Needed by clang before 17 (no aggregate deduction), which builds the fuzz targets.
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

}  // namespace kessler
