#include "core/error.hpp"

namespace kessler {

void failVerify(const char* condition, const char* file, int line, const std::string& message) {
  throw Error(fmt::format("{} (check '{}' failed at {}:{})", message, condition, file, line));
}

}  // namespace kessler
