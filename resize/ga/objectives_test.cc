#include "resize/ga/objectives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace bespoke {
namespace {

// FastAtan2 against the C library over every octant, many magnitudes, the
// axes and the range-reduction boundary.
TEST(Objectives, FastAtan2MatchesTheLibrary) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), exponent(-6.0, 6.0);
  double worst = 0;
  for (int i = 0; i < 200000; ++i) {
    const double y = unit(rng) * std::pow(10.0, exponent(rng));
    const double x = unit(rng) * std::pow(10.0, exponent(rng));
    worst = std::max(worst, std::abs(FastAtan2(y, x) - std::atan2(y, x)));
  }
  EXPECT_LT(worst, 1e-14);
  const double t15 = std::tan(M_PI / 12);
  for (double y : {0.0, -0.0, 1.0, -1.0, t15, -t15, 1e-300})
    for (double x : {0.0, -0.0, 1.0, -1.0, 1e-300})
      EXPECT_NEAR(FastAtan2(y, x), std::atan2(y, x), 1e-14) << y << " " << x;
  EXPECT_EQ(FastAtan2(-0.0, -1.0), std::atan2(-0.0, -1.0));
}

}  // namespace
}  // namespace bespoke
