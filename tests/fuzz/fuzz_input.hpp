#pragma once
// What every fuzz target checks besides "no crash, no hang, no sanitizer report": bad input must
// be refused with a kessler::InputError whose message is one line starting with where the problem
// is ("<name>:<line>..."). Anything else (another exception type, a multi-line or unlocated message)
// aborts, which libFuzzer reports as a finding.
#include "core/error.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace kessler::fuzz {

// Set by the replay driver: every input must be refused (the malformed corpus).
inline bool& expectError() {
  static bool expect = false;
  return expect;
}

inline void checkMessage(const InputError& e, const std::string& name) {
  const std::string message = e.what();
  const bool located = message.rfind(name + ":", 0) == 0;
  // One printable line: no newline, and no other control character a binary input could smuggle in.
  const bool printable = std::none_of(message.begin(), message.end(),
                                      [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
  if (located && printable) {
    if (expectError()) std::printf("  refused: %s\n", message.c_str());
    return;
  }
  std::fprintf(stderr, "bad error message (not one printable line starting with '%s:'):\n%s\n", name.c_str(),
               message.c_str());
  std::abort();
}

inline void accepted(const std::string& name) {
  if (!expectError()) return;
  std::fprintf(stderr, "%s: accepted, but it is in the malformed corpus\n", name.c_str());
  std::abort();
}

}  // namespace kessler::fuzz
