#include "core/log.hpp"

#include <atomic>
#include <cstdio>

namespace kessler::log {

namespace {
std::atomic<Level> current{Level::info};
}

void setLevel(Level l) { current = l; }
Level level() { return current; }

void write(Level at, std::string_view message) {
  std::FILE* out = at == Level::debug ? stderr : stdout;
  fmt::print(out, "{}\n", message);
  std::fflush(out);
}

}  // namespace kessler::log
