// The corpus of malformed decks: each tests/data/decks/bad_*.yaml starts with a comment
// "# expect: <substring of the error message>"; parsing it must throw one InputError with a
// one-line message that starts with "<file>:<line>:<column>: " and contains that substring.
#include "core/error.hpp"
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace kessler::io {
namespace {

namespace fs = std::filesystem;

const fs::path deck_dir = fs::path(KESSLER_TEST_DATA) / "decks";

std::vector<std::string> badDecks() {
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(deck_dir)) {
    const std::string name = entry.path().stem().string();
    if (entry.path().extension() == ".yaml" && name.starts_with("bad_")) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string expectedMessage(const fs::path& file) {
  std::ifstream in(file);
  std::string first_line;
  std::getline(in, first_line);
  const std::string prefix = "# expect: ";
  if (!first_line.starts_with(prefix)) return {};
  return first_line.substr(prefix.size());
}

// "<file>:<digits>:<digits>: " at the start of the message.
bool startsWithLocation(const std::string& message, const std::string& file) {
  if (!message.starts_with(file + ":")) return false;
  std::size_t pos = file.size() + 1;
  for (int field = 0; field < 2; ++field) {
    const std::size_t start = pos;
    while (pos < message.size() && std::isdigit(static_cast<unsigned char>(message[pos]))) ++pos;
    if (pos == start || pos >= message.size() || message[pos] != ':') return false;
    ++pos;
  }
  return message.compare(pos, 1, " ") == 0;
}

class BadDeck : public ::testing::TestWithParam<std::string> {};

TEST_P(BadDeck, FailsWithOneLineThatSaysWhereAndWhy) {
  const fs::path file = deck_dir / (GetParam() + ".yaml");
  const std::string expected = expectedMessage(file);
  ASSERT_FALSE(expected.empty()) << file << " does not start with '# expect: <message>'";
  try {
    parseDeck(file);
    FAIL() << file << " parsed without error; expected: " << expected;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(expected), std::string::npos) << "expected: " << expected << "\n     got: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_TRUE(startsWithLocation(message, file.string())) << message;
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadDeck, ::testing::ValuesIn(badDecks()),
                         [](const ::testing::TestParamInfo<std::string>& param_info) { return param_info.param; });

TEST(BadDeckCorpus, HasAtLeastTwentyDecks) {
  EXPECT_GE(badDecks().size(), 20u);
}

}  // namespace
}  // namespace kessler::io
