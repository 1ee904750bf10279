#pragma once
// Typed access to a parsed YAML deck, with errors that say where. Every failure is a one-line
// kessler::InputError "<file>:<line>:<column>: <key path>: <what is wrong> (got '<value>')", or
// "command line (--set <text>): ..." for a value that came from a command-line override.
#include "core/types.hpp"
#include "core/units.hpp"

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace kessler::io {

// Where the deck's text came from: the file, and the subtrees that command-line overrides replaced.
class DeckSource {
 public:
  explicit DeckSource(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }

  // Errors at `path` or below it are reported as coming from the override `text`.
  void addOverride(std::string text, std::string path);

  // "<file>:<line>:<column>" (1-based) or "command line (--set <text>)".
  std::string where(const YAML::Mark& mark, std::string_view path) const;

 private:
  struct Override {
    std::string text;
    std::string path;
  };
  std::string file_;
  std::vector<Override> overrides_;
};

// A node rendered on one line for messages: a scalar as written, a map or list in flow style,
// shortened if long.
std::string describeNode(const YAML::Node& node);

// `text` with control characters escaped (a newline as \n, others as \xNN), for one-line messages.
std::string printable(std::string_view text);

// "a" + "b" -> "a.b", "" + "b" -> "b".
std::string childPath(std::string_view parent, std::string_view key);

class MapField;

// A node of the deck with its key path ("bodies[0].shape.sphere.radius") and position.
class Field {
 public:
  Field(const DeckSource& source, YAML::Node node, std::string path, YAML::Mark mark);
  Field(const Field&) = default;
  Field& operator=(const Field& other);  // rebinds; never writes into the YAML tree

  const YAML::Node& node() const { return node_; }
  const std::string& path() const { return path_; }
  const YAML::Mark& mark() const { return mark_; }
  const DeckSource& source() const { return *source_; }

  // Throws "<where>: <path>: <what> (got '<value>')"; the value is left out when the node is empty.
  [[noreturn]] void fail(std::string_view what) const;
  // Same without the value, for messages that already quote it.
  [[noreturn]] void failBare(std::string_view what) const;

  // A number (in SI units) or a quantity string ("5 mm") of the given dimension, finite.
  double quantity(units::Dimension dimension) const;
  double positive(units::Dimension dimension) const;
  // A list of exactly three quantities.
  Vec3 vector(units::Dimension dimension) const;
  // A whole number within `min`..`max`.
  long integer(long min, long max) const;
  // true/yes/on or false/no/off.
  bool boolean() const;
  // A scalar (a name, a path, a title), described in messages as `what`; not empty unless allowed.
  std::string text(std::string_view what = "a name", bool allow_empty = false) const;
  // A list; each entry a Field with path "<path>[i]".
  std::vector<Field> list() const;
  // A map whose keys must all be among `allowed`, or among `also_accepted`, which the message about
  // an unknown key does not list (keys that moved elsewhere but still work).
  MapField map(std::vector<std::string_view> allowed, std::vector<std::string_view> also_accepted = {}) const;
  // A map with keys of the user's choosing (names of materials).
  MapField namedMap() const;

 private:
  const std::string& scalar(std::string_view expected) const;

  const DeckSource* source_;
  YAML::Node node_;
  std::string path_;
  YAML::Mark mark_;
};

// A map whose keys were checked: plain scalars, none repeated, none unknown.
class MapField {
 public:
  struct Entry {
    std::string key;
    YAML::Mark key_mark;
    Field value;
  };

  const Field& self() const { return self_; }
  const std::vector<Entry>& entries() const { return entries_; }
  std::optional<Field> find(std::string_view key) const;
  // Fails at the map's position with "missing required key '<key>'" if absent.
  Field require(std::string_view key) const;

 private:
  friend class Field;
  MapField(Field self, std::vector<Entry> entries) : self_(std::move(self)), entries_(std::move(entries)) {}

  Field self_;
  std::vector<Entry> entries_;
};

}  // namespace kessler::io
