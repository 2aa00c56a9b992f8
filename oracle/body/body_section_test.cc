#include "oracle/body/body_section.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bespoke {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Ellipse perimeter by the Gauss-Kummer series (independent of the
// quadrature in body_section.cc): pi (a + b) sum binom(1/2, n)^2 h^n.
double EllipsePerimeter(double a, double b) {
  const double h = std::pow((a - b) / (a + b), 2);
  double sum = 0, coefficient = 1, hn = 1;
  for (int n = 0; n < 200; ++n) {
    sum += coefficient * coefficient * hn;
    coefficient *= (0.5 - n) / (n + 1);  // binom(1/2, n + 1) from binom(1/2, n)
    hn *= h;
  }
  return kPi * (a + b) * sum;
}

Section Shape(double a, SectionHalf front, SectionHalf back) {
  Section s;
  s.a = a;
  s.front = front;
  s.back = back;
  return s;
}

TEST(BodySection, CirclePerimeterIsTwoPiR) {
  const Section circle = Shape(50, {50, 2, 0}, {50, 2, 0});
  EXPECT_NEAR(circle.Perimeter(), 2 * kPi * 50, 1e-9);
}

TEST(BodySection, EllipseHalvesMatchTheSeries) {
  // Two half-ellipses of different depth: half of each full ellipse.
  const Section s = Shape(160, {120, 2, 0}, {90, 2, 0});
  const double expected = 0.5 * EllipsePerimeter(160, 120) + 0.5 * EllipsePerimeter(160, 90);
  EXPECT_NEAR(s.Perimeter(), expected, 1e-8);
  EXPECT_NEAR(Shape(3, {1, 2, 0}, {1, 2, 0}).Perimeter(), 13.364893220555258, 1e-11);
}

TEST(BodySection, FlatPartAddsItsLength) {
  // Flat half-width w on both halves: the perimeter is 4 w plus the ellipse
  // with half-width a - w.
  const Section s = Shape(150, {80, 2, 60}, {80, 2, 60});
  EXPECT_NEAR(s.Perimeter(), 4 * 60 + EllipsePerimeter(90, 80), 1e-8);
}

TEST(BodySection, SuperellipseMatchesAFinePolygon) {
  // p = 3.5, checked against a polygon of 2^21 points (error ~ 1e-9 mm at
  // this size) extrapolated from two resolutions (Richardson, O(h^2)).
  const Section s = Shape(100, {70, 3.5, 0}, {70, 3.5, 0});
  const auto polygon = [&](int quarter) { return PolygonPerimeter(s.Sample(quarter)); };
  const double coarse = polygon(1 << 15), fine = polygon(1 << 16);
  const double extrapolated = fine + (fine - coarse) / 3;
  EXPECT_NEAR(s.Perimeter(), extrapolated, 1e-5);
}

TEST(BodySection, SamplesLieOnTheCurveAndConverge) {
  const Section s = Shape(170, {110, 2.4, 0}, {140, 2.6, 55});
  const auto points = s.Sample(48);
  ASSERT_EQ(points.size(), 192u);
  for (const auto& p : points) EXPECT_NEAR(s.Gauge(p), 1.0, 1e-9);
  // The four extremes sit at indices 0, 48, 96, 144.
  EXPECT_DOUBLE_EQ(points[0].x(), 170);
  EXPECT_DOUBLE_EQ(points[48].y(), 110);
  EXPECT_DOUBLE_EQ(points[96].x(), -170);
  EXPECT_DOUBLE_EQ(points[144].y(), -140);
  // Inscribed polygons: shorter than the curve, error falling about 4x per
  // doubling.
  const double exact = s.Perimeter();
  const double e1 = exact - PolygonPerimeter(s.Sample(24));
  const double e2 = exact - PolygonPerimeter(s.Sample(48));
  EXPECT_GT(e1, 0);
  EXPECT_GT(e2, 0);
  EXPECT_NEAR(e1 / e2, 4.0, 0.6);
}

TEST(BodySection, GaugeSeparatesInsideFromOutside) {
  const Section s = Shape(100, {60, 2.5, 30}, {50, 2, 0});
  EXPECT_LT(s.Gauge({0, 59}), 1);
  EXPECT_GT(s.Gauge({0, 61}), 1);
  EXPECT_LT(s.Gauge({29, 59.9}), 1);
  EXPECT_GT(s.Gauge({99, 40}), 1);
  EXPECT_NEAR(s.Gauge({200, 0}), 2.0, 1e-9);
}

}  // namespace
}  // namespace bespoke
