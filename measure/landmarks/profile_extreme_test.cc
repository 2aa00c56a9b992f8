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

TEST(TopCentre, IsTheExtremeOfASymmetricTop) {
  std::vector<double> at, value;
  Parabola(&at, &value, 0, 1);
  // Samples symmetric about 1075 with NaN gaps ignored: the centre is 1075.
  std::vector<double> top{0, 1, 3, 4, 3, 1, 0}, x{1060, 1065, 1070, 1075, 1080, 1085, 1090};
  ProfileExtremeOptions maximum;
  maximum.minimum = false;
  EXPECT_NEAR(TopCentre(maximum, x, top, 2), 1075, 1e-9);
  top[0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NEAR(TopCentre(maximum, x, top, 2), 1075, 1e-9);
  // A minimum: the parabola's samples within 1 mm of the lowest are
  // 1065-1080, weighted towards 1075.
  const double c = TopCentre({}, at, value, 1);
  EXPECT_GT(c, 1070);
  EXPECT_LT(c, 1077);
  EXPECT_THROW(TopCentre({}, at, value, 0), InternalError);
  EXPECT_THROW(TopCentre({}, x, value, 1), InternalError);
}

TEST(TopCentre, MovesLittleWhereTheBestSampleJumps) {
  // Two bumps 30 mm apart within 0.2 mm of each other: the best sample
  // jumps between them as the second rises by 0.4 mm; the centre moves by
  // less than a third of that jump.
  std::vector<double> x;
  for (double t = 0; t <= 60; t += 3) x.push_back(t);
  auto profile = [&](double second) {
    std::vector<double> v;
    for (double t : x)
      v.push_back(std::max(20 - 0.01 * (t - 15) * (t - 15), second - 0.01 * (t - 45) * (t - 45)));
    return v;
  };
  ProfileExtremeOptions maximum;
  maximum.minimum = false;
  const std::vector<double> low = profile(19.8), high = profile(20.2);
  const double jump = std::abs(x[BestSample(maximum, high, std::vector<bool>(x.size(), true))] -
                               x[BestSample(maximum, low, std::vector<bool>(x.size(), true))]);
  EXPECT_NEAR(jump, 30, 1e-9);
  EXPECT_LT(std::abs(TopCentre(maximum, x, high, 2) - TopCentre(maximum, x, low, 2)), jump / 3);
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
