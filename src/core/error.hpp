#pragma once
// Errors: every failure Kessler reports is a kessler::Error carrying a one-line message that
// says where and why. KESSLER_VERIFY is always on; KESSLER_ASSERT only in debug builds.
#include <fmt/format.h>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace kessler {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

// An error in user input (deck, mesh file, table): the message names file, line and key.
class InputError : public Error {
 public:
  using Error::Error;
};

// A numerical failure during a run (NaN, inverted volume, LME outside the hull, ...).
class NumericalError : public Error {
 public:
  using Error::Error;
};

// A numerical failure at one material point, raised where only its local index is known (a
// material law); the solver adds the point's identity and place.
class PointError : public NumericalError {
 public:
  PointError(std::int64_t point, const std::string& what) : NumericalError(what), point_(point) {}
  std::int64_t point() const { return point_; }

 private:
  std::int64_t point_;
};

[[noreturn]] void failVerify(const char* condition, const char* file, int line, const std::string& message);

}  // namespace kessler

#define KESSLER_VERIFY(cond, ...)                                                             \
  do {                                                                                         \
    if (!(cond)) [[unlikely]]                                                                  \
      ::kessler::failVerify(#cond, __FILE__, __LINE__, ::fmt::format(__VA_ARGS__));           \
  } while (false)

#ifdef NDEBUG
#define KESSLER_ASSERT(cond, ...) \
  do {                            \
  } while (false)
#else
#define KESSLER_ASSERT(cond, ...) KESSLER_VERIFY(cond, __VA_ARGS__)
#endif
