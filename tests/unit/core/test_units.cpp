#include "core/error.hpp"
#include "core/units.hpp"

#include <gtest/gtest.h>

namespace kessler {
namespace {

using namespace units;

TEST(Units, ParsesCommonImpactQuantities) {
  EXPECT_DOUBLE_EQ(toSI("10 mm", length), 0.01);
  EXPECT_DOUBLE_EQ(toSI("6.18 km/s", velocity), 6180.0);
  EXPECT_DOUBLE_EQ(toSI("20 us", time), 20e-6);
  EXPECT_DOUBLE_EQ(toSI("20 \u00b5s", time), 20e-6);
  EXPECT_DOUBLE_EQ(toSI("1.5 GPa", pressure), 1.5e9);
  EXPECT_DOUBLE_EQ(toSI("2.7 g/cm^3", density), 2700.0);
  EXPECT_DOUBLE_EQ(toSI("2700 kg/m^3", density), 2700.0);
  EXPECT_DOUBLE_EQ(toSI("896 J/(kg*K)", specific_heat), 896.0);
  EXPECT_DOUBLE_EQ(toSI("896 J/kg/K", specific_heat), 896.0);
  EXPECT_DOUBLE_EQ(toSI("100 kJ/m^2", energy_per_area), 1e5);
  EXPECT_DOUBLE_EQ(toSI("1e3 1/s", rate), 1e3);
  EXPECT_DOUBLE_EQ(toSI("3 m s^-1", velocity), 3.0);
  EXPECT_DOUBLE_EQ(toSI("-2.5e-3", length), -2.5e-3);  // bare numbers are SI
  // Exact, not merely close: decks echo these values back.
  EXPECT_EQ(toSI("10 us", time), 1e-5);
  EXPECT_EQ(toSI("0.5 mm", length), 5e-4);
  EXPECT_EQ(toSI("2.7 g/cm^3", density), 2700.0);
}

TEST(Units, RejectsBadInputWithReason) {
  auto message = [](const char* text, Dimension d) {
    try {
      toSI(text, d);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("5 kg", length).find("expected m"), std::string::npos);
  EXPECT_NE(message("5 furlongs", length).find("unknown unit symbol"), std::string::npos);
  EXPECT_NE(message("five mm", length).find("not a number"), std::string::npos);
  EXPECT_NE(message("nan", length).find("finite"), std::string::npos);
  EXPECT_NE(message("inf mm", length).find("finite"), std::string::npos);
  EXPECT_NE(message("1e999 m", length).find("range"), std::string::npos);
  EXPECT_NE(message("3 m^x", length).find("integer power"), std::string::npos);
  EXPECT_NE(message("3 (m", length).find("missing ')'"), std::string::npos);
  EXPECT_NE(message("", length).find("empty"), std::string::npos);
}

TEST(Units, DescribesDimensions) {
  EXPECT_EQ(describe(velocity), "m/s");
  EXPECT_EQ(describe(density), "kg/m^3");
  EXPECT_EQ(describe(pressure), "kg/m*s^2");
}

}  // namespace
}  // namespace kessler
