#include "measure/tape/convex_hull_2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// Perimeter of the ellipse with semi-axes a, b by the midpoint rule on the
// arc-length integral (1e6 steps: relative error far below 1e-9).
double EllipsePerimeter(double a, double b) {
  const int steps = 1'000'000;
  double sum = 0;
  for (int i = 0; i < steps; ++i) {
    const double t = 2 * M_PI * (i + 0.5) / steps;
    sum += std::hypot(a * std::sin(t), b * std::cos(t));
  }
  return sum * 2 * M_PI / steps;
}

TEST(ConvexHull2d, SquareWithInteriorAndEdgePoints) {
  Eigen::MatrixX2d p(9, 2);
  p << 0, 0, 10, 0, 10, 10, 0, 10, 5, 5, 5, 0, 10, 5, 2, 7, 0, 0;  // edge midpoints, a duplicate
  const std::vector<int> hull = ConvexHullIndices(p);
  EXPECT_EQ(hull.size(), 4u);  // collinear edge points dropped
  EXPECT_NEAR(ConvexHullPerimeter(p), 40, 1e-12);
  // Counter-clockwise: positive signed area.
  double area2 = 0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const auto a = p.row(hull[i]), b = p.row(hull[(i + 1) % hull.size()]);
    area2 += a.x() * b.y() - a.y() * b.x();
  }
  EXPECT_NEAR(area2, 200, 1e-9);
}

TEST(ConvexHull2d, DepthInsideIsTheDistanceToTheNearestEdge) {
  Eigen::MatrixX2d p(5, 2);
  p << 0, 0, 10, 0, 10, 10, 0, 10, 3, 4;
  const std::vector<int> hull = ConvexHullIndices(p);
  EXPECT_NEAR(DepthInsideHull(p, hull, Eigen::Vector2d(5, 5)), 5, 1e-12);
  EXPECT_NEAR(DepthInsideHull(p, hull, p.row(4).transpose()), 3, 1e-12);
  EXPECT_NEAR(DepthInsideHull(p, hull, Eigen::Vector2d(10, 4)), 0, 1e-12);
}

TEST(ConvexHull2d, EllipseSampledDenselyApproachesItsPerimeter) {
  const double a = 180, b = 120;  // a waist-like section, mm
  const int n = 4000;
  Eigen::MatrixX2d p(n, 2);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n;
    p.row(i) << a * std::cos(t), b * std::sin(t);
  }
  // The inscribed polygon is shorter by O(1/n^2): < 0.002 mm here.
  EXPECT_NEAR(ConvexHullPerimeter(p), EllipsePerimeter(a, b), 2e-3);
  EXPECT_LT(ConvexHullPerimeter(p), EllipsePerimeter(a, b));
}

TEST(ConvexHull2d, ConcaveShapeIsBridgedLikeATape) {
  // A kidney-like outline: a circle of radius 100 with a dent of depth 30 at
  // the back; the hull bridges the dent with a straight chord.
  const int n = 3600;
  Eigen::MatrixX2d p(n + 2, 2);
  // The dent's ends themselves (not on the sampling grid).
  for (const double end : {-0.5, 0.5})
    p.row(end < 0 ? n : n + 1) << 100 * std::cos(1.5 * M_PI + end),
        100 * std::sin(1.5 * M_PI + end);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n;
    const double dent = std::abs(t - 1.5 * M_PI) < 0.5 ? 30 * std::cos((t - 1.5 * M_PI) * M_PI) : 0;
    p.row(i) << (100 - dent) * std::cos(t), (100 - dent) * std::sin(t);
  }
  // Circle minus the arc over the dent's ends plus their chord (the dent
  // profile keeps the ends on the circle): 2*pi*100 - 100*1 + 2*100*sin(0.5).
  const double expected = 2 * M_PI * 100 - 100 * 1.0 + 200 * std::sin(0.5);
  EXPECT_NEAR(ConvexHullPerimeter(p), expected, 0.01);
}

TEST(ConvexHull2d, RandomInteriorPointsDoNotChangeTheHull) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::MatrixX2d p(1006, 2);
  p.topRows(6) << 0, 0, 100, 0, 150, 80, 100, 160, 0, 160, -50, 80;  // a hexagon
  for (int i = 6; i < p.rows(); ++i) p.row(i) << 50 + 40 * u(rng), 80 + 60 * u(rng);
  const double hexagon = 2 * 100 + 4 * std::hypot(50.0, 80.0);
  EXPECT_NEAR(ConvexHullPerimeter(p), hexagon, 1e-9);
}

TEST(ConvexHull2d, DegenerateInputs) {
  EXPECT_EQ(ConvexHullPerimeter(Eigen::MatrixX2d(0, 2)), 0);
  Eigen::MatrixX2d one(3, 2);
  one << 5, 5, 5, 5, 5, 5;
  EXPECT_EQ(ConvexHullPerimeter(one), 0);
  Eigen::MatrixX2d line(4, 2);
  line << 0, 0, 1, 1, 3, 3, 2, 2;
  EXPECT_NEAR(ConvexHullPerimeter(line), 2 * std::sqrt(18.0), 1e-12);
  Eigen::MatrixX2d bad(2, 2);
  bad << 0, 0, NAN, 1;
  EXPECT_THROW(ConvexHullPerimeter(bad), InputError);
}

}  // namespace
}  // namespace bespoke
