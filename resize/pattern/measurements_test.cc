#include "resize/pattern/measurements.h"

#include <gtest/gtest.h>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

nlohmann::json Document(const MeasurementSet& values) { return MeasurementsToJson(values); }

TEST(Measurements, BodyRiseIsDerivedFromWaistHeightAndInsideLeg) {
  const MeasurementSet m =
      MeasurementsFromJson(Document({{"waist_height", 1060}, {"inside_leg", 790}}), "doc");
  ASSERT_EQ(m.count("body_rise"), 1u);
  EXPECT_DOUBLE_EQ(m.at("body_rise"), 270.0);
  EXPECT_TRUE(IsCoreMeasurement("body_rise"));
  EXPECT_TRUE(IsDerivedMeasurement("body_rise"));
  EXPECT_FALSE(IsDerivedMeasurement("waist_height"));
}

TEST(Measurements, BodyRiseNeedsBothInputsAndAPositiveValue) {
  EXPECT_EQ(MeasurementsFromJson(Document({{"waist_height", 1060}}), "doc").count("body_rise"), 0u);
  EXPECT_EQ(MeasurementsFromJson(Document({{"inside_leg", 800}}), "doc").count("body_rise"), 0u);
  MeasurementSet odd = {{"waist_height", 700}, {"inside_leg", 800}};
  AddDerivedMeasurements(&odd, "odd");
  EXPECT_EQ(odd.count("body_rise"), 0u);
}

TEST(Measurements, AGivenBodyRiseMustAgreeWithItsDerivation) {
  MeasurementSet agrees = {{"waist_height", 1060}, {"inside_leg", 810}, {"body_rise", 250.5}};
  AddDerivedMeasurements(&agrees, "agrees");
  EXPECT_DOUBLE_EQ(agrees.at("body_rise"), 250.5);  // kept as given
  MeasurementSet differs = {{"waist_height", 1060}, {"inside_leg", 810}, {"body_rise", 280}};
  EXPECT_THROW(AddDerivedMeasurements(&differs, "differs"), InputError);
  EXPECT_THROW(MeasurementsFromJson(Document(differs), "doc"), InputError);
  // Without the inputs a given body_rise stands on its own.
  MeasurementSet alone = {{"body_rise", 280}};
  AddDerivedMeasurements(&alone, "alone");
  EXPECT_DOUBLE_EQ(alone.at("body_rise"), 280.0);
}

}  // namespace
}  // namespace bespoke
