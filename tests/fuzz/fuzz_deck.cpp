// libFuzzer target: the deck parser (io::parseDeckString) on arbitrary bytes. The deck is named
// as if it lay in tests/data/decks, so that seeds which name a SESAME table there load it.
#include "fuzz/fuzz_input.hpp"
#include "io/deck.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string name = KESSLER_FUZZ_DECK_NAME;
  try {
    kessler::io::parseDeckString(std::string(reinterpret_cast<const char*>(data), size), name);
    kessler::fuzz::accepted(name);
  } catch (const kessler::InputError& e) {
    kessler::fuzz::checkMessage(e, name);
  }
  return 0;
}
