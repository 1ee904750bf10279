// compare_runs DIR_A DIR_B [--min-eroded N]: exit 0 when two run folders hold bitwise the same
// results: the same field files, every dataset and attribute of each byte for byte, and the same
// history.csv, points.xdmf and nodes.xdmf. With --min-eroded, the last output of DIR_A must also
// have at least N eroded points (so that a restart test exercises failure and erosion).
#include "core/error.hpp"
#include "io/hdf5_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using kessler::io::Hdf5Reader;

namespace {

int problems = 0;

void problem(const std::string& what) {
  fmt::print(stderr, "DIFFERENT: {}\n", what);
  ++problems;
}

std::vector<std::string> fieldFiles(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir / "fields")) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return "<missing " + file.string() + ">";
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

void compareFields(const fs::path& a, const fs::path& b) {
  const Hdf5Reader ha(a), hb(b);
  if (ha.readDoubleAttribute("time") != hb.readDoubleAttribute("time")) problem(fmt::format("{}: time", a.string()));
  if (ha.readInt64Attribute("step") != hb.readInt64Attribute("step")) problem(fmt::format("{}: step", a.string()));
  const std::vector<std::string> sets = ha.datasets();
  if (sets != hb.datasets()) problem(fmt::format("{}: different datasets", a.string()));
  for (const std::string& name : sets) {
    if (!hb.has(name)) continue;
    if (ha.shape(name) != hb.shape(name) || ha.readBytes(name) != hb.readBytes(name))
      problem(fmt::format("{}:{}", a.filename().string(), name));
  }
}

long erodedIn(const fs::path& file) {
  const std::vector<std::uint8_t> eroded = Hdf5Reader(file).read<std::uint8_t>("/points/eroded");
  return std::count(eroded.begin(), eroded.end(), std::uint8_t{1});
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 && argc != 5) {
    fmt::print(stderr, "usage: compare_runs DIR_A DIR_B [--min-eroded N]\n");
    return 2;
  }
  const fs::path a = argv[1], b = argv[2];
  const long min_eroded = argc == 5 ? std::atol(argv[4]) : 0;
  try {
    const std::vector<std::string> files = fieldFiles(a);
    if (files != fieldFiles(b)) problem("the lists of field files");
    for (const std::string& name : files)
      if (fs::exists(b / "fields" / name)) compareFields(a / "fields" / name, b / "fields" / name);
    for (const char* name : {"history.csv", "points.xdmf", "nodes.xdmf"})
      if (text(a / name) != text(b / name)) problem(name);
    const long eroded = files.empty() ? 0 : erodedIn(a / "fields" / files.back());
    fmt::print("{} field files compared; {} eroded points at the end\n", files.size(), eroded);
    if (eroded < min_eroded) problem(fmt::format("only {} eroded points, expected at least {}", eroded, min_eroded));
  } catch (const kessler::Error& e) {
    fmt::print(stderr, "compare_runs: {}\n", e.what());
    return 2;
  }
  if (problems > 0) fmt::print(stderr, "{} differences between {} and {}\n", problems, a.string(), b.string());
  return problems > 0 ? 1 : 0;
}
