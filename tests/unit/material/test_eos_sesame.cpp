// SESAME reader: a hand-made file (comment table, free energy words, no line markers, several
// materials) and broken files, each refused with "file:line: what".
#include "core/error.hpp"
#include "material/eos/tabular.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace kessler::eos {
namespace {

const std::string dir = std::string(KESSLER_TEST_DATA) + "/sesame/";

TEST(EosSesame, ReadsAHandMadeFileInSiUnits) {
  const SesameTable t = readSesame(dir + "small.ses");
  EXPECT_EQ(t.material_id, 7);
  EXPECT_EQ(t.z, 13.0);
  EXPECT_EQ(t.a, 26.98);
  EXPECT_EQ(t.density, 2700.0);
  EXPECT_EQ(t.bulk_modulus, 75e9);
  EXPECT_EQ(t.temperature0, 293.0);
  EXPECT_EQ(t.rho, (std::vector<double>{2000.0, 3000.0}));
  EXPECT_EQ(t.temperature, (std::vector<double>{0.0, 1000.0, 2000.0}));
  EXPECT_EQ(t.pressure, (std::vector<double>{-1e9, 5e9, 0.0, 6e9, 1e9, 7e9}));
  EXPECT_EQ(t.energy, (std::vector<double>{0.0, 1e5, 1e6, 1.1e6, 2e6, 2.1e6}));
}

std::string message(const std::string& file, int material = 0) {
  try {
    readSesame(dir + file, material);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(EosSesame, NamesAMissingMaterialOrTable) {
  EXPECT_NE(message("small.ses", 9).find("material 9 is not in the file (materials: 7, 8)"), std::string::npos);
  EXPECT_NE(message("small.ses", 8).find("without table 201 for material 8"), std::string::npos);
  EXPECT_NE(message("no_such_file.ses").find("cannot open"), std::string::npos);
}

struct Bad {
  const char* file;
  int line;
  const char* what;
};

TEST(EosSesame, RefusesBrokenFilesWithFileAndLine) {
  const Bad cases[] = {
      {"bad_empty.ses", 1, "empty file"},
      {"bad_not_sesame.ses", 1, "not a SESAME table header"},
      {"bad_text_garbage.ses", 5, "is not a number"},
      {"bad_truncated.ses", 5, "truncated: table 301 of material 7 has 10 of the 19 words"},
      {"bad_word_count.ses", 3, "word count mismatch: table 201 of material 7 ends after 5 of the 7 words"},
      {"bad_301_too_short.ses", 3, "word count mismatch: table 301 with NR = 2, NT = 3 needs at least 19 words"},
      {"bad_nonmonotonic_t.ses", 5, "temperature grid not increasing"},
      {"bad_nan.ses", 6, "non-finite number 'NaN'"},
      {"bad_missing_301.ses", 2, "without table 301 for material 7"},
      {"bad_negative_density.ses", 4, "negative density"},
      {"bad_energy_not_increasing.ses", 7, "energy does not increase with temperature"},
      {"bad_grid_size.ses", 4, "number of densities must be an integer of at least 2"},
      {"bad_extra_line.ses", 8,
       "word count mismatch: numbers continue after the 19 words that the header of table 301"},
  };
  for (const Bad& c : cases) {
    const std::string m = message(c.file);
    const std::string where = dir + c.file + ":" + std::to_string(c.line) + ": ";
    EXPECT_EQ(m.rfind(where, 0), 0u) << m;
    EXPECT_NE(m.find(c.what), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

// Every bad_*.ses in the folder, including ones added later: an InputError, one line, that
// starts with "file:line: ".
TEST(EosSesame, EveryBadFileGivesALocatedOneLineError) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("bad_", 0) != 0 || entry.path().extension() != ".ses") continue;
    ++files;
    const std::string m = message(name);
    const std::string prefix = dir + name + ":";
    ASSERT_EQ(m.rfind(prefix, 0), 0u) << m;
    const std::size_t colon = m.find(": ", prefix.size());
    ASSERT_NE(colon, std::string::npos) << m;
    const std::string line = m.substr(prefix.size(), colon - prefix.size());
    EXPECT_TRUE(!line.empty() && line.find_first_not_of("0123456789") == std::string::npos && std::stoi(line) >= 1)
        << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
  EXPECT_GE(files, 8);
}

}  // namespace
}  // namespace kessler::eos
