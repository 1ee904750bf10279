#pragma once
// A method's own part of a checkpoint (Method::save, Method::load): named scalars and arrays,
// written and read back bit for bit. io/checkpoint.cpp implements both on the checkpoint's HDF5
// file; names are paths in it ("/nodes/x", "integrator_time" for a scalar on the root).
#include "core/types.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace kessler {

class StateWriter {
 public:
  virtual ~StateWriter() = default;
  virtual void group(const std::string& name) = 0;
  virtual void scalar(const std::string& name, double value) = 0;
  virtual void scalar(const std::string& name, std::int64_t value) = 0;
  virtual void array(const std::string& name, const std::vector<double>& values) = 0;
  virtual void array(const std::string& name, const std::vector<std::int32_t>& values) = 0;
  virtual void array(const std::string& name, const std::vector<std::int64_t>& values) = 0;
  virtual void array(const std::string& name, const std::vector<std::uint8_t>& values) = 0;
  virtual void array(const std::string& name, const std::vector<Vec3>& values) = 0;
  virtual void array(const std::string& name, const std::vector<Mat3>& values) = 0;
};

// Every read checks the stored type and shape; a mismatch, a missing name or fail() throws
// kessler::Error naming the file and what was wrong.
class StateReader {
 public:
  virtual ~StateReader() = default;
  virtual double doubleScalar(const std::string& name) const = 0;
  virtual std::int64_t intScalar(const std::string& name) const = 0;
  // Entries of the array `name` (its first dimension).
  virtual std::size_t length(const std::string& name) const = 0;
  // Whether the file holds the array `name` (one that an older writer did not write).
  virtual bool has(const std::string& name) const = 0;
  // Reads exactly `count` entries into `values`.
  virtual void array(const std::string& name, std::vector<double>& values, std::size_t count) const = 0;
  virtual void array(const std::string& name, std::vector<std::int32_t>& values, std::size_t count) const = 0;
  virtual void array(const std::string& name, std::vector<std::int64_t>& values, std::size_t count) const = 0;
  virtual void array(const std::string& name, std::vector<std::uint8_t>& values, std::size_t count) const = 0;
  virtual void array(const std::string& name, std::vector<Vec3>& values, std::size_t count) const = 0;
  virtual void array(const std::string& name, std::vector<Mat3>& values, std::size_t count) const = 0;
  // Refuses the file: "cannot use <what>".
  [[noreturn]] virtual void fail(const std::string& what) const = 0;
};

}  // namespace kessler
