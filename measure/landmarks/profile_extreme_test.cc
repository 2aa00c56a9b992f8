#include "measure/landmarks/profile_extreme.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "scanners/core/errors.h"

namespace bespoke::landmarks {
namespace {

// Samples every 5 mm of a parabola with its minimum at 1073.4 mm.
void Parabola(std::vector<double>* at, std::vector<double>* value, double noise_mm, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0, noise_mm);
  for (double z = 1000; z <= 1150; z += 5) {
    at->push_back(z);
    value->push_back(600 + 0.01 * (z - 1073.4) * (z - 1073.4) + noise(rng));
  }
}

size_t Best(const std::vector<double>& value) {
  return static_cast<size_t>(std::min_element(value.begin(), value.end()) - value.begin());
}

TEST(ProfileExtreme, FindsTheVertexBetweenSamples) {
  std::vector<double> at, value;
  Parabola(&at, &value, 0, 1);
  EXPECT_DOUBLE_EQ(at[Best(value)], 1075);
  EXPECT_NEAR(ProfileExtreme({}, at, value, Best(value)), 1073.4, 1e-6);
  // A maximum of the negated profile is the same point.
  for (double& v : value) v = -v;
  ProfileExtremeOptions maximum;
  maximum.minimum = false;
  EXPECT_NEAR(ProfileExtreme(maximum, at, value, 15), 1073.4, 1e-6);
}

TEST(ProfileExtreme, AveragesNoiseTheBestSampleFollows) {
  // A flat minimum under 1 mm of noise: the best sample wanders over the
  // grid; the fitted vertex stays closer to the truth on average.
  double sample_error = 0, fit_error = 0;
  for (unsigned seed = 1; seed <= 50; ++seed) {
    std::vector<double> at, value;
    Parabola(&at, &value, 1.0, seed);
    const size_t best = Best(value);
    sample_error += std::abs(at[best] - 1073.4);
    fit_error += std::abs(ProfileExtreme({}, at, value, best) - 1073.4);
  }
  EXPECT_LT(fit_error, 0.8 * sample_error);
}

TEST(ProfileExtreme, KeepsTheSampleWhereTheFitCannotHelp) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // A maximum fitted as a minimum: the fit bends the wrong way.
  std::vector<double> at{0, 5, 10, 15, 20}, value{0, 3, 4, 3, 0};
  EXPECT_DOUBLE_EQ(ProfileExtreme({}, at, value, 2), 10);
  // Too few finite samples.
  std::vector<double> sparse{nan, 3, 1, nan, nan};
  EXPECT_DOUBLE_EQ(ProfileExtreme({}, at, sparse, 2), 10);
  // A vertex beyond the neighbours is clamped to them.
  std::vector<double> edge{9, 4, 1, 0.5, 0.4};
  const double z = ProfileExtreme({}, at, edge, 2);
  EXPECT_GE(z, 5);
  EXPECT_LE(z, 15);
  EXPECT_THROW(ProfileExtreme({}, at, value, 5), InternalError);
}

TEST(ProfileExtreme, BestSampleIsTheFirstBestEligibleFiniteOne) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> value{1, nan, 3, 0.5, 3, 0.5};
  const std::vector<bool> all(6, true), some{false, true, true, false, true, true};
  EXPECT_EQ(BestSample({}, value, all), 3u);
  EXPECT_EQ(BestSample({}, value, some), 5u);
  ProfileExtremeOptions maximum;
  maximum.minimum = false;
  EXPECT_EQ(BestSample(maximum, value, all), 2u);
  EXPECT_EQ(BestSample({}, value, std::vector<bool>(6, false)), 6u);
  EXPECT_THROW(BestSample({}, value, std::vector<bool>(5, true)), InternalError);
}

TEST(ProfileExtreme, WindowMeanSkipsGapsAndEnds) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> m = WindowMean({1, 2, nan, 4, 5}, 1, 2);
  EXPECT_TRUE(std::isnan(m[0]));
  EXPECT_DOUBLE_EQ(m[1], 1.5);
  EXPECT_DOUBLE_EQ(m[2], 3);
  EXPECT_DOUBLE_EQ(m[3], 4.5);
  EXPECT_TRUE(std::isnan(m[4]));
  EXPECT_TRUE(std::isnan(WindowMean({1, nan, nan}, 1, 2)[1]));
}

}  // namespace
}  // namespace bespoke::landmarks
