#include "scanners/clean/floor.h"

#include <gtest/gtest.h>

#include <random>

#include "oracle/scene/synthetic_scene.h"

namespace bespoke {
namespace {

using testing::AngleDeg;
using testing::MakeSyntheticScene;
using testing::RandomRigid;
using testing::ScenePart;
using testing::SyntheticScene;
using testing::SyntheticSceneOptions;

SyntheticScene Scene(unsigned seed, bool floor) {
  SyntheticSceneOptions options;
  options.seed = seed;
  options.spacing_mm = 6.0;
  options.floor = floor;
  options.scanner_from_body = RandomRigid(seed, 1500.0);
  return MakeSyntheticScene(options);
}

Eigen::Vector3d TrueUp(const SyntheticScene& scene) {
  return scene.scanner_from_body.linear().col(2);
}

TEST(FloorTest, FindsAndRemovesTheFloor) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const SyntheticScene scene = Scene(seed, true);
    const FloorResult floor = RemoveFloor(FloorOptions{}, scene.cloud.points);
    ASSERT_TRUE(floor.found) << floor.note;
    EXPECT_LT(AngleDeg(floor.plane.up, TrueUp(scene)), 0.2);
    // The plane passes through the body frame's origin (soles at z = 0).
    EXPECT_NEAR(floor.plane.Height(scene.scanner_from_body.translation()), 0.0, 0.5);

    std::int64_t floor_kept = 0, body_removed = 0, body_removed_high = 0;
    const Eigen::Isometry3d body_from_scanner = scene.scanner_from_body.inverse();
    for (size_t i = 0; i < scene.part.size(); ++i) {
      const Eigen::Vector3d p = scene.cloud.points.row(static_cast<Eigen::Index>(i)).transpose();
      if (scene.part[i] == ScenePart::kFloor && floor.keep[i]) ++floor_kept;
      if (scene.part[i] == ScenePart::kBody && !floor.keep[i]) {
        ++body_removed;
        if ((body_from_scanner * p).z() > 13.0) ++body_removed_high;  // 10 mm band + 3 sigma noise
      }
    }
    EXPECT_EQ(floor_kept, 0);
    EXPECT_EQ(body_removed_high, 0);
    EXPECT_LT(body_removed, 0.02 * scene.Count(ScenePart::kBody));  // the lowest 10 mm of the feet
    EXPECT_GT(floor.below_points, 0);                               // stray points under the floor
  }
}

TEST(FloorTest, NoFloorIsReportedAndNothingRemoved) {
  for (unsigned seed : {1u, 2u}) {
    const SyntheticScene scene = Scene(seed, false);
    const FloorResult floor = RemoveFloor(FloorOptions{}, scene.cloud.points);
    EXPECT_FALSE(floor.found);
    EXPECT_FALSE(floor.note.empty());
    EXPECT_EQ(std::count(floor.keep.begin(), floor.keep.end(), false), 0);
  }
}

// A wall behind the person holding more points than the floor is a bigger
// plane, but it is across the body's long axis: not the floor.
TEST(FloorTest, AWallIsNotTheFloor) {
  SyntheticSceneOptions options;
  options.spacing_mm = 6.0;
  options.floor_half_size_mm = 600.0;
  const SyntheticScene scene = MakeSyntheticScene(options);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Eigen::Index wall_points = 2 * scene.Count(ScenePart::kFloor);
  Eigen::MatrixX3d points(scene.cloud.size() + wall_points, 3);
  points.topRows(scene.cloud.size()) = scene.cloud.points;
  for (Eigen::Index i = 0; i < wall_points; ++i) {
    points.row(scene.cloud.size() + i) << -1200 + 2400 * u(rng), -650.0, 2200 * u(rng);
  }
  const FloorResult floor = RemoveFloor(FloorOptions{}, points);
  ASSERT_TRUE(floor.found) << floor.note;
  EXPECT_LT(AngleDeg(floor.plane.up, Eigen::Vector3d::UnitZ()), 0.2);
}

TEST(FloorTest, RejectsBadOptions) {
  FloorOptions options;
  options.distance_mm = -1;
  EXPECT_ANY_THROW(options.Check());
}

}  // namespace
}  // namespace bespoke
