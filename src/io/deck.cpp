#include "io/deck.hpp"

#include "core/error.hpp"
#include "core/log.hpp"
#include "io/deck_overrides.hpp"
#include "io/deck_parts.hpp"
#include "io/yaml_reader.hpp"
#include "solver/methods.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

namespace kessler::io {

namespace {

namespace fs = std::filesystem;

std::vector<int> parseSymmetry(const Field& field) {
  std::vector<int> axes;
  for (const Field& item : field.list()) {
    const std::string name = item.text();
    const int axis = name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : -1;
    if (axis < 0) item.fail("must be x, y or z (the normal of a symmetry plane through the origin)");
    if (std::find(axes.begin(), axes.end(), axis) != axes.end()) item.fail("repeats a symmetry plane");
    axes.push_back(axis);
  }
  return axes;
}

// OTM's keys, `solver.otm` (also accepted, with a note, directly under `solver`, where they were
// before 2026-11-27).
constexpr std::array<std::string_view, 6> otm_keys = {"lme_gamma",        "lme_tolerance",    "min_neighbours",
                                                      "contact_distance", "crack_visibility", "volume_averaging"};

void parseOtmKey(const std::string& key, const Field& value, OtmOptions& o) {
  if (key == "lme_gamma") o.lme_gamma = value.positive(units::dimensionless);
  if (key == "lme_tolerance") {
    o.lme_tolerance = value.quantity(units::dimensionless);
    if (!(o.lme_tolerance > 0.0 && o.lme_tolerance < 1.0)) value.fail("must lie in (0, 1)");
  }
  // Four nodes at least: a point must lie inside the convex hull of its neighbours in 3D.
  if (key == "min_neighbours") o.min_neighbours = static_cast<int>(value.integer(4, 10000));
  if (key == "contact_distance") {
    o.contact_distance = value.quantity(units::dimensionless);
    if (o.contact_distance < 0.0) value.fail("must not be negative");
  }
  if (key == "crack_visibility") o.crack_visibility = value.boolean();
  if (key == "volume_averaging") o.volume_averaging = value.boolean();
}

ContactSettings parseContact(const Field& field) {
  const MapField map = field.map({"type", "friction"});
  ContactSettings contact;
  if (std::optional<Field> type = map.find("type")) {
    const std::string name = type->text();
    if (name == "seizing")
      contact.kind = ContactSettings::Kind::seizing;
    else if (name == "sliding")
      contact.kind = ContactSettings::Kind::sliding;
    else
      type->fail("must be seizing or sliding");
  }
  if (std::optional<Field> friction = map.find("friction")) {
    contact.friction = friction->quantity(units::dimensionless);
    if (!(contact.friction >= 0.0)) friction->fail("must not be negative");
    if (!contact.sliding()) friction->fail("applies to a sliding contact only (give type: sliding)");
  }
  return contact;
}

void parseSolver(const Field& field, RunConfig& config) {
  const std::vector<std::string_view> moved(otm_keys.begin(), otm_keys.end());
  MapField map = field.map({"method", "end_time", "cfl", "max_steps", "min_dt_fraction", "max_energy_growth",
                            "debris_contact", "contact", "otm"},
                           moved);
  if (std::optional<Field> method = map.find("method")) {
    const std::vector<std::string>& known = methodNames();
    if (std::find(known.begin(), known.end(), method->text()) == known.end())
      method->fail(fmt::format("unknown method (known: {})", fmt::join(known, ", ")));
    config.method = method->text();
  }
  SolverSettings& s = config.solver;
  s.end_time = map.require("end_time").positive(units::time);
  if (std::optional<Field> cfl = map.find("cfl")) {
    s.cfl = cfl->quantity(units::dimensionless);
    if (!(s.cfl > 0.0 && s.cfl <= 1.0)) cfl->fail("must lie in (0, 1]");
  }
  if (std::optional<Field> steps = map.find("max_steps"))
    s.max_steps = steps->integer(0, std::numeric_limits<long>::max());
  if (std::optional<Field> contact = map.find("debris_contact")) s.debris_contact = contact->boolean();
  if (std::optional<Field> contact = map.find("contact")) s.contact = parseContact(*contact);
  if (std::optional<Field> fraction = map.find("min_dt_fraction")) {
    s.min_dt_fraction = fraction->quantity(units::dimensionless);
    if (!(s.min_dt_fraction >= 0.0 && s.min_dt_fraction < 1.0)) fraction->fail("must lie in [0, 1) (0: no check)");
  }
  if (std::optional<Field> growth = map.find("max_energy_growth"))
    s.max_energy_growth = growth->positive(units::dimensionless);

  std::vector<std::string> old_place;
  std::string first;
  for (const MapField::Entry& entry : map.entries()) {
    if (std::find(moved.begin(), moved.end(), entry.key) == moved.end()) continue;
    if (map.find("otm")) entry.value.fail("belongs in solver.otm, which this deck also has: give it there only");
    if (old_place.empty()) first = entry.value.source().where(entry.key_mark, entry.value.path());
    old_place.push_back(entry.key);
    parseOtmKey(entry.key, entry.value, config.otm);
  }
  if (!old_place.empty())
    log::info("note: {}: solver.{}: OTM's keys now go in solver.otm; the old place still works", first,
              fmt::join(old_place, ", "));
  if (std::optional<Field> otm = map.find("otm")) {
    const MapField own = otm->map(moved);
    for (const MapField::Entry& entry : own.entries()) parseOtmKey(entry.key, entry.value, config.otm);
  }
}

OutputConfig parseOutput(const std::optional<Field>& field, double end_time) {
  OutputConfig output;
  output.every = end_time / 20.0;
  if (!field) return output;
  MapField map = field->map({"every", "dir"});
  if (std::optional<Field> every = map.find("every")) {
    output.every = every->quantity(units::time);
    if (output.every < 0.0) every->fail("must not be negative (0 writes only the first and last states)");
  }
  if (std::optional<Field> dir = map.find("dir")) output.dir = dir->text("a folder path");
  return output;
}

CheckpointConfig parseCheckpoint(const std::optional<Field>& field, double end_time) {
  CheckpointConfig checkpoint;
  checkpoint.every = end_time / 10.0;
  if (!field) return checkpoint;
  MapField map = field->map({"every", "wall_interval"});
  if (std::optional<Field> every = map.find("every")) {
    checkpoint.every = every->quantity(units::time);
    if (checkpoint.every < 0.0) every->fail("must not be negative (0: no checkpoints by simulated time)");
  }
  if (std::optional<Field> wall = map.find("wall_interval")) {
    checkpoint.wall_interval = wall->quantity(units::time);
    if (checkpoint.wall_interval < 0.0) wall->fail("must not be negative (0: no checkpoints by wall time)");
  }
  return checkpoint;
}

RunConfig parseTree(const Field& top, const fs::path& base_dir) {
  MapField deck = top.map({"title", "materials", "bodies", "symmetry", "solver", "output", "checkpoint", "analysis"});
  RunConfig config;
  config.deck_path = top.source().file();
  if (std::optional<Field> title = deck.find("title")) config.title = title->text("a title", true);
  config.materials = parseMaterials(deck.require("materials"), base_dir);
  if (std::optional<Field> symmetry = deck.find("symmetry")) config.symmetry_axes = parseSymmetry(*symmetry);
  Field bodies = deck.require("bodies");
  config.bodies = parseBodies(bodies, config.materials, config.symmetry_axes, base_dir);
  parseSolver(deck.require("solver"), config);
  config.output = parseOutput(deck.find("output"), config.solver.end_time);
  config.checkpoint = parseCheckpoint(deck.find("checkpoint"), config.solver.end_time);
  checkOverlaps(config.bodies, bodies);
  checkMemory(config, bodies);
  config.analysis = parseAnalysis(deck.find("analysis"), config.bodies, bodies);
  return config;
}

[[noreturn]] void failYaml(const std::string& name, const YAML::Exception& e, std::string_view kind) {
  const int line = e.mark.is_null() ? 1 : e.mark.line + 1;
  const int column = e.mark.is_null() ? 1 : e.mark.column + 1;
  throw InputError(printable(fmt::format("{}:{}:{}: {}: {}", name, line, column, kind, e.msg)));
}

// The line (1-based) where a second YAML document starts, 0 if there is none: a '---' marker after
// content, or content after a '...' end marker. Markers sit at column 0, where no block scalar of
// a deck can hold them.
int secondDocumentLine(const std::string& text) {
  auto hasContent = [](std::string_view rest) {
    const std::size_t first = rest.find_first_not_of(" \t\r");
    return first != std::string_view::npos && rest[first] != '#';
  };
  std::istringstream in(text);
  std::string line;
  bool content = false, ended = false;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string_view view(line);
    auto marker = [&](std::string_view m) {
      return view.starts_with(m) &&
             (view.size() == m.size() || std::isspace(static_cast<unsigned char>(view[m.size()])));
    };
    if (marker("---")) {
      if (content || ended) return number;
      content = hasContent(view.substr(3));
    } else if (marker("...")) {
      ended = true;
    } else if (hasContent(view)) {
      if (ended) return number;
      content = true;
    }
  }
  return 0;
}

RunConfig parseText(const std::string& text, const std::string& name, const fs::path& base_dir,
                    const std::vector<std::string>& overrides) {
  DeckSource source(name);
  if (const int line = secondDocumentLine(text))
    throw InputError(fmt::format("{}:{}:1: a second YAML document ('---'): a deck is one document", name, line));
  // YAML::Load, not LoadAll: yaml-cpp 0.7's LoadAll loops forever, allocating, on a stray ',' in
  // block context (yaml-cpp issue #1040, fixed upstream in PR #1319; found by fuzz_deck).
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    failYaml(name, e, "YAML syntax error");
  }
  if (!root || root.IsNull()) {
    // A null document from a file with content: yaml-cpp gave up on its first token (e.g. a ',').
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      const std::size_t first = line.find_first_not_of(" \t\r");
      if (first == std::string::npos || line[first] == '#' || line.starts_with("---")) continue;
      throw InputError(printable(fmt::format("{}:{}:{}: YAML syntax error: no YAML value starts here (got '{}')", name,
                                             number, first + 1, line.substr(first, 40))));
    }
    throw InputError(fmt::format("{}:1:1: the deck is empty", name));
  }
  Field top(source, root, "", root.Mark());
  if (!root.IsMap())
    top.fail(
        "the deck must be a map of sections (title, materials, bodies, symmetry, solver, output, checkpoint, "
        "analysis)");
  applyOverrides(root, overrides, source);
  try {
    return parseTree(top, base_dir);
  } catch (const YAML::Exception& e) {
    failYaml(name, e, "YAML error");
  }
}

}  // namespace

RunConfig parseDeckString(const std::string& yaml_text, const std::string& name_for_errors,
                          const std::vector<std::string>& overrides) {
  return parseText(yaml_text, name_for_errors, fs::path(name_for_errors).parent_path(), overrides);
}

RunConfig parseDeck(const fs::path& deck, const std::vector<std::string>& overrides) {
  const std::string name = deck.string();
  std::error_code error;
  const fs::file_status status = fs::status(deck, error);
  if (!fs::exists(status)) throw InputError(fmt::format("{}: cannot read the deck: no such file", name));
  if (fs::is_directory(status)) throw InputError(fmt::format("{}: cannot read the deck: it is a directory", name));
  std::ifstream in(deck, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot read the deck: {}", name, std::strerror(errno)));
  // A deck is a few KiB of text: read at most a bound, so that the wrong file given (a mesh, a
  // device such as /dev/zero) is refused instead of filling the memory.
  constexpr std::streamsize max_deck_bytes = 16 << 20;
  std::string text(static_cast<std::size_t>(max_deck_bytes) + 1, '\0');
  in.read(text.data(), max_deck_bytes + 1);
  if (in.bad()) throw InputError(fmt::format("{}: cannot read the deck: read error", name));
  if (in.gcount() > max_deck_bytes)
    throw InputError(fmt::format("{}:1:1: more than {} MiB, too large for a deck: is it the right file?", name,
                                 max_deck_bytes >> 20));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return parseText(text, name, deck.parent_path(), overrides);
}

}  // namespace kessler::io
