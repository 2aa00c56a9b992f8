#include "measure/landmarks/arm_notch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace bespoke::landmarks {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A section (z = 0, mm, under 1 mm apart along the outline): the outline
// of a trunk's ellipse (half-width 160, half-depth 120) and, on each side,
// an arm's circle of radius 50 centred `arm_x` out; each shape's points
// inside the other are left out (the scanner sees the union's outline).
struct Section {
  Eigen::MatrixX3d points;
  std::vector<int> rows;
};

bool InsideTrunk(double x, double y) { return (x * x) / (160 * 160) + (y * y) / (120 * 120) < 1; }

Section TrunkAndArms(double arm_x) {
  std::vector<Eigen::Vector3d> pts;
  for (double t = 0; t < 2 * kPi; t += 1.0 / 600) {
    const double x = 160 * std::cos(t), y = 120 * std::sin(t);
    if (std::hypot(std::abs(x) - arm_x, y) > 50) pts.emplace_back(x, y, 0);
  }
  for (int sign : {+1, -1})
    for (double t = 0; t < 2 * kPi; t += 1.0 / 300) {
      const double x = sign * arm_x + 50 * std::cos(t), y = 50 * std::sin(t);
      if (!InsideTrunk(x, y)) pts.emplace_back(x, y, 0);
    }
  Section s;
  s.points.resize(static_cast<Eigen::Index>(pts.size()), 3);
  for (size_t i = 0; i < pts.size(); ++i) {
    s.points.row(static_cast<Eigen::Index>(i)) = pts[i].transpose();
    s.rows.push_back(static_cast<int>(i));
  }
  return s;
}

TEST(ArmNotch, ArmRestingOnTheTrunkLeavesANotch) {
  // The arm's circle presses 2 mm into the trunk's side (x' 158-160 mm).
  const Section s = TrunkAndArms(208);
  for (int sign : {+1, -1}) {
    const ArmNotch notch = FindArmNotch(ArmNotchOptions{}, s.points, s.rows, sign);
    EXPECT_TRUE(notch.found) << sign << " ratio " << notch.ratio;
    EXPECT_GT(sign * notch.x_mm, 150) << sign;
    EXPECT_LT(sign * notch.x_mm, 170) << sign;
    EXPECT_LT(std::abs(notch.y_mm), 20) << sign;
  }
}

TEST(ArmNotch, ArmApartFromTheTrunkLeavesANotch) {
  const Section s = TrunkAndArms(240);  // a 30 mm gap
  const ArmNotch notch = FindArmNotch(ArmNotchOptions{}, s.points, s.rows, +1);
  EXPECT_TRUE(notch.found) << notch.ratio;
  // At the gap's edges: the trunk's side (160) or the arm's inner side (190).
  EXPECT_GT(notch.x_mm, 150);
  EXPECT_LT(notch.x_mm, 195);
}

TEST(ArmNotch, TrunkAloneHasNone) {
  // A shoulder's section tapers outwards: the trunk alone, its rounded
  // sides (where the depth falls to nothing) included.
  Section s = TrunkAndArms(1000);  // the arms far outside the search
  std::vector<int> trunk;
  for (int r : s.rows)
    if (std::abs(s.points(r, 0)) <= 160.5) trunk.push_back(r);
  for (int sign : {+1, -1}) {
    const ArmNotch notch = FindArmNotch(ArmNotchOptions{}, s.points, trunk, sign);
    EXPECT_FALSE(notch.found) << sign << " ratio " << notch.ratio;
  }
}

TEST(ArmNotch, ShallowBumpIsNoArm) {
  // A lobe 30 mm deep beyond the trunk's side (under min_lobe_depth_mm).
  std::vector<Eigen::Vector3d> pts;
  for (double t = 0; t < 2 * kPi; t += 1.0 / 600)
    pts.emplace_back(160 * std::cos(t), 120 * std::sin(t), 0);
  for (double t = 0; t < 2 * kPi; t += 1.0 / 50)
    pts.emplace_back(185 + 15 * std::cos(t), 15 * std::sin(t), 0);
  Eigen::MatrixX3d points(static_cast<Eigen::Index>(pts.size()), 3);
  std::vector<int> rows;
  for (size_t i = 0; i < pts.size(); ++i) {
    points.row(static_cast<Eigen::Index>(i)) = pts[i].transpose();
    rows.push_back(static_cast<int>(i));
  }
  EXPECT_FALSE(FindArmNotch(ArmNotchOptions{}, points, rows, +1).found);
}

TEST(ArmNotch, EmptySectionHasNone) {
  const Eigen::MatrixX3d points(0, 3);
  const ArmNotch notch = FindArmNotch(ArmNotchOptions{}, points, {}, +1);
  EXPECT_FALSE(notch.found);
  EXPECT_EQ(notch.ratio, 1);
}

}  // namespace
}  // namespace bespoke::landmarks
