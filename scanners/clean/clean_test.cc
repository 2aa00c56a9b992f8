// The whole chain on synthetic scenes: a person on a floor with noise, stray
// points and a pole, in metres, seen from random scanner poses.
#include "scanners/clean/clean.h"

#include <gtest/gtest.h>

#include <cmath>

#include "oracle/scene/synthetic_scene.h"
#include "scanners/clean/clean_json.h"
#include "scanners/clean/neighbours.h"
#include "scanners/core/units.h"

namespace bespoke {
namespace {

using testing::AngleDeg;
using testing::MakeSyntheticScene;
using testing::RandomRigid;
using testing::ScenePart;
using testing::SyntheticScene;
using testing::SyntheticSceneOptions;

// What the reader does with a file in metres: guess the unit, scale to mm.
PointCloud ToMillimetres(const PointCloud& cloud, double* mm_per_unit) {
  const Eigen::Vector3d extent =
      cloud.points.colwise().maxCoeff() - cloud.points.colwise().minCoeff();
  const auto unit = GuessLengthUnit(extent.maxCoeff());
  EXPECT_TRUE(unit.has_value());
  *mm_per_unit = MillimetresPer(unit.value_or(LengthUnit::kMillimetre));
  PointCloud mm = cloud;
  mm.points *= *mm_per_unit;
  return mm;
}

struct FrameErrors {
  double up_deg, forward_deg, right_deg;
  Eigen::Vector3d origin_mm;  // the true origin in the estimated body frame
};

FrameErrors Compare(const Eigen::Isometry3d& body_from_scanner, const SyntheticScene& scene) {
  const Eigen::Isometry3d truth = scene.scanner_from_body.inverse();
  FrameErrors e;
  e.right_deg = AngleDeg(body_from_scanner.linear().row(0), truth.linear().row(0));
  e.forward_deg = AngleDeg(body_from_scanner.linear().row(1), truth.linear().row(1));
  e.up_deg = AngleDeg(body_from_scanner.linear().row(2), truth.linear().row(2));
  e.origin_mm = body_from_scanner * scene.scanner_from_body.translation();
  return e;
}

// Checks the frame, that only the body is left, and the normals.
void ExpectBodyRecovered(const SyntheticScene& scene, const CleanResult& result,
                         const std::vector<std::string>& expected_flags = {}) {
  const FrameErrors e = Compare(result.body_from_scanner, scene);
  EXPECT_LT(e.up_deg, 1.0);
  EXPECT_LT(e.forward_deg, 2.0);
  EXPECT_LT(e.right_deg, 2.0);
  EXPECT_LT(std::abs(e.origin_mm.z()), 3.0) << "feet not on z = 0";
  EXPECT_LT(e.origin_mm.head<2>().norm(), 8.0) << "origin not between the feet";
  EXPECT_EQ(result.frame.front_source, "feet");
  EXPECT_EQ(result.flags, expected_flags);

  // Every output point is within 10 mm of a true body sample.
  const Eigen::MatrixX3d body_scanner = scene.PointsMm(ScenePart::kBody);
  const Eigen::Isometry3d scanner_from_body_est = result.body_from_scanner.inverse();
  const Eigen::MatrixX3d out_scanner =
      (result.cloud.points * scanner_from_body_est.linear().transpose()).rowwise() +
      scanner_from_body_est.translation().transpose();
  const std::vector<int> nearest = NearestPointIndices(body_scanner, out_scanner);
  std::int64_t far = 0;
  for (Eigen::Index i = 0; i < out_scanner.rows(); ++i) {
    if ((out_scanner.row(i) - body_scanner.row(nearest[static_cast<size_t>(i)])).norm() > 10.0)
      ++far;
  }
  EXPECT_EQ(far, 0) << "points left that are not on the body";
  // ... and the whole body is there: crown to feet, both hands.
  const Eigen::Vector3d low = result.cloud.points.colwise().minCoeff();
  const Eigen::Vector3d high = result.cloud.points.colwise().maxCoeff();
  EXPECT_NEAR(high.z(), scene.height_mm, 5.0);
  EXPECT_NEAR(high.x(), scene.right_hand_max_x_mm, 6.0);
  EXPECT_NEAR(low.x(), -scene.right_hand_max_x_mm, 6.0);

  // Normals point out: the true normal of the nearest body sample agrees.
  ASSERT_TRUE(result.cloud.has_normals());
  std::vector<Eigen::Index> body_rows;
  for (size_t i = 0; i < scene.part.size(); ++i) {
    if (scene.part[i] == ScenePart::kBody) body_rows.push_back(static_cast<Eigen::Index>(i));
  }
  std::int64_t outward = 0;
  for (Eigen::Index i = 0; i < out_scanner.rows(); ++i) {
    const Eigen::Vector3d n =
        scanner_from_body_est.linear() * result.cloud.normals.row(i).transpose();
    const Eigen::Index truth_row = body_rows[static_cast<size_t>(nearest[static_cast<size_t>(i)])];
    if (n.dot(scene.true_normals.row(truth_row)) > 0) ++outward;
  }
  EXPECT_GT(static_cast<double>(outward) / out_scanner.rows(), 0.98);
}

class CleanChainTest : public ::testing::TestWithParam<unsigned> {};

// A small floor and no second object, so that the unit can be guessed from
// the extent in any orientation (see synthetic_scene.h).
TEST_P(CleanChainTest, RecoversTheBodyFromAScanInMetres) {
  SyntheticSceneOptions options;
  options.seed = GetParam();
  options.spacing_mm = 5.0;
  options.floor_half_size_mm = 500.0;
  options.second_object = false;
  options.scanner_from_body = RandomRigid(GetParam() + 100, 2000.0);
  options.mm_per_unit = 1000.0;  // the file is in metres
  const SyntheticScene scene = MakeSyntheticScene(options);

  double mm_per_unit = 0;
  const PointCloud input = ToMillimetres(scene.cloud, &mm_per_unit);
  ASSERT_EQ(mm_per_unit, 1000.0);
  const CleanResult result = CleanScan(CleanOptions{}, input);
  EXPECT_TRUE(result.floor.has_value());
  ExpectBodyRecovered(scene, result);
}

// The full scene: a large floor, a pole 150 mm from the right hand, stray
// points and clumps, in millimetres.
TEST_P(CleanChainTest, DropsFloorPoleAndStrayPoints) {
  SyntheticSceneOptions options;
  options.seed = GetParam() + 10;
  options.spacing_mm = 5.0;
  options.scanner_from_body = RandomRigid(GetParam() + 200, 2000.0);
  const SyntheticScene scene = MakeSyntheticScene(options);
  const CleanResult result = CleanScan(CleanOptions{}, scene.cloud);
  EXPECT_TRUE(result.floor.has_value());
  ASSERT_GE(result.cluster_sizes.size(), 2u);  // the pole was a cluster of its own
  // The pole holds more than 2 % of the points: its removal is flagged.
  ExpectBodyRecovered(scene, result, {"large_cluster_dropped"});

  // Stage bookkeeping: counts chain up, times are recorded.
  ASSERT_EQ(result.stages.size(), 9u);
  EXPECT_EQ(result.stages.front().points_in, scene.cloud.size());
  for (size_t s = 1; s < result.stages.size(); ++s) {
    EXPECT_EQ(result.stages[s].points_in, result.stages[s - 1].points_out) << result.stages[s].name;
    EXPECT_GE(result.stages[s].time_s, 0.0);
  }
  EXPECT_EQ(result.stages.back().points_out, result.cloud.size());
}

INSTANTIATE_TEST_SUITE_P(Poses, CleanChainTest, ::testing::Values(1u, 2u, 3u));

}  // namespace
}  // namespace bespoke
