#include "scanners/core/units.h"

#include <gtest/gtest.h>

#include <limits>

namespace bespoke {
namespace {

TEST(Units, ConvertsToMillimetres) {
  EXPECT_DOUBLE_EQ(MillimetresPer(LengthUnit::kMillimetre), 1.0);
  EXPECT_DOUBLE_EQ(MillimetresPer(LengthUnit::kCentimetre), 10.0);
  EXPECT_DOUBLE_EQ(MillimetresPer(LengthUnit::kDecimetre), 100.0);
  EXPECT_DOUBLE_EQ(MillimetresPer(LengthUnit::kMetre), 1000.0);
}

TEST(Units, ParsesNamesAndRejectsOthers) {
  EXPECT_EQ(ParseLengthUnit("m"), LengthUnit::kMetre);
  EXPECT_EQ(ParseLengthUnit("Metres"), LengthUnit::kMetre);
  EXPECT_EQ(ParseLengthUnit("MM"), LengthUnit::kMillimetre);
  EXPECT_EQ(ParseLengthUnit("dm"), LengthUnit::kDecimetre);
  EXPECT_FALSE(ParseLengthUnit("inch").has_value());
  EXPECT_FALSE(ParseLengthUnit("").has_value());
}

TEST(Units, GuessesFromABodysExtent) {
  EXPECT_EQ(GuessLengthUnit(1.75), LengthUnit::kMetre);      // 1.75 m tall
  EXPECT_EQ(GuessLengthUnit(17.5), LengthUnit::kDecimetre);  // MakeHuman
  EXPECT_EQ(GuessLengthUnit(175.0), LengthUnit::kCentimetre);
  EXPECT_EQ(GuessLengthUnit(1750.0), LengthUnit::kMillimetre);
  EXPECT_EQ(GuessLengthUnit(2.4), LengthUnit::kMetre);  // arms raised
  EXPECT_FALSE(GuessLengthUnit(0.0).has_value());
  EXPECT_FALSE(GuessLengthUnit(-3.0).has_value());
  EXPECT_FALSE(GuessLengthUnit(std::numeric_limits<double>::quiet_NaN()).has_value());
  EXPECT_FALSE(GuessLengthUnit(1e9).has_value());
}

}  // namespace
}  // namespace bespoke
