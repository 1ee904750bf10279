#include "io/yaml_reader.hpp"

#include "core/error.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace kessler::io {

namespace {

constexpr std::size_t max_shown = 60;

// How a quantity of a dimension is named in messages, with an example of how to write one.
std::string expectedQuantity(units::Dimension d) {
  struct Known {
    units::Dimension dimension;
    const char* text;
  };
  static constexpr Known known[] = {
      {units::dimensionless, "a number such as '0.3'"},    {units::length, "a length such as '5 mm'"},
      {units::velocity, "a velocity such as '200 m/s'"},   {units::time, "a time such as '20 us'"},
      {units::density, "a density such as '2700 kg/m^3'"}, {units::pressure, "a pressure such as '70 GPa'"},
  };
  for (const Known& k : known)
    if (k.dimension == d) return k.text;
  return fmt::format("a quantity in {}", units::describe(d));
}

std::string oneLine(std::string text) {
  std::string out;
  for (char c : text) out += c == '\n' ? std::string("\\n") : std::string(1, c);
  if (out.size() > max_shown) out = out.substr(0, max_shown - 3) + "...";
  return out;
}

// YAML's own spellings of infinity and not-a-number, which YAML takes for numbers.
bool isYamlNonFinite(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  if (!text.empty() && (text.front() == '+' || text.front() == '-')) text.erase(0, 1);
  return text == ".inf" || text == ".nan";
}

}  // namespace

void DeckSource::addOverride(std::string text, std::string path) {
  overrides_.push_back({std::move(text), std::move(path)});
}

std::string DeckSource::where(const YAML::Mark& mark, std::string_view path) const {
  // The latest override wins, as it does when applied.
  for (auto it = overrides_.rbegin(); it != overrides_.rend(); ++it) {
    const std::string& owned = it->path;
    bool below = path.size() > owned.size() && path.substr(0, owned.size()) == owned &&
                 (path[owned.size()] == '.' || path[owned.size()] == '[');
    if (path == owned || below) return fmt::format("command line (--set {})", it->text);
  }
  if (mark.is_null()) return fmt::format("{}:1:1", file_);
  return fmt::format("{}:{}:{}", file_, mark.line + 1, mark.column + 1);
}

std::string describeNode(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "";
  if (node.IsScalar()) return oneLine(node.Scalar());
  YAML::Emitter out;
  out.SetMapFormat(YAML::Flow);
  out.SetSeqFormat(YAML::Flow);
  out << node;
  return oneLine(out.c_str());
}

std::string childPath(std::string_view parent, std::string_view key) {
  return parent.empty() ? std::string(key) : fmt::format("{}.{}", parent, key);
}

Field::Field(const DeckSource& source, YAML::Node node, std::string path, YAML::Mark mark)
    : source_(&source), node_(std::move(node)), path_(std::move(path)), mark_(mark) {}

Field& Field::operator=(const Field& other) {
  source_ = other.source_;
  node_.reset(other.node_);  // rebinds the handle; assigning a YAML::Node would overwrite the tree
  path_ = other.path_;
  mark_ = other.mark_;
  return *this;
}

std::string printable(std::string_view text) {
  std::string out;
  for (char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n')
      out += "\\n";
    else if (byte < 0x20 || byte == 0x7f)
      out += fmt::format("\\x{:02x}", byte);
    else
      out += c;
  }
  return out;
}

void Field::failBare(std::string_view what) const {
  // Keys and values are quoted as written; a binary file must not put control characters (or a
  // second line) into the one-line message.
  throw InputError(
      printable(fmt::format("{}: {}: {}", source_->where(mark_, path_), path_.empty() ? "top level" : path_, what)));
}

void Field::fail(std::string_view what) const {
  std::string shown = describeNode(node_);
  if (!node_.IsDefined() || node_.IsNull()) failBare(what);
  failBare(fmt::format("{} (got '{}')", what, shown));
}

const std::string& Field::scalar(std::string_view expected) const {
  if (!node_.IsDefined() || node_.IsNull()) fail(fmt::format("missing value: must be {}", expected));
  if (node_.IsMap()) fail(fmt::format("must be {}, not a map", expected));
  if (node_.IsSequence()) fail(fmt::format("must be {}, not a list", expected));
  return node_.Scalar();
}

double Field::quantity(units::Dimension dimension) const {
  const std::string& text = scalar(expectedQuantity(dimension));
  if (isYamlNonFinite(text)) fail("must be a finite number");
  try {
    return units::toSI(text, dimension);
  } catch (const InputError& e) {
    // The units parser quotes the text in most of its messages; do not show it twice.
    std::string why = e.what();
    if (why.find(fmt::format("'{}'", text)) != std::string::npos) failBare(why);
    fail(why);
  }
}

double Field::positive(units::Dimension dimension) const {
  double value = quantity(dimension);
  if (!(value > 0.0)) fail("must be positive");
  return value;
}

Vec3 Field::vector(units::Dimension dimension) const {
  std::string expected = fmt::format("a list of 3 components, each {}", expectedQuantity(dimension));
  if (!node_.IsDefined() || node_.IsNull()) fail(fmt::format("missing value: must be {}", expected));
  if (!node_.IsSequence()) fail(fmt::format("must be {}", expected));
  if (node_.size() != 3) fail(fmt::format("must have 3 components, not {}", node_.size()));
  std::vector<Field> components = list();
  return {components[0].quantity(dimension), components[1].quantity(dimension), components[2].quantity(dimension)};
}

long Field::integer(long min, long max) const {
  double value = quantity(units::dimensionless);
  if (value != std::floor(value)) fail("must be a whole number");
  // 2^63 and above do not fit a long (converting them is undefined), though max as a double may
  // round up to 2^63.
  constexpr double long_limit = 9223372036854775808.0;
  if (value < static_cast<double>(min) || !(value < long_limit) || static_cast<long>(value) > max) {
    if (max == std::numeric_limits<long>::max() && value < static_cast<double>(min))
      fail(fmt::format("must be at least {}", min));
    fail(fmt::format("must lie between {} and {}", min, max));
  }
  return static_cast<long>(value);
}

bool Field::boolean() const {
  const std::string value = text("true or false");
  if (value == "true" || value == "yes" || value == "on") return true;
  if (value == "false" || value == "no" || value == "off") return false;
  fail("must be true or false");
}

std::string Field::text(std::string_view what, bool allow_empty) const {
  std::string value = scalar(what);
  if (value.empty() && !allow_empty) fail("must not be empty");
  return value;
}

std::vector<Field> Field::list() const {
  if (!node_.IsDefined() || node_.IsNull()) fail("missing value: must be a list such as [a, b]");
  if (!node_.IsSequence()) fail("must be a list such as [a, b]");
  std::vector<Field> items;
  for (std::size_t i = 0; i < node_.size(); ++i) {
    YAML::Node item = node_[i];
    YAML::Mark mark = item.IsNull() || item.Mark().is_null() ? mark_ : item.Mark();
    items.emplace_back(*source_, item, fmt::format("{}[{}]", path_, i), mark);
  }
  return items;
}

MapField Field::map(std::vector<std::string_view> allowed, std::vector<std::string_view> also_accepted) const {
  if (!node_.IsDefined() || node_.IsNull()) fail("missing value: must be a map such as { key: value }");
  if (!node_.IsMap()) fail("must be a map such as { key: value }");
  MapField result = namedMap();
  for (const MapField::Entry& entry : result.entries()) {
    if (std::find(allowed.begin(), allowed.end(), entry.key) != allowed.end()) continue;
    if (std::find(also_accepted.begin(), also_accepted.end(), entry.key) != also_accepted.end()) continue;
    Field(*source_, YAML::Node(), entry.value.path(), entry.key_mark)
        .failBare(fmt::format("unknown key (allowed: {})", fmt::join(allowed, ", ")));
  }
  return result;
}

MapField Field::namedMap() const {
  if (!node_.IsDefined() || node_.IsNull()) fail("missing value: must be a map such as { name: ... }");
  if (!node_.IsMap()) fail("must be a map such as { name: ... }");
  std::vector<MapField::Entry> entries;
  // yaml-cpp keeps repeated keys (and operator[] returns the first), so look for them here.
  for (const auto& pair : node_) {
    const YAML::Node key_node = pair.first;
    if (!key_node.IsScalar()) Field(*source_, key_node, path_, key_node.Mark()).fail("keys must be plain names");
    std::string key = key_node.Scalar();
    YAML::Mark key_mark = key_node.Mark();
    Field key_field(*source_, YAML::Node(), childPath(path_, key), key_mark);
    for (const MapField::Entry& seen : entries) {
      if (seen.key != key) continue;
      if (seen.key_mark.is_null()) key_field.failBare("duplicate key");
      key_field.failBare(fmt::format("duplicate key (first given at line {})", seen.key_mark.line + 1));
    }
    YAML::Node value = pair.second;
    YAML::Mark value_mark = value.IsNull() || value.Mark().is_null() ? key_mark : value.Mark();
    entries.push_back({key, key_mark, Field(*source_, value, key_field.path(), value_mark)});
  }
  return MapField(*this, std::move(entries));
}

std::optional<Field> MapField::find(std::string_view key) const {
  for (const Entry& entry : entries_)
    if (entry.key == key) return entry.value;
  return std::nullopt;
}

Field MapField::require(std::string_view key) const {
  std::optional<Field> found = find(key);
  if (!found) self_.failBare(fmt::format("missing required key '{}'", key));
  return *found;
}

}  // namespace kessler::io
