#pragma once
// Minimal levelled logging to stderr/stdout. Quiet mode suppresses info messages.
#include <fmt/format.h>

#include <string_view>

namespace kessler::log {

enum class Level { quiet, info, debug };

void setLevel(Level level);
Level level();

void write(Level at, std::string_view message);

template <typename... Args>
void info(fmt::format_string<Args...> f, Args&&... args) {
  if (level() >= Level::info) write(Level::info, fmt::format(f, std::forward<Args>(args)...));
}

template <typename... Args>
void debug(fmt::format_string<Args...> f, Args&&... args) {
  if (level() >= Level::debug) write(Level::debug, fmt::format(f, std::forward<Args>(args)...));
}

}  // namespace kessler::log
