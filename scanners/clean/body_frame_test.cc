#include "scanners/clean/body_frame.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "oracle/scene/synthetic_scene.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using testing::AngleDeg;
using testing::MakeSyntheticScene;
using testing::RandomRigid;
using testing::ScenePart;
using testing::SyntheticScene;
using testing::SyntheticSceneOptions;

SyntheticScene BodyOnly(unsigned seed, bool feet_forward = true, bool head_forward = true) {
  SyntheticSceneOptions options;
  options.seed = seed;
  options.spacing_mm = 5.0;
  options.floor = false;
  options.second_object = false;
  options.isolated_outliers = 0;
  options.outlier_clumps = 0;
  options.feet_forward = feet_forward;
  options.head_forward = head_forward;
  options.scanner_from_body = RandomRigid(seed + 50, 3000.0);
  return MakeSyntheticScene(options);
}

FloorPlane TrueFloor(const SyntheticScene& scene) {
  FloorPlane plane;
  plane.up = scene.scanner_from_body.linear().col(2);
  plane.offset_mm = -plane.up.dot(scene.scanner_from_body.translation());
  return plane;
}

struct Errors {
  double up_deg, forward_deg, right_deg;
  Eigen::Vector3d origin_mm;  // the true origin in the estimated frame
};

Errors Compare(const BodyFrame& frame, const SyntheticScene& scene) {
  const Eigen::Matrix3d truth = scene.scanner_from_body.linear().transpose();
  const Eigen::Matrix3d est = frame.body_from_scanner.linear();
  return {AngleDeg(est.row(2), truth.row(2)), AngleDeg(est.row(1), truth.row(1)),
          AngleDeg(est.row(0), truth.row(0)),
          frame.body_from_scanner * scene.scanner_from_body.translation()};
}

TEST(BodyFrameTest, WithTheFloorPlane) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const SyntheticScene scene = BodyOnly(seed);
    const BodyFrame frame =
        EstimateBodyFrame(BodyFrameOptions{}, scene.cloud.points, TrueFloor(scene));
    const Errors e = Compare(frame, scene);
    EXPECT_LT(e.up_deg, 1e-6);
    EXPECT_LT(e.forward_deg, 1.0) << "seed " << seed;
    EXPECT_LT(e.right_deg, 1.0);
    EXPECT_NEAR(e.origin_mm.z(), 0.0, 1e-6);
    EXPECT_LT(e.origin_mm.head<2>().norm(), 3.0) << "seed " << seed;
    EXPECT_EQ(frame.up_source, "floor");
    EXPECT_EQ(frame.front_source, "feet");
    EXPECT_EQ(frame.feet_found, 2);
    EXPECT_NEAR(frame.foot_offset_mm, 65.0, 10.0);  // footprint centre ahead of the ankle axis
    EXPECT_GT(frame.nose_cue_mm, 15.0);             // mm: the nose tip is narrower than the occiput
    EXPECT_NEAR(frame.height_mm, 1750.0, 3.0);
    EXPECT_TRUE(frame.flags.empty());
  }
}

// Without a floor: up from the principal axis, signed by the feet's end.
TEST(BodyFrameTest, WithoutAFloor) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const SyntheticScene scene = BodyOnly(seed);
    const BodyFrame frame = EstimateBodyFrame(BodyFrameOptions{}, scene.cloud.points, std::nullopt);
    const Errors e = Compare(frame, scene);
    EXPECT_LT(e.up_deg, 1.0) << "seed " << seed;
    EXPECT_LT(e.forward_deg, 1.5);
    EXPECT_LT(e.right_deg, 1.5);
    EXPECT_LT(std::abs(e.origin_mm.z()), 4.0);  // the lowest point, within noise
    EXPECT_LT(e.origin_mm.head<2>().norm(), 5.0);
    EXPECT_EQ(frame.up_source, "principal_axis");
    EXPECT_GT(frame.end_area_ratio, 3.0);
    EXPECT_TRUE(frame.flags.empty());
  }
}

// Feet centred under the ankles give no front cue; the nose does.
TEST(BodyFrameTest, FrontFromTheNoseWhenTheFeetDoNotTell) {
  const SyntheticScene scene = BodyOnly(7, /*feet_forward=*/false, /*head_forward=*/true);
  const BodyFrame frame =
      EstimateBodyFrame(BodyFrameOptions{}, scene.cloud.points, TrueFloor(scene));
  const Errors e = Compare(frame, scene);
  EXPECT_EQ(frame.front_source, "nose");
  EXPECT_EQ(frame.flags, std::vector<std::string>{"front_from_nose"});
  EXPECT_LT(e.forward_deg, 1.0);
  EXPECT_LT(std::abs(frame.foot_offset_mm), 10.0);
}

// With no cue at all the result says so instead of guessing silently.
TEST(BodyFrameTest, FlagsAnUndecidableFront) {
  const SyntheticScene scene = BodyOnly(8, false, false);
  const BodyFrame frame =
      EstimateBodyFrame(BodyFrameOptions{}, scene.cloud.points, TrueFloor(scene));
  EXPECT_EQ(frame.front_source, "none");
  EXPECT_NE(std::find(frame.flags.begin(), frame.flags.end(), "front_uncertain"),
            frame.flags.end());
  // Up and the left-right axis are still right; only the sign of y is a guess.
  const Errors e = Compare(frame, scene);
  EXPECT_LT(std::min(e.forward_deg, 180.0 - e.forward_deg), 1.0);
}

TEST(BodyFrameTest, TooFewPointsIsAnInputError) {
  const Eigen::MatrixX3d points = Eigen::MatrixX3d::Random(50, 3);
  EXPECT_THROW(EstimateBodyFrame(BodyFrameOptions{}, points, std::nullopt), InputError);
}

}  // namespace
}  // namespace bespoke
