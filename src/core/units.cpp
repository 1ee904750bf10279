#include "core/units.hpp"

#include "core/error.hpp"

#include <charconv>
#include <cmath>
#include <utility>

namespace kessler::units {

namespace {

Dimension combine(Dimension a, Dimension b, int sign) {
  for (std::size_t i = 0; i < a.exponent.size(); ++i) a.exponent[i] += sign * b.exponent[i];
  return a;
}

Dimension power(Dimension a, int p) {
  for (int& e : a.exponent) e *= p;
  return a;
}

struct Symbol {
  std::string_view name;
  double factor;
  Dimension dimension;
};

// Base and derived symbols. Mass is "g" so that prefixes compose ("kg", "mg").
constexpr std::array symbols{
    Symbol{"m", 1.0, length},
    Symbol{"g", 1e-3, mass},
    Symbol{"s", 1.0, time},
    Symbol{"K", 1.0, temperature},
    Symbol{"N", 1.0, {{1, 1, -2, 0}}},
    Symbol{"Pa", 1.0, pressure},
    Symbol{"bar", 1e5, pressure},
    Symbol{"J", 1.0, energy},
    Symbol{"W", 1.0, {{2, 1, -3, 0}}},
    Symbol{"Hz", 1.0, rate},
};

struct Prefix {
  std::string_view name;
  double factor;
};

constexpr std::array prefixes{
    Prefix{"T", 1e12}, Prefix{"G", 1e9},       Prefix{"M", 1e6},       Prefix{"k", 1e3},
    Prefix{"c", 1e-2}, Prefix{"m", 1e-3},      Prefix{"u", 1e-6},      Prefix{"\u00b5", 1e-6},
    Prefix{"\u03bc", 1e-6}, Prefix{"n", 1e-9}, Prefix{"p", 1e-12},
};

bool isUnitChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || static_cast<unsigned char>(c) >= 0x80;
}

// Recursive-descent parser of unit expressions:
//   expr   := term { ('*' | '/' | ' ') term }
//   term   := factor [ '^' integer ]
//   factor := symbol | '1' | '(' expr ')'
class UnitParser {
 public:
  explicit UnitParser(std::string_view text) : text_(text) {}

  Quantity parseAll() {
    Quantity q = expr();
    skipSpaces();
    if (pos_ != text_.size()) fail(fmt::format("unexpected '{}'", text_.substr(pos_)));
    return q;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError(fmt::format("invalid unit '{}': {}", text_, why));
  }

  void skipSpaces() {
    while (pos_ < text_.size() && text_[pos_] == ' ') ++pos_;
  }

  Quantity expr() {
    Quantity q = term();
    for (;;) {
      skipSpaces();
      if (pos_ >= text_.size() || text_[pos_] == ')') return q;
      int sign = 1;
      if (text_[pos_] == '*' || text_[pos_] == '.') {
        ++pos_;
      } else if (text_[pos_] == '/') {
        sign = -1;
        ++pos_;
      }
      Quantity rhs = term();
      q.value = sign > 0 ? q.value * rhs.value : q.value / rhs.value;
      q.dimension = combine(q.dimension, rhs.dimension, sign);
    }
  }

  Quantity term() {
    Quantity q = factor();
    skipSpaces();
    if (pos_ < text_.size() && text_[pos_] == '^') {
      ++pos_;
      skipSpaces();
      int p = 0;
      const char* begin = text_.data() + pos_;
      auto [end, ec] = std::from_chars(begin, text_.data() + text_.size(), p);
      if (ec != std::errc{} || end == begin) fail("expected an integer power after '^'");
      pos_ += static_cast<std::size_t>(end - begin);
      q.value = std::pow(q.value, p);
      q.dimension = power(q.dimension, p);
    }
    return q;
  }

  Quantity factor() {
    skipSpaces();
    if (pos_ >= text_.size()) fail("expected a unit symbol");
    if (text_[pos_] == '(') {
      ++pos_;
      Quantity q = expr();
      skipSpaces();
      if (pos_ >= text_.size() || text_[pos_] != ')') fail("missing ')'");
      ++pos_;
      return q;
    }
    if (text_[pos_] == '1') {
      ++pos_;
      return {1.0, dimensionless};
    }
    std::size_t start = pos_;
    while (pos_ < text_.size() && isUnitChar(text_[pos_])) ++pos_;
    if (start == pos_) fail(fmt::format("unexpected '{}'", text_.substr(pos_)));
    return symbol(text_.substr(start, pos_ - start));
  }

  Quantity symbol(std::string_view word) const {
    for (const Symbol& s : symbols)
      if (s.name == word) return {s.factor, s.dimension};
    for (const Prefix& p : prefixes) {
      if (word.size() <= p.name.size() || word.substr(0, p.name.size()) != p.name) continue;
      std::string_view rest = word.substr(p.name.size());
      for (const Symbol& s : symbols)
        if (s.name == rest) return {p.factor * s.factor, s.dimension};
    }
    fail(fmt::format("unknown unit symbol '{}'", word));
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace

std::string describe(Dimension d) {
  static constexpr std::array<std::string_view, 4> base{"m", "kg", "s", "K"};
  std::string num, den;
  for (std::size_t i = 0; i < 4; ++i) {
    int e = d.exponent[i];
    if (e == 0) continue;
    std::string& side = e > 0 ? num : den;
    if (!side.empty()) side += "*";
    side += base[i];
    if (std::abs(e) != 1) side += fmt::format("^{}", std::abs(e));
  }
  if (num.empty() && den.empty()) return "1 (dimensionless)";
  if (num.empty()) num = "1";
  return den.empty() ? num : num + "/" + den;
}

Quantity parseUnit(std::string_view unit) { return UnitParser(trim(unit)).parseAll(); }

Quantity parse(std::string_view text) {
  std::string_view s = trim(text);
  if (s.empty()) throw InputError("empty value where a number was expected");
  double number = 0.0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), number);
  if (ec == std::errc::result_out_of_range)
    throw InputError(fmt::format("number '{}' is out of range", s));
  if (ec != std::errc{} || end == s.data())
    throw InputError(fmt::format("'{}' is not a number with an optional unit", s));
  if (!std::isfinite(number)) throw InputError(fmt::format("'{}' is not a finite number", s));
  std::string_view rest = trim(s.substr(static_cast<std::size_t>(end - s.data())));
  if (rest.empty()) return {number, dimensionless};
  Quantity unit = parseUnit(rest);
  // Prefix products such as 1e-6 are not exact in binary; when the factor is (the inverse of)
  // an integer, divide or multiply by that integer so "10 us" is exactly 1e-5 s.
  double value = number * unit.value;
  const double inverse = 1.0 / unit.value;
  if (unit.value < 1.0 && std::abs(inverse - std::round(inverse)) < 1e-9 * inverse)
    value = number / std::round(inverse);
  else if (std::abs(unit.value - std::round(unit.value)) < 1e-9 * unit.value)
    value = number * std::round(unit.value);
  if (!std::isfinite(value)) throw InputError(fmt::format("'{}' overflows in SI units", s));
  return {value, unit.dimension};
}

double toSI(std::string_view text, Dimension expected) {
  Quantity q = parse(text);
  bool bare = trim(text).find_first_not_of("0123456789+-.eE") == std::string_view::npos;
  if (!bare && q.dimension != expected)
    throw InputError(fmt::format("'{}' has units of {}, expected {}", trim(text), describe(q.dimension),
                                 describe(expected)));
  return q.value;
}

}  // namespace kessler::units
