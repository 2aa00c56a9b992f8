#include "measure/tape/ellipse_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace bespoke {
namespace {

// Points on an ellipse (semi-axes a, b, first axis at `angle` rad, centre c)
// over parameters [t0, t1], with Gaussian noise of `sigma` mm.
Eigen::MatrixX2d Arc(double a, double b, double angle, Eigen::Vector2d c, double t0, double t1,
                     int n, double sigma) {
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0, sigma);
  const Eigen::Vector2d u(std::cos(angle), std::sin(angle)), v(-u.y(), u.x());
  Eigen::MatrixX2d p(n, 2);
  for (int i = 0; i < n; ++i) {
    const double t = t0 + (t1 - t0) * i / (n - 1);
    p.row(i) = (c + a * std::cos(t) * u + b * std::sin(t) * v).transpose();
    p.row(i) += Eigen::RowVector2d(noise(rng), noise(rng));
  }
  return p;
}

TEST(EllipseFit, RecoversAnArmSectionFromTwoThirdsOfItsLoop) {
  // An upper arm 96 x 80 mm turned 30 deg, 200 mm off the origin; its
  // inner third (120 deg) unscanned.
  const Eigen::Vector2d c(200, -40);
  const Eigen::MatrixX2d p = Arc(48, 40, 0.52, c, -2.0, 2.2, 120, 0.0);
  const std::optional<Ellipse2d> e = FitEllipse(p);
  ASSERT_TRUE(e.has_value());
  EXPECT_NEAR((e->centre - c).norm(), 0, 0.01);
  // Every input point lies on the fitted ellipse (OpenCV fits in single
  // precision: a few hundredths of a millimetre).
  for (Eigen::Index i = 0; i < p.rows(); ++i)
    EXPECT_NEAR((e->At(e->ParameterOf(p.row(i).transpose())) - p.row(i).transpose()).norm(), 0,
                0.05)
        << i;
  // And so does the unscanned third.
  const Eigen::MatrixX2d hidden = Arc(48, 40, 0.52, c, 2.3, 4.2, 20, 0.0);
  for (Eigen::Index i = 0; i < hidden.rows(); ++i)
    EXPECT_NEAR(e->RadiusToward(hidden.row(i).transpose()), (hidden.row(i) - c.transpose()).norm(),
                0.05);
}

TEST(EllipseFit, NoisyPointsGiveTheAxesWithinAMillimetre) {
  const Eigen::MatrixX2d p = Arc(80, 60, -1.1, Eigen::Vector2d(-30, 500), 0, 2 * M_PI, 400, 1.0);
  const std::optional<Ellipse2d> e = FitEllipse(p);
  ASSERT_TRUE(e.has_value());
  const double big = std::max(e->semi_axis_u_mm, e->semi_axis_v_mm);
  const double small = std::min(e->semi_axis_u_mm, e->semi_axis_v_mm);
  EXPECT_NEAR(big, 80, 1.0);
  EXPECT_NEAR(small, 60, 1.0);
}

TEST(EllipseFit, TooFewOrCollinearOrNonFinitePointsFixNoEllipse) {
  EXPECT_FALSE(FitEllipse(Eigen::MatrixX2d::Zero(4, 2)).has_value());
  Eigen::MatrixX2d line(10, 2);
  for (int i = 0; i < 10; ++i) line.row(i) << i, 2 * i;
  EXPECT_FALSE(FitEllipse(line).has_value());
  Eigen::MatrixX2d bad = Arc(10, 8, 0, Eigen::Vector2d::Zero(), 0, 6, 20, 0);
  bad(3, 1) = std::nan("");
  EXPECT_FALSE(FitEllipse(bad).has_value());
}

}  // namespace
}  // namespace bespoke
