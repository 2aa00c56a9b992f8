#include "measure/measurements/section_holes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "measure/tape/convex_hull_2d.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// Perimeter of the ellipse with semi-axes a, b: Ramanujan's second
// approximation, exact to far below a micrometre for an arm's 48 x 40 mm.
double EllipsePerimeter(double a, double b) {
  const double h = (a - b) * (a - b) / ((a + b) * (a + b));
  return M_PI * (a + b) * (1 + 3 * h / (10 + std::sqrt(4 - 3 * h)));
}

// An upper arm's section (semi-axes 48 x 40 mm, turned 0.4 rad, centred at
// (230, -20) mm), sampled every ~2 mm outside the hole [hole_from, hole_to]
// (radians of the ellipse), with 0.5 mm Gaussian noise.
Eigen::MatrixX2d ArmLoop(double hole_from, double hole_to, double sigma) {
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0, sigma);
  const Eigen::Vector2d c(230, -20), u(std::cos(0.4), std::sin(0.4)), v(-u.y(), u.x());
  std::vector<Eigen::Vector2d> p;
  for (int i = 0; i < 140; ++i) {
    const double t = 2 * M_PI * i / 140;
    if (t > hole_from && t < hole_to) continue;
    p.push_back(c + 48 * std::cos(t) * u + 40 * std::sin(t) * v +
                Eigen::Vector2d(noise(rng), noise(rng)));
  }
  Eigen::MatrixX2d m(static_cast<Eigen::Index>(p.size()), 2);
  for (std::size_t i = 0; i < p.size(); ++i) m.row(static_cast<Eigen::Index>(i)) = p[i];
  return m;
}

double TapeWith(const Eigen::MatrixX2d& loop, const SkinOverHoles& fill) {
  Eigen::MatrixX2d all(loop.rows() + fill.points.rows(), 2);
  all << loop, fill.points;
  return ConvexHullPerimeter(all);
}

TEST(SectionHoles, TheTapeOverAnArmsInnerSideFollowsItsSkin) {
  const double truth = EllipsePerimeter(48, 40);
  // A 92 deg hole; no noise, so that the hull's perimeter is the skin's
  // (section_girth.cc denoises a scan's points before the hull).
  const Eigen::MatrixX2d loop = ArmLoop(2.0, 3.6, 0.0);
  const double chord = ConvexHullPerimeter(loop);
  const SkinOverHoles fill = FillSectionHoles({}, loop);
  EXPECT_EQ(fill.holes, 1);
  EXPECT_GT(fill.bridged_mm, 60.0);
  EXPECT_LT(chord, truth - 5.0) << "mm: the chord cuts the hole's arc short";
  EXPECT_NEAR(TapeWith(loop, fill), truth, 1.0) << "mm";
}

TEST(SectionHoles, AWholeLoopIsLeftAsScanned) {
  const SkinOverHoles fill = FillSectionHoles({}, ArmLoop(1, 1, 0.5));
  EXPECT_EQ(fill.holes, 0);
  EXPECT_EQ(fill.points.rows(), 0);
}

TEST(SectionHoles, AHoleTooWideToJudgeKeepsItsChord) {
  // 172 deg of the loop missing: more than max_hole_deg (150).
  const SkinOverHoles fill = FillSectionHoles({}, ArmLoop(0.5, 3.5, 0.5));
  EXPECT_EQ(fill.holes, 0);
  SkinOverHolesOptions wide;
  wide.max_hole_deg = 200;
  EXPECT_EQ(FillSectionHoles(wide, ArmLoop(0.5, 3.5, 0.5)).holes, 1);
}

TEST(SectionHoles, ALoopNoEllipseFitsIsLeftToTheChord) {
  // A 200 x 40 mm rectangle's outline with a hole in one long side: the
  // ellipse misfits it by far more than a tenth of its radius.
  std::vector<Eigen::Vector2d> p;
  for (double x = -100; x <= 100; x += 4) {
    if (x < -40 || x > 0) p.emplace_back(x, 20);
    p.emplace_back(x, -20);
  }
  for (double y = -16; y <= 16; y += 4) p.emplace_back(-100, y), p.emplace_back(100, y);
  Eigen::MatrixX2d loop(static_cast<Eigen::Index>(p.size()), 2);
  for (std::size_t i = 0; i < p.size(); ++i) loop.row(static_cast<Eigen::Index>(i)) = p[i];
  EXPECT_EQ(FillSectionHoles({}, loop).holes, 0);
}

TEST(SectionHoles, BadOptionsAreInputErrors) {
  SkinOverHolesOptions o;
  o.step_mm = 0;
  EXPECT_THROW(FillSectionHoles(o, ArmLoop(2, 3, 0)), InputError);
  o = {};
  o.max_hole_deg = 360;
  EXPECT_THROW(o.Check(), InputError);
}

}  // namespace
}  // namespace bespoke
