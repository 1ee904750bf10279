#include "io/deck_overrides.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

#include <charconv>

namespace kessler::io {

namespace {

std::string trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return std::string(s);
}

[[noreturn]] void fail(const std::string& text, std::string_view path, std::string_view what) {
  if (path.empty()) throw InputError(fmt::format("command line (--set {}): {}", text, what));
  throw InputError(fmt::format("command line (--set {}): {}: {}", text, path, what));
}

// "bodies[0].velocity" and "bodies.0.velocity" both give {"bodies", "0", "velocity"}.
std::vector<std::string> splitKey(const std::string& text, const std::string& key) {
  std::vector<std::string> segments(1);
  for (char c : key) {
    if (c == '.' || c == '[') {
      segments.emplace_back();
    } else if (c != ']') {
      segments.back() += c;
    }
  }
  for (const std::string& segment : segments)
    if (trim(segment).empty())
      fail(text, "", fmt::format("'{}' is not a key path such as solver.end_time", key));
  for (std::string& segment : segments) segment = trim(segment);
  return segments;
}

void applyOne(YAML::Node root, const std::string& text, DeckSource& source) {
  std::size_t equals = text.find('=');
  if (equals == std::string::npos) fail(text, "", "expected key=value, e.g. solver.end_time=5 us");
  std::vector<std::string> segments = splitKey(text, trim(std::string_view(text).substr(0, equals)));
  YAML::Node value;
  try {
    value = YAML::Load(text.substr(equals + 1));
  } catch (const YAML::Exception& e) {
    fail(text, "", fmt::format("the value is not valid YAML: {}", e.msg));
  }

  // Walk with a handle that is rebound (reset) at each level: assigning a YAML::Node would
  // overwrite the node it refers to instead.
  YAML::Node node;
  node.reset(root);
  std::string path;
  std::string owned;  // the first level the override creates, or the key it replaces
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const std::string& segment = segments[i];
    const bool last = i + 1 == segments.size();
    YAML::Node child;
    if (node.IsSequence()) {
      std::size_t index = 0;
      auto [end, ec] = std::from_chars(segment.data(), segment.data() + segment.size(), index);
      if (ec != std::errc{} || end != segment.data() + segment.size())
        fail(text, path, fmt::format("'{}' is not an index into this list", segment));
      if (index >= node.size())
        fail(text, path,
             fmt::format("index {} is out of range: the list has {} entries", index, node.size()));
      path = fmt::format("{}[{}]", path, index);
      child.reset(node[index]);
    } else if (node.IsMap() || node.IsNull() || !node.IsDefined()) {
      path = childPath(path, segment);
      const YAML::Node& const_node = node;
      if (owned.empty() && !(node.IsMap() && const_node[segment].IsDefined())) owned = path;
      child.reset(node[segment]);
    } else {
      fail(text, path, fmt::format("is a single value, so it has no '{}' inside it", segment));
    }
    if (last) child = value;  // here assignment is meant: it writes the value into the tree
    node.reset(child);
  }
  source.addOverride(text, owned.empty() ? path : owned);
}

}  // namespace

void applyOverrides(YAML::Node root, const std::vector<std::string>& overrides, DeckSource& source) {
  for (const std::string& text : overrides) applyOne(root, text, source);
}

}  // namespace kessler::io
