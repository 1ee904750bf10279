// SESAME ASCII reader and writer (LANL format; Lyon & Johnson, LA-UR-92-3407, 1992; docs/eos.md
// "SESAME files"). A table is a header line (I2 record flag, I6 material id, I6
// table id, I6 word count) followed by its words, five E15.8 numbers per line,
// columns 76-80 holding a line marker that is ignored. Units in the file:
// g/cm^3, K, GPa, MJ/kg; Kessler converts to SI on the way in.
#include "core/error.hpp"
#include "material/eos/tabular.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

namespace kessler::eos {

namespace {

constexpr double g_per_cm3 = 1e3;  // kg/m^3
constexpr double gpa = 1e9;        // Pa
constexpr double mj_per_kg = 1e6;  // J/kg
constexpr std::size_t field_width = 15;
constexpr std::size_t data_columns = 75;  // five E15.8 fields; columns 76-80 are the marker

struct Header {
  int flag = 0, material = 0, table = 0, words = 0;
  bool has_words = false;  // false when the word-count field is blank (a truncated header)
};

// The words of one table and the line each came from, for located messages.
struct Words {
  std::vector<double> value;
  std::vector<int> line;
};

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return std::string(s.substr(first, s.find_last_not_of(" \t") - first + 1));
}

std::optional<int> parseInt(std::string_view text) {
  const std::string t = trim(text);
  int value = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (t.empty() || ec != std::errc() || end != t.data() + t.size()) return std::nullopt;
  return value;
}

std::string_view column(std::string_view line, std::size_t first, std::size_t width) {
  return first < line.size() ? line.substr(first, width) : std::string_view();
}

// A header from its four fields; a blank material or table is allowed only on
// the end-of-file record (flag 2); a blank word count is refused later, with
// its line.
std::optional<Header> headerFrom(std::string_view f, std::string_view m, std::string_view t, std::string_view w) {
  auto orBlank = [](std::string_view s, int blank) {
    return trim(s).empty() ? std::optional<int>(blank) : parseInt(s);
  };
  const auto flag = parseInt(f);
  const auto material = orBlank(m, 0), table = orBlank(t, 0), words = orBlank(w, 0);
  if (!flag || !material || !table || !words) return std::nullopt;
  if (*flag != 2 && (trim(m).empty() || trim(t).empty())) return std::nullopt;
  return Header{.flag = *flag, .material = *material, .table = *table, .words = *words, .has_words = !trim(w).empty()};
}

// A header in fixed columns (I2, I6, I6, I6) or, for hand-made files, as
// separate integers. Data lines never match: column 3 of an E15.8 field is its
// decimal point.
std::optional<Header> parseHeader(const std::string& line) {
  const std::string_view s(line);
  // A digit in column 21 means the word count overflowed its I6 field: read the
  // tokens instead.
  const bool overflow = s.size() > 20 && std::isdigit(static_cast<unsigned char>(s[20]));
  if (auto h = headerFrom(column(s, 0, 2), column(s, 2, 6), column(s, 8, 6), column(s, 14, 6)); h && !overflow)
    return h;
  std::istringstream in(line);
  std::string f, m, t, w;
  in >> f >> m >> t >> w;
  return headerFrom(f, m, t, w);
}

// One E15.8 field; also accepts Fortran's 'D' exponent and its 3-digit form
// "1.0+100".
std::optional<double> parseNumber(std::string text) {
  for (char& c : text)
    if (c == 'D' || c == 'd') c = 'E';
  if (text.find_first_of("Ee") == std::string::npos) {
    const auto sign = text.find_first_of("+-", 1);
    if (sign != std::string::npos && std::isdigit(static_cast<unsigned char>(text[sign - 1]))) text.insert(sign, "E");
  }
  std::size_t begin = (!text.empty() && text[0] == '+') ? 1 : 0;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data() + begin, text.data() + text.size(), value);
  if (text.size() == begin || end != text.data() + text.size()) return std::nullopt;
  // Out of range: overflow reads as infinity (refused as non-finite), underflow
  // as 0.
  if (ec == std::errc::result_out_of_range) return std::strtod(text.c_str() + begin, nullptr);
  if (ec != std::errc()) return std::nullopt;
  return value;
}

// Text of a line quoted in a message: at most 40 characters, non-printable
// bytes as '?', so that a binary file still gives a one-line, readable message.
std::string printable(std::string_view text) {
  std::string q = trim(text.substr(0, 40));
  for (char& c : q)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e) c = '?';
  return q;
}

class Reader {
 public:
  explicit Reader(const std::filesystem::path& file) : file_(file.string()) {
    std::ifstream in(file);
    if (!in) throw InputError(fmt::format("{}: cannot open the SESAME file", file_));
    for (std::string line; std::getline(in, line);) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      lines_.push_back(std::move(line));
    }
  }

  [[noreturn]] void fail(int line, const std::string& what) const {
    // Messages quote the file's text; a binary file must not put control
    // characters into them.
    std::string shown;
    for (char c : what) {
      const auto byte = static_cast<unsigned char>(c);
      shown += byte < 0x20 || byte == 0x7f ? fmt::format("\\x{:02x}", byte) : std::string(1, c);
    }
    throw InputError(fmt::format("{}:{}: {}", file_, line, shown));
  }
  int lastLine() const { return std::max<int>(1, static_cast<int>(lines_.size())); }

  // The next non-blank line, or nullopt at the end of the file.
  std::optional<std::string> next() {
    while (next_ < lines_.size()) {
      const std::string& line = lines_[next_++];
      if (!trim(line).empty()) return line;
    }
    return std::nullopt;
  }
  int line() const { return static_cast<int>(next_); }  // 1-based number of the line last returned
  void back() { --next_; }

  // Skips a table Kessler does not read (comments, other materials): up to the
  // next header.
  void skipTable() {
    while (auto text = next()) {
      if (parseHeader(*text)) {
        back();
        return;
      }
    }
  }

  Words readWords(const Header& h) {
    Words w;
    const auto n = static_cast<std::size_t>(h.words);
    while (w.value.size() < n) {
      const auto text = next();
      if (!text)
        fail(lastLine(), fmt::format("truncated: table {} of material {} has "
                                     "{} of the {} words its header announces",
                                     h.table, h.material, w.value.size(), n));
      if (parseHeader(*text))
        fail(line(), fmt::format("word count mismatch: table {} of material {} "
                                 "ends after {} of the {} words its "
                                 "header announces",
                                 h.table, h.material, w.value.size(), n));
      const std::string data = text->substr(0, std::min(text->size(), data_columns));
      bool ended = false;
      for (std::size_t at = 0; at < data.size(); at += field_width) {
        const std::string field = trim(std::string_view(data).substr(at, field_width));
        if (field.empty()) {
          ended = true;
          continue;
        }
        if (ended)
          fail(line(),
               "a blank field between numbers (expected five E15.8 "
               "numbers per line)");
        const auto value = parseNumber(field);
        if (!value)
          fail(line(), fmt::format("'{}' is not a number (expected five E15.8 numbers per line)", printable(field)));
        if (!std::isfinite(*value)) fail(line(), fmt::format("non-finite number '{}'", field));
        if (w.value.size() == n)
          fail(line(), fmt::format("word count mismatch: table {} of material "
                                   "{} has more than the {} words its "
                                   "header announces",
                                   h.table, h.material, n));
        w.value.push_back(*value);
        w.line.push_back(line());
      }
    }
    return w;
  }

 private:
  std::string file_;
  std::vector<std::string> lines_;
  std::size_t next_ = 0;
};

void strictlyIncreasing(const Reader& r, const Words& w, std::size_t first, std::size_t count, const char* what) {
  for (std::size_t k = first; k < first + count; ++k) {
    if (w.value[k] < 0.0) r.fail(w.line[k], fmt::format("negative {} {:.8E}", what, w.value[k]));
    if (k > first && !(w.value[k] > w.value[k - 1]))
      r.fail(w.line[k], fmt::format("{} grid not increasing: {:.8E} follows {:.8E}", what, w.value[k], w.value[k - 1]));
  }
}

std::size_t gridSize(const Reader& r, const Words& w, std::size_t k, const char* what) {
  const double n = w.value[k];
  if (!(n >= 2.0 && n <= 1e6 && n == std::floor(n)))
    r.fail(w.line[k], fmt::format("table 301: the number of {} must be an "
                                  "integer of at least 2 (got {})",
                                  what, n));
  return static_cast<std::size_t>(n);
}

void fill201(const Reader& r, const Words& w, SesameTable& t) {
  if (w.value.size() < 5)
    r.fail(w.line.back(), fmt::format("table 201 needs 5 words (Z, A, rho0, B0, T0), got {}", w.value.size()));
  if (!(w.value[2] > 0.0))
    r.fail(w.line[2], fmt::format("table 201: reference density must be positive (got {})", w.value[2]));
  if (w.value[4] < 0.0) r.fail(w.line[4], fmt::format("table 201: negative reference temperature {}", w.value[4]));
  t.z = w.value[0];
  t.a = w.value[1];
  t.density = w.value[2] * g_per_cm3;
  t.bulk_modulus = w.value[3] * gpa;
  t.temperature0 = w.value[4];
}

void fill301(const Reader& r, const Words& w, int header_line, SesameTable& t) {
  if (w.value.size() < 2) r.fail(header_line, "table 301 needs at least the two grid sizes NR and NT");
  const std::size_t nr = gridSize(r, w, 0, "densities");
  const std::size_t nt = gridSize(r, w, 1, "temperatures");
  const std::size_t needed = 2 + nr + nt + 2 * nr * nt;
  if (w.value.size() < needed)
    r.fail(header_line, fmt::format("word count mismatch: table 301 with NR = "
                                    "{}, NT = {} needs at least {} words, "
                                    "its header announces {}",
                                    nr, nt, needed, w.value.size()));
  strictlyIncreasing(r, w, 2, nr, "density");
  strictlyIncreasing(r, w, 2 + nr, nt, "temperature");
  for (std::size_t i = 0; i < nr; ++i) t.rho.push_back(w.value[2 + i] * g_per_cm3);
  for (std::size_t j = 0; j < nt; ++j) t.temperature.push_back(w.value[2 + nr + j]);
  const std::size_t p0 = 2 + nr + nt, e0 = p0 + nr * nt;
  for (std::size_t k = 0; k < nr * nt; ++k) {
    t.pressure.push_back(w.value[p0 + k] * gpa);
    t.energy.push_back(w.value[e0 + k] * mj_per_kg);
  }
  // p(rho, e) inverts E(rho, T) in T, which needs E to increase with T at every
  // density.
  for (std::size_t j = 1; j < nt; ++j)
    for (std::size_t i = 0; i < nr; ++i)
      if (!(t.energy[j * nr + i] > t.energy[(j - 1) * nr + i]))
        r.fail(w.line[e0 + j * nr + i], fmt::format("table 301: energy does not increase with temperature at "
                                                    "rho = {:.8E} g/cm^3 between "
                                                    "T = {:.8E} K and {:.8E} K ({:.8E} then {:.8E} MJ/kg)",
                                                    w.value[2 + i], t.temperature[j - 1], t.temperature[j],
                                                    w.value[e0 + (j - 1) * nr + i], w.value[e0 + j * nr + i]));
}

}  // namespace

SesameTable readSesame(const std::filesystem::path& file, int material_id) {
  Reader r(file);
  SesameTable t;
  int selected = material_id;
  bool chosen = material_id != 0;
  std::vector<int> materials;
  bool has201 = false, has301 = false;
  std::optional<Header> previous;
  while (auto text = r.next()) {
    const auto h = parseHeader(*text);
    if (!h && previous && parseNumber(trim(std::string_view(*text).substr(0, std::min(text->size(), field_width)))))
      r.fail(r.line(), fmt::format("word count mismatch: numbers continue after the {} "
                                   "words that the header of "
                                   "table {} of material {} announces",
                                   previous->words, previous->table, previous->material));
    if (!h)
      r.fail(r.line(), fmt::format("not a SESAME table header (expected record "
                                   "flag, material id, table id, word "
                                   "count): '{}'",
                                   printable(*text)));
    previous = h;
    if (h->flag == 2) break;  // end-of-file record
    if (h->flag != 0 && h->flag != 1)
      r.fail(r.line(), fmt::format("record flag {} is not a SESAME table "
                                   "header (0 or 1) or end of file (2)",
                                   h->flag));
    if (!h->has_words) r.fail(r.line(), fmt::format("the header of table {} has no word count (truncated?)", h->table));
    if (h->words <= 0) r.fail(r.line(), fmt::format("table {} has a word count of {}", h->table, h->words));
    if (!chosen) {
      selected = h->material;
      chosen = true;
    }
    if (std::find(materials.begin(), materials.end(), h->material) == materials.end()) materials.push_back(h->material);
    const bool wanted = h->material == selected && (h->table == 201 || h->table == 301);
    if (!wanted) {
      r.skipTable();
      continue;
    }
    const int header_line = r.line();
    bool& seen = h->table == 201 ? has201 : has301;
    if (seen) r.fail(header_line, fmt::format("a second table {} for material {}", h->table, selected));
    seen = true;
    const Words w = r.readWords(*h);
    if (h->table == 201)
      fill201(r, w, t);
    else
      fill301(r, w, header_line, t);
  }
  if (materials.empty()) r.fail(r.lastLine(), "empty file: no SESAME table header found");
  if (std::find(materials.begin(), materials.end(), selected) == materials.end())
    r.fail(r.lastLine(),
           fmt::format("material {} is not in the file (materials: {})", selected, fmt::join(materials, ", ")));
  for (auto [found, table] : {std::pair{has201, 201}, std::pair{has301, 301}})
    if (!found) r.fail(r.lastLine(), fmt::format("end of file without table {} for material {}", table, selected));
  t.material_id = selected;
  return t;
}

void writeSesame(const SesameTable& t, const std::filesystem::path& file) {
  const std::size_t nr = t.rho.size(), nt = t.temperature.size();
  if (nr < 2 || nt < 2 || t.pressure.size() != nr * nt || t.energy.size() != nr * nt)
    throw InputError(
        fmt::format("{}: cannot write a SESAME table of {} "
                    "densities, {} temperatures, {} pressures and "
                    "{} energies",
                    file.string(), nr, nt, t.pressure.size(), t.energy.size()));
  if (t.material_id < 0 || t.material_id > 999999)
    throw InputError(fmt::format("{}: SESAME material id {} does not fit in I6", file.string(), t.material_id));
  if (2 + nr + nt + 2 * nr * nt > 999999)
    throw InputError(
        fmt::format("{}: a {} x {} table 301 has more words than its I6 header can count", file.string(), nr, nt));
  std::vector<double> words201{t.z, t.a, t.density / g_per_cm3, t.bulk_modulus / gpa, t.temperature0};
  std::vector<double> words301{static_cast<double>(nr), static_cast<double>(nt)};
  for (double rho : t.rho) words301.push_back(rho / g_per_cm3);
  words301.insert(words301.end(), t.temperature.begin(), t.temperature.end());
  for (double p : t.pressure) words301.push_back(p / gpa);
  for (double e : t.energy) words301.push_back(e / mj_per_kg);

  std::string out;
  int line = 0;
  auto endLine = [&](std::string text) {
    text.resize(data_columns, ' ');
    out += fmt::format("{}{:5d}\n", text, ++line % 100000);
  };
  auto table = [&](int flag, int id, const std::vector<double>& words) {
    endLine(fmt::format("{:2d}{:6d}{:6d}{:6d}", flag, t.material_id, id, words.size()));
    std::string text;
    for (std::size_t k = 0; k < words.size(); ++k) {
      double v = words[k];
      // E15.8 holds two exponent digits; smaller magnitudes are written as
      // zero.
      if (!std::isfinite(v) || std::abs(v) >= 1e99)
        throw InputError(fmt::format("{}: table {} word {} = {} cannot be written as E15.8", file.string(), id, k, v));
      if (std::abs(v) < 1e-99) v = 0.0;
      text += fmt::format("{:15.8E}", v);
      if (k % 5 == 4 || k + 1 == words.size()) {
        endLine(std::move(text));
        text.clear();
      }
    }
  };
  table(0, 201, words201);
  table(1, 301, words301);
  std::ofstream f(file);
  if (!(f << out) || !(f.flush())) throw InputError(fmt::format("{}: cannot write the SESAME file", file.string()));
}

}  // namespace kessler::eos
